// The fluids module on an axisymmetric body: one step of a uniform radial expansion v_r = a r, mapped
// exactly by APIC (C_p = diag(a, 0); tests/libmpm/test_axisymmetric.cpp) and differentiated by USF before any force
// acts (the gas's initial pressure pushes its free faces), so that tr D = L_rr + L_tt = 2 a and
// J = (1 + a dt)^2: the ideal gas's energy update (eq. 5.33 with D, docs/errata.md #11) and the Tait pressure
// (eq. 5.31) against those closed forms. In plane strain tr D would be a: the hoop rate must reach the laws.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "../libmpm/scene_fixture.hpp"
#include "mpm/fluids/field_keys.hpp"
#include "mpm/particles/field_keys.hpp"

namespace mpm {
namespace {

std::unique_ptr<Simulation<2>> expanding_ring(const std::string& material, double a) {
  auto sim = test::simulation_from_yaml<2>(R"(dimension: 2
grid: {coordinates: axisymmetric, extent: [1.0, 1.0], cell_size: 0.1}
materials: {fluid: )" + material + R"(}
bodies: [{material: fluid, shape: {type: box, min: [0, 0.2], max: [0.6, 0.8]}, velocity: ["0.01*x", 0]}]
solver: {scheme: usf, velocity_transfer: apic, dt: 1.0e-4, end_time: 1}
)");
  Mat<2> C = Mat<2>::Zero();
  C(0, 0) = a;
  for (auto& c : sim->bodies()[0].particles.field(mpm::keys::affine_velocity<2>)) c = C;
  return sim;
}

TEST(AxisymmetricFluids, IdealGasSeesTheHoopRate) {
  const double a = 0.01, dt = 1e-4, gamma = 1.4, rho0 = 1.2, p0 = 1e5;
  auto sim = expanding_ring("{model: ideal_gas, density: 1.2, initial_pressure: 1.0e5, gamma: 1.4}", a);
  sim->advance(dt);
  const auto& p = sim->bodies()[0].particles;
  const auto& e = p.field(fluids::keys::internal_energy);
  const double e0 = p0 / ((gamma - 1) * rho0), trD = 2 * a, J = (1 + a * dt) * (1 + a * dt);
  const double e1 = e0 / (1 + dt * (gamma - 1) * trD);  // expanding: no artificial viscosity
  const double pressure = (gamma - 1) * rho0 / J * e1;
  for (Index i = 0; i < p.size(); ++i) {
    ASSERT_NEAR(e[i], e1, 1e-12 * e1) << i;
    for (int c = 0; c < 3; ++c) ASSERT_NEAR(p.stress[i].c[c], -pressure, 1e-10 * pressure) << i;
  }
}

TEST(AxisymmetricFluids, TaitPressureFromTheRingVolume) {
  const double a = 0.01, dt = 1e-4, kappa = 2e6, gamma = 7, mu = 1e-3;
  auto sim = expanding_ring("{model: newtonian_fluid, density: 1000, bulk_modulus: 2.0e6, viscosity: 1.0e-3}", a);
  sim->advance(dt);
  const auto& p = sim->bodies()[0].particles;
  const double J = (1 + a * dt) * (1 + a * dt), pressure = kappa * (std::pow(J, -gamma) - 1);
  for (Index i = 0; i < p.size(); ++i) {
    // sigma = 2 mu dev(D) - p I with D = diag(a, 0, a): rr = tt = 2 mu a/3 - p, zz = -4 mu a/3 - p
    ASSERT_NEAR(p.stress[i].c[0], 2 * mu * a / 3 - pressure, 1e-9 * std::abs(pressure)) << i;
    ASSERT_NEAR(p.stress[i].c[2], p.stress[i].c[0], 1e-9 * std::abs(pressure)) << i;
    ASSERT_NEAR(p.stress[i].c[1], -4 * mu * a / 3 - pressure, 1e-9 * std::abs(pressure)) << i;
  }
}

}  // namespace
}  // namespace mpm
