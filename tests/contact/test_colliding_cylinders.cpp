// Colliding elastic-plastic cylinders of Love & Sulsky (reference 003, §4.2): plane strain, radius 1,
// centres (-1.05, 0) and (1.05, 0), the left one at velocity (1.0, -0.1), the right one at rest; K = 133.3,
// G = 43.3 (E = 117.2, nu = 0.3535), sigma_Y = 10, H = 0.01, rho0 = 8.824; domain [-2.20, 2.728] x
// [-1.44, 1.20] with 28 x 22 cells, dt = 0.015, 120 steps. Their implicit energy-consistent scheme
// conserves linear and angular momentum exactly and the energy (kinetic + stored + dissipated) to the
// solver tolerance. Here (explicit MUSL with multi-velocity contact): linear momentum to round-off (equal
// and opposite normals), angular momentum drifts (reported: the contact corrections act at the nodes,
// not at the particles, and the lumped-mass transfers lose some), and with either onset the total energy
// (kinetic + strain + plastic work) never increases.
#include <cmath>
#include <cstdio>

#include "contact_scene_support.hpp"

#if defined(MPM_WITH_PLASTICITY)

namespace mpm::test {
namespace {

const std::string cylinders = R"(
dimension: 2
grid: {origin: [-2.20, -1.44], extent: [4.928, 2.64], cell_size: [0.176, 0.12]}
materials:
  metal: {model: j2_plasticity, density: 8.824, youngs_modulus: 117.21, poisson_ratio: 0.35346,
          yield_stress: 10, hardening_modulus: 0.01}
bodies:
  - {name: left, material: metal, shape: {type: disk, center: [-1.05, 0], radius: 1}, particles_per_cell: 2,
     velocity: [1.0, -0.1]}
  - {name: right, material: metal, shape: {type: disk, center: [1.05, 0], radius: 1}, particles_per_cell: 2}
solver: {scheme: musl, shape_function: linear, velocity_transfer: flip, dt: 0.015, end_time: 1.8}
contact: {onset: @ONSET@}
)";

TEST(CollidingCylinders, MomentumConservedEnergyNeverIncreases) {
  for (const std::string onset : {"grid", "particle_gap"}) {
    auto sim = simulation_from_yaml<2>(fill(cylinders, {{"ONSET", onset}}));
    const Vec<2> p0 = total_momentum(*sim);
    const double L0 = angular_momentum(*sim), e0 = sim->energy().total();
    double p_drift = 0, L_drift = 0, e_max = e0;
    sim->run([&](const Simulation<2>& s) {
      p_drift = std::max(p_drift, (total_momentum(s) - p0).norm());
      L_drift = std::max(L_drift, std::abs(angular_momentum(s) - L0));
      e_max = std::max(e_max, s.energy().total());
    });
    const auto e = sim->energy();
    std::printf(
        "[ measured ] colliding cylinders (%s onset, 120 steps): |p - p0| max %.2e (|p0| = %.3f); angular momentum "
        "drift max %.3e (L0 = %.4f, %.2f%%); energy max/E0 - 1 = %.2e, final: kinetic %.4f strain %.4f plastic %.4f "
        "total/E0 - 1 = %.3e; onset %.3f\n",
        onset.c_str(), p_drift, p0.norm(), L_drift, L0, 100 * L_drift / std::abs(L0), e_max / e0 - 1, e.kinetic,
        e.strain, e.plastic_work, e.total() / e0 - 1, contact_module(*sim)->onset_time());
    EXPECT_EQ(sim->step(), 120);
    EXPECT_LT(p_drift, 1e-12 * 30);            // round-off on momenta of order 28 (kg m/s per unit thickness)
    EXPECT_LT(L_drift, 0.012 * std::abs(L0));  // measured 1.00% (node onset), 0.71% (particle gap)
    EXPECT_GT(e.plastic_work, 0);              // the cylinders yield at the contact
    // with the paper's corrections the node criterion gained +5.6% (test_contact_energy.cpp shows why);
    // now measured never above E0 with either onset, final -13.6% (node) and -4.6% (particle gap).
    EXPECT_LE(e_max, e0 * (1 + 1e-9));
  }
}

}  // namespace
}  // namespace mpm::test

#endif
