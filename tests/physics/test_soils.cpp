// drucker_prager and mohr_coulomb (physics/soils, docs/theory.md §18) at one material point, driven by the
// material-test driver's library function (apps material_test.hpp), against closed forms:
//  - triaxial compression at three confining pressures: the peak deviatoric stress q on the yield surface
//    (eqs. 18.14, 18.15) to 1e-10, and the ratio of the volumetric to the axial strain rate once the stress no longer
//    changes, which the flow rule fixes through the dilation angle alone (eqs. 18.16, 18.17);
//  - triaxial extension (eqs. 18.14, 18.15): Drucker-Prager's inner cone and Mohr-Coulomb agree there;
//  - a column of sand collapsing under gravity in 2D MUSL: every particle admissible, the energy audit closed, and a
//    restart from its saved state bit-identical;
//  - objectivity: a stressed point spun rigidly keeps its principal stresses (Hughes-Winget, eq. 18.12) and flows
//    no more; the particle history is plain doubles, so checkpoints and migration carry it;
//  - the apex and the tension cut-off: a point pulled apart isotropically ends at p = min(T, c cot phi), on or inside
//    the yield surface, s = 0 at the apex.
// Measured errors are printed as "[ measured ]" lines.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include "../libmpm/scene_fixture.hpp"
#include "mpm/app/material_test.hpp"
#include "mpm/core/state_archive.hpp"
#include "mpm/particles/field_layout.hpp"
#include "mpm/soils/drucker_prager.hpp"
#include "mpm/soils/mohr_coulomb.hpp"
#include "mpm/soils/soil_batch.hpp"
#include "soil_restart.hpp"

