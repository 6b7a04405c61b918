// APIC (Jiang et al. 2015; review §5.5.1, eqs 5.37-5.38).
#include <gtest/gtest.h>

#include <cmath>

#include "mpm/scene_error.hpp"
#include "scene_fixture.hpp"

namespace mpm {
namespace {

std::string disk(const std::string& solver, const std::string& velocity) {
  return "dimension: 2\n"
         "grid: {origin: [0, 0], extent: [1, 1], cell_size: 0.05}\n"
         "materials: {m: {model: neo_hookean, density: 1000, youngs_modulus: 1.0e4, poisson_ratio: 0.3}}\n"
         "bodies: [{material: m, shape: {type: disk, center: [0.5, 0.5], radius: 0.3}, velocity: " +
         velocity +
         "}]\n"
         "solver: {" +
         solver + "}\n";
}

// An affine velocity field v = A x + b with C_p = A is transferred exactly, edge particles included:
// P2G gives m_I (A x_I + b) on every node and G2P reproduces the linear field. (With PIC the nodes at the
// body's edge receive a biased average, eq. 2.43.) Zero stress at the start: no force in the first step.
void check_affine_exact(const std::string& scheme, const std::string& shape) {
  auto sim = test::simulation_from_yaml<2>(
      disk("scheme: " + scheme + ", shape_function: " + shape + ", velocity_transfer: apic, dt: 1.0e-6, end_time: 1",
           "[\"0.2*x - 0.1*y + 0.05\", \"0.3*x + 0.1*y\"]"));
  Mat<2> A;
  A << 0.2, -0.1, 0.3, 0.1;
  auto& p = sim->bodies()[0].particles;
  for (auto& C : p.field<MatU<2>>("affine_velocity")) C = A;
  sim->advance(1e-6);
  Real worst = 0;
  for (Index i = 0; i < p.size(); ++i) {
    // Positions moved by dt v; compare with the field at the new position (changes by O(dt |A v|) ~ 1e-7).
    const Vec<2> x = p.x[i], exact = A * x + Vec<2>(0.05, 0);
    worst = std::max(worst, (Vec<2>(p.v[i]) - exact).norm());
  }
  EXPECT_LT(worst, 1e-6) << scheme << " " << shape;
  for (const auto& C : p.field<MatU<2>>("affine_velocity")) ASSERT_LT((Mat<2>(C) - A).norm(), 1e-6);
}

TEST(Apic, AffineFieldTransferredExactlyUslLinear) { check_affine_exact("usl", "linear"); }
TEST(Apic, AffineFieldTransferredExactlyMuslLinear) { check_affine_exact("musl", "linear"); }
TEST(Apic, AffineFieldTransferredExactlyMuslCubic) { check_affine_exact("musl", "cubic_bspline"); }
TEST(Apic, AffineFieldTransferredExactlyUsfQuadratic) { check_affine_exact("usf", "quadratic_bspline"); }

Real angular_momentum(const Simulation<2>& sim) {
  Real L = 0;
  for (const auto& b : sim.bodies())
    for (Index i = 0; i < b.particles.size(); ++i) {
      const Vec<2> r = Vec<2>(b.particles.x[i]) - Vec<2>(0.5, 0.5);
      L += b.particles.mass[i] * (r[0] * b.particles.v[i][1] - r[1] * b.particles.v[i][0]);
    }
  return L;
}

// A spinning disk (rigid rotation at 1 rad/s): APIC keeps its angular momentum, PIC dissipates it.
// Only the particles' orbital part sum m x (x) v is measured here; APIC also carries angular momentum in
// C_p (the term m (C_p D_p)^T : epsilon of Jiang et al.), an O(h^2) share: measured 0.979 after 1 s.
TEST(Apic, SpinningDiskKeepsAngularMomentum) {
  const std::string spin = "[\"-(y-0.5)\", \"x-0.5\"]";
  auto apic = test::simulation_from_yaml<2>(disk("scheme: musl, velocity_transfer: apic, cfl: 0.4, end_time: 1", spin));
  auto pic = test::simulation_from_yaml<2>(disk("scheme: musl, flip_fraction: 0, cfl: 0.4, end_time: 1", spin));
  const Real L0 = angular_momentum(*apic);
  apic->run();
  pic->run();
  const Real la = angular_momentum(*apic) / L0, lp = angular_momentum(*pic) / L0;
  std::printf("[ measured ] spinning disk after 1 s: angular momentum APIC %.5f, PIC %.5f of the initial\n", la, lp);
  EXPECT_GT(la, 0.97);
  EXPECT_LT(la, 1.0 + 1e-9);
  EXPECT_LT(lp, 0.05);  // measured 0.011
  const auto e = apic->energy();
  EXPECT_LT(e.momentum.norm(), 1e-10 * e.mass);  // linear momentum stays zero
}

TEST(Apic, RefusedWithTlmpm) {
  EXPECT_THROW(
      test::simulation_from_yaml<2>(disk("scheme: tlmpm, velocity_transfer: apic, cfl: 0.4, end_time: 1", "[0, 0]")),
      SceneError);
}

}  // namespace
}  // namespace mpm
