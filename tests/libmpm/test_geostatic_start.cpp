// The geostatic start of a soil body (docs/theory.md §20): a set's `initial_stress: geostatic` (eqs 20.1-20.2,
// libmpm/src/sets/geostatic_stress.cpp) against the weight of the material above each particle, and the gravity
// stage (`solver.gravity_stage`, eqs 20.3-20.4, libmpm/src/simulation/gravity_stage.cpp) against the static stress
// of a laterally confined elastic column.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <numbers>
#include <string>

#include "history_fixture.hpp"
#include "mpm/particles/field_keys.hpp"

namespace mpm::test {
namespace {

// Two layers in one set, a lighter one (rho 1800, 1 m) on a heavier one (rho 2000, 1 m), plane strain, g = 10:
// sigma_yy = -g rho_1 (2 - y) in the upper layer, -g (rho_1 + rho_2 (1 - y)) in the lower one. The upper layer
// is a Drucker-Prager sand of friction angle 30 degrees (Jaky: K0 = 1 - sin 30 = 0.5), the lower an elastic clay
// (nu = 0.25: K0 = nu / (1 - nu) = 1/3), unless the condition gives k0. Slip walls and a fixed base: the state is
// in equilibrium, so the run leaves it as it is.
const std::string layers = R"yaml(
dimension: 2
grid: {origin: [0, 0], extent: [1, 2.5], cell_size: 0.1, boundary: {x_min: slip, x_max: slip, y_min: fixed}}
materials:
  sand: {model: drucker_prager, density: 1800, youngs_modulus: 2.0e7, poisson_ratio: 0.3, friction_angle: 30,
         cohesion: 0}
  clay: {model: linear_elastic, density: 2000, youngs_modulus: 1.0e7, poisson_ratio: 0.25}
bodies:
  - {name: upper, material: sand, shape: {type: box, min: [0, 1], max: [1, 2]}}
  - {name: lower, material: clay, shape: {type: box, min: [0, 0], max: [1, 1]}}
sets:
  ground: {body: [upper, lower]}
conditions:
  - {set: ground, initial_stress: geostatic}
solver: {scheme: musl, cfl: 0.5, gravity: [0, -10], end_time: 0.05}
output: {fields: [displacement]}
)yaml";

double vertical_stress(double y) { return y >= 1 ? -10 * 1800 * (2 - y) : -10 * (1800 + 2000 * (1 - y)); }

TEST(GeostaticStress, IsTheWeightAboveWithEachModelsK0) {
  auto m = measured<2>(layers);
  double worst = 0;
  for (const auto& b : m->sim->bodies()) {
    const double k0 = b.name == "upper" ? 0.5 : 0.25 / 0.75;
    for (Index i = 0; i < b.particles.size(); ++i) {
      const double sv = vertical_stress(b.particles.x[i][1]);
      const auto& s = b.particles.stress[i].c;
      for (const double e : {s[0] - k0 * sv, s[1] - sv, s[2] - k0 * sv, s[3]}) worst = std::max(worst, std::abs(e));
    }
  }
  std::printf("[ measured ] largest |sigma - sigma_geostatic| %.3g Pa of rho g H = 38000 Pa\n", worst);
  EXPECT_LT(worst, 1e-10 * 38000);  // eq. 20.1 is exact for piecewise-constant density (the interface at mid-gap)

  // A column at rest stays so: the stress is the state of equilibrium of the grid's weights too.
  const double e0 = m->sim->energy().total();
  double moved = 0;
  m->sim->run([&](const Simulation<2>& sim) {
    for (const auto& b : sim.bodies())
      for (Index i = 0; i < b.particles.size(); ++i)
        moved = std::max(moved, (b.particles.x[i] - b.particles.field(keys::reference_position<2>)[i]).norm());
  });
  std::printf("[ measured ] over 0.05 s: largest displacement %.3g m, energy change %.3g J/m\n", moved,
              m->sim->energy().total() - e0);
  EXPECT_LT(moved, 1e-9);
}

TEST(GeostaticStress, TakesTheConditionsK0AndAnyVerticalAxis) {
  std::string yaml = layers;
  yaml.replace(yaml.find("initial_stress: geostatic}"), 26, "initial_stress: geostatic, k0: 0.7}");
  auto m = measured<2>(yaml);
  const auto& p = m->sim->bodies()[1].particles;
  for (Index i = 0; i < p.size(); ++i) EXPECT_NEAR(p.stress[i].c[0], 0.7 * p.stress[i].c[1], 1e-9);

  // 3D with gravity along -z: sigma_zz the weight, sigma_xx = sigma_yy = K0 sigma_zz
  const std::string column3d = R"yaml(
dimension: 3
grid: {extent: [0.4, 0.4, 1.2], cell_size: 0.1, boundary: {z_min: fixed}}
materials: {sand: {model: drucker_prager, density: 1600, youngs_modulus: 2.0e7, poisson_ratio: 0.3,
                   friction_angle: 35}}
bodies: [{name: sand, material: sand, shape: {type: box, min: [0, 0, 0], max: [0.4, 0.4, 1]}}]
sets: {all: {body: sand}}
conditions: [{set: all, initial_stress: geostatic}]
solver: {scheme: musl, cfl: 0.5, gravity: [0, 0, -9.81], end_time: 0.01}
)yaml";
  auto c = measured<3>(column3d);
  const double k0 = 1 - std::sin(35 * std::numbers::pi / 180);
  const auto& q = c->sim->bodies()[0].particles;
  for (Index i = 0; i < q.size(); ++i) {
    const double sv = -9.81 * 1600 * (1 - q.x[i][2]);
    EXPECT_NEAR(q.stress[i].c[2], sv, 1e-9);
    EXPECT_NEAR(q.stress[i].c[0], k0 * sv, 1e-9);
    EXPECT_NEAR(q.stress[i].c[1], k0 * sv, 1e-9);
    for (int k = 3; k < 6; ++k) EXPECT_EQ(q.stress[i].c[k], 0);
  }
}