namespace mpm::soils {
namespace {

using app::LoadPath;
using app::MaterialTestOptions;
using app::MaterialTestResult;

constexpr Real degree = std::numbers::pi / 180;

/// A dense sand with some cohesion: E = 50 MPa, nu = 0.3, phi = 30 deg, psi = 10 deg, c = 10 kPa, no tension.
SoilParams sand(ConeMatching matching = ConeMatching::outer_cone) {
  SoilParams s;
  s.density = 1800;
  const Real E = 50e6, nu = 0.3;
  s.shear_modulus = E / (2 * (1 + nu));
  s.bulk_modulus = E / (3 * (1 - 2 * nu));
  s.friction = 30 * degree;
  s.dilation = 10 * degree;
  s.cohesion = 10e3;
  s.tension_cutoff = 0;
  s.matching = matching;
  return s;
}

template <class Return>
MaterialTestResult triaxial(const SoilParams& s, Real confining, LoadPath path) {
  SoilBatch<3, Return> material(s);
  MaterialTestOptions o;
  o.path = path;
  o.confining_pressure = confining;
  o.strain = 0.05;  // far beyond yield (about 1e-2 here)
  o.steps = 200;
  return app::run_material_test(material, o);
}

Real relative(Real a, Real b) { return std::abs(a - b) / std::abs(b); }

/// Delta eps_v / Delta eps_axial over the last step.
Real dilatancy_ratio(const MaterialTestResult& r) {
  const auto& a = r.rows[r.rows.size() - 2];
  const auto& b = r.rows.back();
  return (b.volumetric_strain - a.volumetric_strain) / (b.strain(0, 0) - a.strain(0, 0));
}

Real peak_q(const MaterialTestResult& r) {
  Real q = 0;
  for (const auto& row : r.rows) q = std::max(q, row.deviatoric_stress);
  return q;
}

TEST(DruckerPrager, TriaxialCompressionPeakAndDilatancy) {
  for (const ConeMatching matching : {ConeMatching::outer_cone, ConeMatching::inner_cone, ConeMatching::plane_strain}) {
    const SoilParams s = sand(matching);
    const ConeCoefficients yield = cone_coefficients(matching, s.friction);
    const Real eta_bar = cone_coefficients(matching, s.dilation).eta;
    for (const Real confining : {50e3, 100e3, 200e3}) {
      const MaterialTestResult r = triaxial<DruckerPrager>(s, confining, LoadPath::triaxial_compression);
      // sigma = diag(-p_c - q, -p_c, -p_c): sqrt(J2) = q / sqrt(3), p = -p_c - q / 3 on the cone (eq. 18.14)
      const Real expected = (yield.xi * s.cohesion + yield.eta * confining) / (1 / std::sqrt(3.0) - yield.eta / 3);
      const Real error = relative(peak_q(r), expected);
      // d eps_p = d gamma (s / (2 sqrt(J2)) + eta_bar / 3 1): axial -1/sqrt(3) + eta_bar / 3, volume eta_bar (18.16)
      const Real ratio = eta_bar / (eta_bar / 3 - 1 / std::sqrt(3.0));
      const Real ratio_error = std::abs(dilatancy_ratio(r) - ratio);
      std::printf("[ measured ] DP matching %d, p_c = %g kPa: q %.6g (error %.2e), dilatancy %.6f (error %.2e)\n",
                  static_cast<int>(matching), confining / 1e3, peak_q(r), error, dilatancy_ratio(r), ratio_error);
      EXPECT_LT(error, 1e-10);
      EXPECT_LT(ratio_error, 1e-10);
      EXPECT_GT(r.rows.back().model_fields.at(1), 0);  // plastic_volumetric_strain: dilation
    }
  }
}

TEST(MohrCoulomb, TriaxialCompressionPeakAndDilatancy) {
  const SoilParams s = sand();
  const Real sp = std::sin(s.friction), sd = std::sin(s.dilation);
  for (const Real confining : {50e3, 100e3, 200e3}) {
    const MaterialTestResult r = triaxial<MohrCoulomb>(s, confining, LoadPath::triaxial_compression);
    // sigma_1 = sigma_2 = -p_c, sigma_3 = -p_c - q on the main plane (an edge of the pyramid, eq. 18.15)
    const Real expected = (2 * confining * sp + 2 * s.cohesion * std::cos(s.friction)) / (1 - sp);
    const Real error = relative(peak_q(r), expected);
    // two equal multipliers on the edge: d eps = d gamma (1 + sin psi, 1 + sin psi, -2 (1 - sin psi)) (eq. 18.17)
    const Real ratio = -2 * sd / (1 - sd);
    const Real ratio_error = std::abs(dilatancy_ratio(r) - ratio);
    std::printf("[ measured ] MC p_c = %g kPa: q %.6g (error %.2e), dilatancy %.6f (error %.2e)\n", confining / 1e3,
                peak_q(r), error, dilatancy_ratio(r), ratio_error);
    EXPECT_LT(error, 1e-10);
    EXPECT_LT(ratio_error, 1e-10);
  }
}

TEST(SoilModels, TriaxialExtensionInnerConeAgreesWithMohrCoulomb) {
  const SoilParams s = sand(ConeMatching::inner_cone);
  const Real sp = std::sin(s.friction);
  for (const Real confining : {50e3, 100e3, 200e3}) {
    // sigma = diag(-p_c + q, -p_c, -p_c): Mohr-Coulomb q = (2 p_c sin phi + 2 c cos phi) / (1 + sin phi)
    const Real expected = (2 * confining * sp + 2 * s.cohesion * std::cos(s.friction)) / (1 + sp);
    const Real mc = peak_q(triaxial<MohrCoulomb>(s, confining, LoadPath::triaxial_extension));
    const Real dp = peak_q(triaxial<DruckerPrager>(s, confining, LoadPath::triaxial_extension));
    std::printf("[ measured ] extension p_c = %g kPa: MC error %.2e, DP inner cone error %.2e\n", confining / 1e3,
                relative(mc, expected), relative(dp, expected));
    EXPECT_LT(relative(mc, expected), 1e-10);
    EXPECT_LT(relative(dp, expected), 1e-10);
  }
}

/// Isotropic extension (with a little shear) beyond the apex: the stress ends at p = min(T, c cot phi), inside the
/// yield surface, with no deviator at the apex itself, for both models.
template <class Return>
void check_apex(Real tension_cutoff) {
  SoilParams s = sand();
  s.tension_cutoff = tension_cutoff;
  SoilBatch<3, Return> material(s);
  MaterialTestOptions o;
  o.path = LoadPath::deformation_csv;
  for (int k = 1; k <= 10; ++k) {
    app::DeformationSample sample;
    sample.time = k * 0.1;
    sample.F = Mat3::Identity() * (1 + 1e-3 * k);
    sample.F(0, 1) = 2e-4 * k;  // and some shear, so that the return has a deviator to remove
    o.samples.push_back(sample);
  }
  const MaterialTestResult r = app::run_material_test(material, o);
  const Real apex = s.cohesion / std::tan(s.friction);
  const Real cap = std::min(tension_cutoff, apex);
  const Mat3 stress = r.rows.back().stress;
  const Real mean = stress.trace() / 3;
  const Real error = std::abs(mean - cap) / apex;
  // below the apex the deviator is what the yield surface leaves at p = T (on or inside it); at the apex none
  const Real deviator = (stress - mean * Mat3::Identity()).norm() / apex;
  const Real yield = material.return_mapping().yield_function(stress) / s.cohesion;
  std::printf("[ measured ] %s, T = %g kPa: |p - min(T, c cot phi)| / (c cot phi) = %.2e, yield function %.2e c\n",
              Return::key, tension_cutoff / 1e3, error, yield);
  EXPECT_LT(error, 1e-12);
  EXPECT_LT(yield, 1e-12);
  if (cap == apex) {
    EXPECT_LT(deviator, 1e-12);
  }
}

TEST(SoilModels, ApexAndTensionCutoff) {
  for (const Real T : {0.0, 5e3, 1e6}) {
    check_apex<DruckerPrager>(T);
    check_apex<MohrCoulomb>(T);
  }
}

// Linear softening (eq. 18.19) of c from 10 to 2 kPa and phi from 30 to 25 deg over eps_p = 0.01: the peak stays at or
// below the peak strength, and once eps_p passed 0.01 the stress is the residual strength's closed form (18.14, 18.15;
// the strength lags eps_p by one step, which no longer matters once it is constant).
TEST(SoilModels, SofteningEndsOnTheResidualStrength) {
  SoilParams s = sand(ConeMatching::outer_cone);
  s.softening = {.enabled = true, .residual_cohesion = 2e3, .residual_friction = 25 * degree, .strain = 0.01};
  const SoilParams residual = s.softened(1);
  const Real confining = 100e3;
  const auto dp_q = [&](const SoilParams& p) {
    const ConeCoefficients y = cone_coefficients(p.matching, p.friction);
    return (y.xi * p.cohesion + y.eta * confining) / (1 / std::sqrt(3.0) - y.eta / 3);
  };
  const auto mc_q = [&](const SoilParams& p) {
    const Real sp = std::sin(p.friction);
    return (2 * confining * sp + 2 * p.cohesion * std::cos(p.friction)) / (1 - sp);
  };
  const MaterialTestResult dp = triaxial<DruckerPrager>(s, confining, LoadPath::triaxial_compression);
  const MaterialTestResult mc = triaxial<MohrCoulomb>(s, confining, LoadPath::triaxial_compression);
  ASSERT_GT(dp.rows.back().model_fields.at(0), s.softening.strain);  // plastic_strain beyond the softening range
  const Real dp_error = relative(dp.rows.back().deviatoric_stress, dp_q(residual));
  const Real mc_error = relative(mc.rows.back().deviatoric_stress, mc_q(residual));
  std::printf(
      "[ measured ] softening: residual q DP %.6g (error %.2e), MC %.6g (error %.2e); peaks %.6g <= %.6g, "
      "%.6g <= %.6g\n",
      dp.rows.back().deviatoric_stress, dp_error, mc.rows.back().deviatoric_stress, mc_error, peak_q(dp), dp_q(s),
      peak_q(mc), mc_q(s));
  EXPECT_LT(dp_error, 1e-10);
  EXPECT_LT(mc_error, 1e-10);
  EXPECT_LE(peak_q(dp), dp_q(s) * (1 + 1e-10));
  EXPECT_LE(peak_q(mc), mc_q(s) * (1 + 1e-10));
  EXPECT_LT(dp.rows.back().deviatoric_stress, 0.9 * peak_q(dp));
}

// A point at a stress on the cone (p = -100 kPa, q at 90% of the cone's) spun by a rigid rotation of 4 turns in 400
// steps: the Hughes-Winget rotation R = (1 - w/2)^-1 (1 + w/2) is orthogonal, so the principal stresses stay to
// round-off and no plastic flow occurs.
TEST(SoilModels, RigidRotationKeepsThePrincipalStresses) {
  const SoilParams s = sand(ConeMatching::outer_cone);
  SoilBatch<3, DruckerPrager> material(s);
  const ConeCoefficients yield = cone_coefficients(s.matching, s.friction);
  const Real p = -100e3, sqrt_j2 = 0.9 * (yield.xi * s.cohesion - yield.eta * p);
  Mat3 sigma = p * Mat3::Identity();
  sigma(0, 0) += -2 * sqrt_j2 / std::sqrt(3.0);  // s = diag(-2, 1, 1) sqrt(J2) / sqrt(3)
  sigma(1, 1) += sqrt_j2 / std::sqrt(3.0);
  sigma(2, 2) += sqrt_j2 / std::sqrt(3.0);
  const Eigen::Vector3d before = Eigen::SelfAdjointEigenSolver<Mat3>(sigma).eigenvalues();
  Mat3 spin = Mat3::Zero();
  const Real omega = 2 * std::numbers::pi * 4, dt = 1.0 / 400;  // 4 turns in 1 s
  spin(0, 1) = -omega;
  spin(1, 0) = omega;
  spin(1, 2) = -0.5 * omega;  // about an oblique axis
  spin(2, 1) = 0.5 * omega;
  SoilState state;
  for (int k = 0; k < 400; ++k) sigma = material.update_point(spin, dt, 1, sigma, state);
  const Eigen::Vector3d after = Eigen::SelfAdjointEigenSolver<Mat3>(sigma).eigenvalues();
  const Real error = (after - before).cwiseAbs().maxCoeff() / std::abs(p);
  std::printf("[ measured ] 400 spin steps: principal stresses kept to %.2e of p, plastic strain %g\n", error,
              state.plastic_strain);
  EXPECT_LT(error, 1e-12);
  EXPECT_EQ(state.plastic_strain, 0);
  EXPECT_EQ(state.plastic_volumetric_strain, 0);
}

// The model inside a run: a 0.1 m square column of cohesionless sand (Drucker-Prager, plane-strain cone, phi = 30 deg,
// psi = 0) collapsing under gravity on a fixed floor and wall, 2D MUSL, 0.2 s. Every particle ends on or inside the
// cone and below the apex p = 0, the plastic work is positive, and the energy audit (kinetic + strain + gravity +
// plastic work, fixed faces doing no work) closes to 1% of the initial potential energy.
std::string column_collapse(const std::string& model) {
  return R"(
dimension: 2
grid: {origin: [0, 0], extent: [0.4, 0.15], cell_size: 0.01, boundary: {x_min: fixed, y_min: fixed}}
materials:
  sand: {model: )" +
         model + R"(, density: 1800, youngs_modulus: 5.0e6, poisson_ratio: 0.3, friction_angle: 30 deg}
bodies: [{material: sand, shape: {type: box, min: [0, 0], max: [0.1, 0.1]}}]
solver: {scheme: musl, cfl: 0.4, end_time: 0.2, gravity: [0, -9.81]}
output: {fields: [plastic_strain, plastic_volumetric_strain]}
)";
}

TEST(SoilModels, ColumnCollapseStaysAdmissibleAndBooksItsEnergy) {
  for (const std::string model : {"drucker_prager", "mohr_coulomb"}) {
    auto sim = test::simulation_from_yaml<2>(column_collapse(model), "collapse.yaml");
    const EnergyBalance e0 = sim->energy();
    sim->run();
    const EnergyBalance e = sim->energy();
    const auto& body = sim->bodies()[0];
    const auto& p = body.particles;
    SoilParams s;
    s.friction = 30 * degree;
    s.shear_modulus = 1;
    s.bulk_modulus = 1;
    const DruckerPrager dp(s);
    const MohrCoulomb mc(s);
    Real worst = 0, largest_mean = -1e300, stress_scale = 0;
    for (Index i = 0; i < p.size(); ++i) {
      const Mat3 sigma = p.stress[i].full();
      stress_scale = std::max(stress_scale, sigma.cwiseAbs().maxCoeff());
      worst = std::max(worst, model == "drucker_prager" ? dp.yield_function(sigma) : mc.yield_function(sigma));
      largest_mean = std::max(largest_mean, sigma.trace() / 3);
    }
    std::vector<double> eps_p;
    ASSERT_TRUE(body.material->append_output("plastic_strain", p, eps_p));
    const Real balance = std::abs(e.total() - e0.total()) / std::abs(e0.gravity);
    std::printf(
        "[ measured ] %s column collapse: max yield function %.2e of the largest stress, max mean stress "
        "%.2e Pa, max plastic strain %.3f, plastic work %.4g J/m, energy balance %.2e of the potential\n",
        model.c_str(), worst / stress_scale, largest_mean, *std::max_element(eps_p.begin(), eps_p.end()),
        e.plastic_work, balance);
    EXPECT_LT(worst, 1e-9 * stress_scale);
    EXPECT_LE(largest_mean, 1e-9 * stress_scale);
    EXPECT_GT(e.plastic_work, 0);
    EXPECT_LT(balance, 0.01);
  }
}

// A collapse saved halfway (step 800 of about 3000) and restored into a new simulation ends with the same bits as
// the one that ran through: the soil history (field `soil`) travels with the particles' state.
TEST(SoilModels, RestartFromSavedStateIsExact) {
  for (const std::string model : {"drucker_prager", "mohr_coulomb"}) {
    const Real plastic = test_support::expect_exact_restart(column_collapse(model), "collapse.yaml", model);
    EXPECT_GT(plastic, 0.01) << model;  // the saved state had flowed
  }
}

// The history field is three doubles: checkpoints store it as float64 values and migration copies it as bytes.
TEST(SoilModels, HistoryIsCheckpointedAsDoubles) {
  const FieldLayout layout = field_layout_of<SoilState>("soil");
  EXPECT_EQ(layout.scalar, ScalarType::float64);
  EXPECT_EQ(layout.components, 3u);
}

}  // namespace
}  // namespace mpm::soils
