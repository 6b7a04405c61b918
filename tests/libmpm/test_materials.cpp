// Material-point tests of the elastic laws (review App. B.1-B.2), strain path in, stress out.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "mpm/materials/linear_elastic.hpp"
#include "mpm/materials/material_batch.hpp"
#include "mpm/materials/neo_hookean.hpp"

namespace mpm {
namespace {

const ElasticConstants steel = ElasticConstants::from_young_poisson(7800, 200e9, 0.3);

// Runs a velocity-gradient history on one 3D particle through the batched interface, updating F the
// way the schemes do (eq. 2.55b).
template <class Model>
SymTensor<3> drive(const Mat3& L, Real dt, int steps, const Mat3& F0 = Mat3::Identity(),
                   const Mat3& s0 = Mat3::Zero()) {
  ParticleSet<3> p;
  p.add(Vec<3>::Zero(), 1, 1);
  p.F[0] = F0;
  p.stress[0] = SymTensor<3>::from(s0);
  MaterialBatch<3, Model> m(steel);
  const MatU<3> Lu = L;
  for (int s = 0; s < steps; ++s) {
    p.F[0] = (Mat3::Identity() + dt * L) * p.F[0];
    m.update_stress(p, 0, 1, &Lu, dt);
  }
  return p.stress[0];
}

TEST(Materials, LinearElasticUniaxialStrain) {
  // 1e-4 axial strain in 100 steps: sigma_xx = (lambda + 2 mu) eps, sigma_yy = sigma_zz = lambda eps.
  Mat3 L = Mat3::Zero();
  L(0, 0) = 1e-4;
  const Mat3 s = drive<LinearElastic>(L, 0.01, 100).full();
  EXPECT_NEAR(s(0, 0), (steel.lambda + 2 * steel.mu) * 1e-4, 1e-9 * steel.mu);
  EXPECT_NEAR(s(1, 1), steel.lambda * 1e-4, 1e-9 * steel.mu);
  EXPECT_NEAR(s(2, 2), steel.lambda * 1e-4, 1e-9 * steel.mu);
  EXPECT_NEAR(s(0, 1), 0, 1e-9 * steel.mu);
}

TEST(Materials, LinearElasticSimpleShear) {
  Mat3 L = Mat3::Zero();
  L(0, 1) = 2e-5;  // engineering shear 2e-5 -> tensor shear strain 1e-5
  const Mat3 s = drive<LinearElastic>(L, 0.1, 10).full();
  EXPECT_NEAR(s(0, 1), 2 * steel.mu * 1e-5, 1e-6 * steel.mu * 1e-5);
  EXPECT_NEAR(s.trace(), 0, 1e-12 * steel.mu);
}

// Jaumann rate: a stressed point spun through 90 degrees keeps its invariants (to the first-order
// accuracy of the explicit update) and its stress tensor turns with the body.
TEST(Materials, LinearElasticRigidRotationIsObjective) {
  Mat3 s0 = Mat3::Zero();
  s0(0, 0) = 100e6;
  s0(1, 1) = -20e6;
  s0(0, 1) = s0(1, 0) = 30e6;
  const Real omega = 1, angle = std::numbers::pi / 2;
  const int steps = 20000;
  Mat3 L = Mat3::Zero();
  L(1, 0) = omega;
  L(0, 1) = -omega;
  const Mat3 s = drive<LinearElastic>(L, angle / steps, steps, Mat3::Identity(), s0).full();
  const auto vm = [](const Mat3& a) {
    const Mat3 d = a - a.trace() / 3 * Mat3::Identity();
    return std::sqrt(1.5 * d.squaredNorm());
  };
  EXPECT_NEAR(s.trace(), s0.trace(), 1e-9 * s0.norm());
  EXPECT_NEAR(vm(s), vm(s0), 1e-3 * vm(s0));
  // After a quarter turn about z, sigma_xx and sigma_yy have swapped and sigma_xy changed sign.
  EXPECT_NEAR(s(0, 0), s0(1, 1), 1e-3 * s0.norm());
  EXPECT_NEAR(s(1, 1), s0(0, 0), 1e-3 * s0.norm());
  EXPECT_NEAR(s(0, 1), -s0(0, 1), 1e-3 * s0.norm());
}

TEST(Materials, NeoHookeanStressMatchesClosedForm) {
  Mat3 F;
  F << 1.2, 0.1, 0, 0, 0.9, 0, 0, 0, 1.05;
  ParticleSet<3> p;
  p.add(Vec<3>::Zero(), 1, 1);
  p.F[0] = F;
  MaterialBatch<3, NeoHookean> m(steel);
  const MatU<3> zero = MatU<3>::Zero();
  m.update_stress(p, 0, 1, &zero, 1e-3);
  const Real J = F.determinant();
  const Mat3 expected =
      (steel.mu * (F * F.transpose() - Mat3::Identity()) + steel.lambda * std::log(J) * Mat3::Identity()) / J;
  EXPECT_LT((p.stress[0].full() - expected).norm(), 1e-12 * expected.norm());
  // Stored energy W(F) (Bonet & Wood) times the reference volume 1.
  const Real W = 0.5 * steel.mu * ((F.transpose() * F).trace() - 3) - steel.mu * std::log(J) +
                 0.5 * steel.lambda * std::log(J) * std::log(J);
  EXPECT_NEAR(m.strain_energy(p), W, 1e-12 * W);
}

TEST(Materials, NeoHookeanSmallStrainLimitIsHooke) {
  Mat3 L = Mat3::Zero();
  L(0, 0) = 1e-6;
  const Mat3 s = drive<NeoHookean>(L, 1, 1).full();
  EXPECT_NEAR(s(0, 0), (steel.lambda + 2 * steel.mu) * 1e-6, 1e-5 * s(0, 0));
  EXPECT_NEAR(s(1, 1), steel.lambda * 1e-6, 1e-5 * s(0, 0));
}

TEST(Materials, LinearElasticEnergyIsHalfStressTimesStrain) {
  Mat3 L = Mat3::Zero();
  L(0, 0) = 1e-4;
  L(1, 1) = -3e-5;
  ParticleSet<3> p;
  p.add(Vec<3>::Zero(), 1, 1);
  MaterialBatch<3, LinearElastic> m(steel);
  const MatU<3> Lu = L;
  p.F[0] = Mat3::Identity() + L;
  m.update_stress(p, 0, 1, &Lu, 1);
  const Mat3 eps = L;  // one step of dt = 1
  const Real expected = 0.5 * (p.stress[0].full().cwiseProduct(eps)).sum() * p.F[0].determinant();
  EXPECT_NEAR(m.strain_energy(p), expected, 1e-10 * expected);
}

TEST(Materials, WaveSpeed) {
  EXPECT_NEAR(LinearElastic::wave_speed(steel, 1), std::sqrt((steel.lambda + 2 * steel.mu) / steel.density), 1e-9);
  EXPECT_NEAR(NeoHookean::wave_speed(steel, 1), std::sqrt((steel.lambda + 2 * steel.mu) / steel.density), 1e-9);
  EXPECT_GT(NeoHookean::wave_speed(steel, 0.5), NeoHookean::wave_speed(steel, 1));  // stiffer in compression
}

}  // namespace
}  // namespace mpm