// The gravity stage on a laterally confined elastic column started from zero stress: it settles, the run starts at
// rest at t = 0 from the static state, sigma_yy = -rho g (H - Y) by the weight above (Y the height before
// settling: the mass above a particle does not change) and sigma_xx = sigma_zz = nu / (1 - nu) sigma_yy (no lateral
// strain), each within 1% of rho g H (issue 52: "geostatic column ... within 1% after the gravity stage").
const std::string settling = R"yaml(
dimension: 2
grid: {origin: [0, 0], extent: [1, 2.5], cell_size: 0.1, boundary: {x_min: slip, x_max: slip, y_min: fixed}}
materials:
  soil: {model: linear_elastic, density: 2000, youngs_modulus: 1.0e7, poisson_ratio: 0.3}
bodies:
  - {name: column, material: soil, shape: {type: box, min: [0, 0], max: [1, 2]}}
solver: {scheme: @SCHEME@, cfl: 0.5, gravity: [0, -10], end_time: 0.05, gravity_stage: {tolerance: 1.0e-4}}
output: {fields: [displacement]}
)yaml";

class GravityStage : public ::testing::TestWithParam<const char*> {};

TEST_P(GravityStage, SettlesAConfinedColumnToItsStaticStress) {
  std::string yaml = settling;
  yaml.replace(yaml.find("@SCHEME@"), 8, GetParam());
  auto m = measured<2>(yaml);
  Simulation<2>& sim = *m->sim;
  EXPECT_EQ(sim.time(), 0);
  EXPECT_EQ(sim.step(), 0);
  const auto& p = sim.bodies()[0].particles;
  const double rho_g_H = 2000 * 10 * 2.0, k0 = 0.3 / 0.7;
  // Y: each particle's height in the filled lattice (a row every 0.05 m from 0.025 m), which the settlement (< 3 mm)
  // does not leave; rho g (H - Y) is the weight above it. Linear hats give a strain, so a stress, constant in each
  // cell: the two rows of a cell share the stress of the cell's middle, rho g h / 4 = 500 Pa from each row's own
  // (1.25% of rho g H at 20 cells). So the stress field is compared cell by cell (the mean of a cell's particles
  // against the weight above the mean of their heights), and particle by particle within that bound.
  std::map<long, std::array<double, 5>> cells;  // by row of cells: count, sums of Y, sigma_yy, sigma_xx, sigma_zz
  double particle_error = 0, speed = 0, top = 0;
  for (Index i = 0; i < p.size(); ++i) {
    const double Y = (std::round(p.x[i][1] / 0.05 - 0.5) + 0.5) * 0.05, sv = -2000 * 10 * (2 - Y);
    auto& c = cells[std::lround(std::floor(Y / 0.1))];
    c[0] += 1, c[1] += Y, c[2] += p.stress[i].c[1], c[3] += p.stress[i].c[0], c[4] += p.stress[i].c[2];
    particle_error = std::max(particle_error, std::abs(p.stress[i].c[1] - sv));
    speed = std::max(speed, Vec<2>(p.v[i]).norm());
    top = std::max(top, double(p.x[i][1]));
  }
  double vertical = 0, horizontal = 0;
  for (const auto& [row, c] : cells) {
    const double sv = -2000 * 10 * (2 - c[1] / c[0]);
    vertical = std::max(vertical, std::abs(c[2] / c[0] - sv));
    horizontal = std::max({horizontal, std::abs(c[3] / c[0] - k0 * sv), std::abs(c[4] / c[0] - k0 * sv)});
  }
  const double static_settlement = rho_g_H * 2.0 / (2 * 1e7 * 0.7 / (1.3 * 0.4));  // rho g H^2 / (2 M)
  std::printf(
      "[ measured ] %s: per cell sigma_yy within %.3g Pa, sigma_xx = sigma_zz within %.3g Pa of rho g H = %.0f Pa; "
      "per particle sigma_yy within %.3g Pa; speed after the stage %.3g m/s; the top row settled %.4g mm (static "
      "%.4g mm at the top surface)\n",
      GetParam(), vertical, horizontal, rho_g_H, particle_error, speed, 1e3 * (1.975 - top), 1e3 * static_settlement);
  EXPECT_LT(vertical, 0.01 * rho_g_H);
  EXPECT_LT(horizontal, 0.01 * rho_g_H);
  EXPECT_LT(particle_error, 2000 * 10 * 0.1 / 4 + 0.01 * rho_g_H);
  EXPECT_EQ(speed, 0);
  // the displacement counts from the settled state
  for (Index i = 0; i < p.size(); ++i) EXPECT_EQ(Vec<2>(p.field(keys::reference_position<2>)[i]), Vec<2>(p.x[i]));
  // and the run stays at rest from it
  double moved = 0;
  sim.run([&](const Simulation<2>& s) {
    const auto& q = s.bodies()[0].particles;
    for (Index i = 0; i < q.size(); ++i)
      moved = std::max(moved, (q.x[i] - q.field(keys::reference_position<2>)[i]).norm());
  });
  std::printf("[ measured ] %s: largest displacement over the 0.05 s after the stage %.3g m\n", GetParam(), moved);
  EXPECT_LT(moved, 1e-3 * static_settlement);
}

INSTANTIATE_TEST_SUITE_P(Schemes, GravityStage, ::testing::Values("musl", "usl", "usf"));

}  // namespace
}  // namespace mpm::test
