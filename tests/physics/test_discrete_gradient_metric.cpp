// The metric of the algorithmic deviatoric stress (81) (discrete_gradient.hpp, docs/implicit.md §4.1): at a point
// of the 227 m/s Taylor bar's foot (F_n of the cell on the wall next to the axis at t = 42 us, compressed 11:1,
// on the yield surface), random steps with |grad dphi| = 6e-3 as Newton took there. The spatial tangent of S_algo,
// |F_mid dS_algo F_mid^T| / |dH|, stays at the elastic scale (~G) with the metric C-bar^-1 dC C-bar^-1; with the
// identity of (81) as printed it reached 54 G: the kink in the residual that stalled Newton (theory.md §15).
#include <gtest/gtest.h>

#include <cstdio>
#include <random>

#include "mpm/plasticity/discrete_gradient.hpp"
#include "mpm/plasticity/hencky_j2.hpp"

namespace mpm::plasticity {
namespace {

struct Foot {
  HenckyJ2Params c;
  HenckyJ2State<2> state;
  Mat3 F_n = Mat3::Zero();
  Foot() {
    c.density = 8930, c.bulk_modulus = 129.889e9, c.shear_modulus = 43.2963e9, c.plastic = true;
    c.yield_stress = 0.4e9, c.hardening_modulus = 0.1e9;
    F_n(0, 0) = 3.2613, F_n(0, 1) = -0.1194, F_n(1, 0) = -0.5320, F_n(1, 1) = 0.0881, F_n(2, 2) = 3.3557;
    HenckyJ2::commit(state, HenckyJ2::evaluate<2>(c, state, F_n, 1e-6));  // on the yield surface at F_n
  }
  /// S_algo^dev for F_{n+1} = (1 + H) F_n, in the metric of discrete_gradient.hpp or the identity of (81).
  Mat3 algorithmic(const Mat3& H, bool identity) const {
    const auto at_n = HenckyJ2::elastic_response<2>(c, state, F_n);
    const Mat3 F1 = (Mat3::Identity() + H) * F_n;
    const auto at_1 = HenckyJ2::evaluate<2>(c, state, F1, 1e-6);
    const Mat3 S_n = pull_back(F_n, at_n.dev_kirchhoff), S_1 = pull_back(F1, at_1.dev_kirchhoff);
    const Mat3 dC = right_cauchy_green_increment(F_n, H);
    const Real increment = at_1.stored_energy - at_n.stored_energy + at_1.dissipation;
    if (identity) return 2 * discrete_gradient(0.25 * (S_n + S_1), dC, increment, 0);
    return algorithmic_deviatoric_stress(S_n, S_1, at_n.stored_energy, at_1.stored_energy, at_1.dissipation,
                                         F_n.transpose() * F_n, dC);
  }
};

TEST(DiscreteGradient, MetricKeepsTheTangentAtTheElasticScaleAtLargeStretch) {
  const Foot foot;
  std::mt19937 rng(3);
  std::normal_distribution<double> normal(0, 1);
  Real worst_metric = 0, worst_identity = 0, worst_identity_error = 0;
  for (int k = 0; k < 2000; ++k) {
    Mat3 H = Mat3::Zero(), E = Mat3::Zero();
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j) H(i, j) = normal(rng), E(i, j) = normal(rng);
    H(2, 2) = normal(rng), E(2, 2) = normal(rng);  // the hoop stretch
    H *= 6e-3 / H.norm(), E /= E.norm();
    const Real d = 1e-7;
    const Mat3 F_mid = (Mat3::Identity() + 0.5 * H) * foot.F_n;
    for (bool identity : {false, true}) {
      const Mat3 a = foot.algorithmic(H, identity), b = foot.algorithmic(H + d * E, identity);
      const Real tangent = (F_mid * (b - a) * F_mid.transpose()).norm() / d;
      (identity ? worst_identity : worst_metric) = std::max(identity ? worst_identity : worst_metric, tangent);
    }
    // both satisfy (83): 1/2 S_algo : dC = dW + dD
    const Mat3 dC = right_cauchy_green_increment(foot.F_n, H);
    const auto at_n = HenckyJ2::elastic_response<2>(foot.c, foot.state, foot.F_n);
    const auto at_1 = HenckyJ2::evaluate<2>(foot.c, foot.state, (Mat3::Identity() + H) * foot.F_n, 1e-6);
    const Real work = at_1.stored_energy - at_n.stored_energy + at_1.dissipation;
    worst_identity_error = std::max(
        worst_identity_error, std::abs(0.5 * contract(foot.algorithmic(H, false), dC) - work) / at_n.stored_energy);
  }
  const Real G = foot.c.shear_modulus;
  std::printf(
      "[ measured ] Taylor-bar foot (C_n eigenvalues ~5e-3 and ~11), 2000 random steps |H| = 6e-3: largest spatial "
      "tangent of S_algo %.2f G with the metric, %.1f G with the identity of (81); (83) with the metric to %.1e of W\n",
      worst_metric / G, worst_identity / G, worst_identity_error);
  EXPECT_LT(worst_metric, 3 * G);
  EXPECT_GT(worst_identity, 10 * G);  // what the metric removes
  EXPECT_LT(worst_identity_error, 1e-12);
}

}  // namespace
}  // namespace mpm::plasticity