namespace mpm {
namespace {

// The packed in-plane update (used by the batch loop in 1D/2D/3D) must be the same law as the 3x3
// update_point: drive both along the same plane-strain history.
template <class Model, int Dim>
void check_packed_equals_general() {
  Mat<Dim> L = Mat<Dim>::Zero();
  for (int r = 0; r < Dim; ++r)
    for (int c = 0; c < Dim; ++c) L(r, c) = 0.3 * (r + 1) - 0.2 * c + (r == c ? 0.1 : -0.05);
  ParticleSet<Dim> packed;
  packed.add(Vec<Dim>::Zero(), 1, 1);
  MaterialBatch<Dim, Model> batch(steel);
  Mat3 F3 = Mat3::Identity(), s3 = Mat3::Zero();
  const Real dt = 1e-3;
  for (int step = 0; step < 50; ++step) {
    const MatU<Dim> Lu = L;
    packed.F[0] = (Mat<Dim>::Identity() + dt * L) * packed.F[0];
    batch.update_stress(packed, 0, 1, &Lu, dt);
    PointKinematics k;
    k.L = embed<Dim>(L, 0);
    F3 = (Mat3::Identity() + dt * k.L) * F3;
    k.F = F3;
    k.J = F3.determinant();
    k.dt = dt;
    s3 = Model::update_point(steel, k, s3);
  }
  EXPECT_LT((packed.stress[0].full() - s3).norm(), 1e-10 * s3.norm()) << Model::key << " " << Dim << "D";
}

TEST(Materials, PackedUpdateEqualsGeneralLaw) {
  check_packed_equals_general<LinearElastic, 1>();
  check_packed_equals_general<LinearElastic, 2>();
  check_packed_equals_general<LinearElastic, 3>();
  check_packed_equals_general<NeoHookean, 1>();
  check_packed_equals_general<NeoHookean, 2>();
  check_packed_equals_general<NeoHookean, 3>();
}

}  // namespace
}  // namespace mpm
