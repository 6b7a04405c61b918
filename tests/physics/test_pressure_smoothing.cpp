// The fluids' node-averaged volume ratio (pressure_smoothing, docs/theory.md eqs PS.1-PS.3): what one averaging does
// to a noisy J (volume kept, energy only removed and booked), and what it buys on a hydrostatic column and a dam
// break in a closed tank.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>

#include "../libmpm/scene_fixture.hpp"
#include "mpm/core/exact_sum.hpp"
#include "mpm/schemes/axisymmetric.hpp"

namespace mpm {
namespace {

/// Water at rest in a closed box without gravity, `smoothing` 0 or 1.
std::string still_water(int smoothing) {
  return test::fill(R"yaml(dimension: 2
grid: {origin: [0, 0], extent: [1, 1], cell_size: 0.1, boundary: {x_min: slip, x_max: slip, y_min: slip, y_max: slip}}
materials:
  water: {model: newtonian_fluid, density: 1000, bulk_modulus: 2.0e5, pressure_smoothing: @S@}
bodies:
  - {name: water, material: water, shape: {type: box, min: [0.2, 0.2], max: [0.8, 0.6]}, particles_per_cell: 2}
solver: {scheme: musl, shape_function: linear, dt: 1.0e-9, end_time: 1.0e-9}
)yaml",
                    {{"S", std::to_string(smoothing)}});
}

struct VolumeBooks {
  double volume = 0;  ///< sum m J / rho0 (m^2)
  double spread = 0;  ///< largest J - smallest J
};
VolumeBooks books(const Simulation<2>& sim) {
  ExactSum volume;
  double lo = 1e300, hi = -1e300;
  for (const auto& b : sim.bodies())
    for (Index i = 0; i < b.particles.size(); ++i) {
      const double J = Mat<2>(b.particles.F[i]).determinant();
      volume += b.particles.volume0[i] * J;
      lo = std::min(lo, J);
      hi = std::max(hi, J);
    }
  return {volume.value(), hi - lo};
}

// One step of 1 ns on water at rest whose J alternates 0.99 / 1.01 from particle to particle (a noise below the
// grid's resolution): the average keeps sum V0 J (eq. PS.2) to round-off, takes the noise out (the spread of J falls
// from 0.02 to what the free surface's half-empty nodes leave), and the stored energy it removes is what
// `smoothed_energy` books (eq. PS.3): strain energy + booked = the strain energy before, to the step's kinetic
// energy (1e-9 s of acceleration). A uniform J stays uniform to round-off.
TEST(PressureSmoothing, KeepsTheVolumeAndBooksTheEnergyItRemoves) {
  auto sim = test::simulation_from_yaml<2>(still_water(1), "still.yaml");
  auto& p = sim->bodies()[0].particles;
  for (Index i = 0; i < p.size(); ++i) p.F[i] = MatU<2>(std::sqrt(i % 2 ? 1.01 : 0.99) * Mat<2>::Identity());
  const VolumeBooks before = books(*sim);
  const double w0 = sim->energy().strain;
  sim->run();
  const VolumeBooks after = books(*sim);
  int smoothing_modules = 0;
  double removed = 0;
  for (const auto& m : sim->modules())
    if (m->name() == "pressure_smoothing") {
      ++smoothing_modules;
      removed = m->energy_column_value();
    }
  ASSERT_EQ(smoothing_modules, 1);
  std::printf(
      "[ measured ] one average: volume %.15g -> %.15g, J spread %.4f -> %.4f, strain energy %.6g -> %.6g J, "
      "booked %.6g J, kinetic %.3g J\n",
      before.volume, after.volume, before.spread, after.spread, w0, sim->energy().strain, removed,
      sim->energy().kinetic);
  EXPECT_NEAR(after.volume, before.volume, 1e-12 * before.volume);
  EXPECT_LT(after.spread, 0.5 * before.spread);
  EXPECT_GT(removed, 0.5 * w0);
  EXPECT_NEAR(sim->energy().strain + removed, w0, 1e-6 * w0);

  auto uniform = test::simulation_from_yaml<2>(still_water(1), "still.yaml");
  auto& q = uniform->bodies()[0].particles;
  for (Index i = 0; i < q.size(); ++i) q.F[i] = MatU<2>(std::sqrt(0.99) * Mat<2>::Identity());
  uniform->run();
  EXPECT_LT(books(*uniform).spread, 1e-12);
}

/// One average of an alternating J (0.99 / 1.01 by particle) in `Dim` dimensions, `grid` the grid line of the scene
/// (axisymmetric or Cartesian): returns {sum m J before, after, strain energy before, after + smoothed_energy,
/// smoothed_energy}.
template <int Dim>
std::array<double, 5> one_average(const std::string& grid, const std::string& box) {
  auto sim = test::simulation_from_yaml<Dim>(test::fill(R"yaml(dimension: @D@
grid: @G@
materials: {water: {model: newtonian_fluid, density: 1000, bulk_modulus: 2.0e5, pressure_smoothing: 1}}
bodies: [{name: water, material: water, shape: {type: box, @B@}, particles_per_cell: 2}]
solver: {scheme: usf, dt: 1.0e-9, end_time: 1.0e-9}
)yaml",
                                                        {{"D", std::to_string(Dim)}, {"G", grid}, {"B", box}}),
                                             "still.yaml");
  auto& p = sim->bodies()[0].particles;
  const auto mass_volume = [&] {
    ExactSum s;
    for (Index i = 0; i < p.size(); ++i) s += p.mass[i] * axisym::volume_ratio(p, i, axisym::hoop_stretch_of(p));
    return s.value();
  };
  for (Index i = 0; i < p.size(); ++i)
    p.F[i] = MatU<Dim>(std::pow(i % 2 ? 1.01 : 0.99, 1.0 / Dim) * Mat<Dim>::Identity());
  const double before = mass_volume(), w0 = sim->energy().strain;
  sim->run();
  double removed = 0;
  for (const auto& m : sim->modules())
    if (m->name() == "pressure_smoothing") removed = m->energy_column_value();
  return {before, mass_volume(), w0, sim->energy().strain + removed, removed};
}

// Eqs PS.2-PS.3 in 1D, 3D and on an axisymmetric body (ring masses, J with the hoop stretch), with USF: sum m J kept
// to round-off and the strain energy removed equal to the column's sum.
TEST(PressureSmoothing, KeepsTheVolumeIn1d3dAndAxisymmetric) {
  const std::array<std::array<double, 5>, 3> r = {
      one_average<1>("{origin: [0], extent: [1], cell_size: 0.1, boundary: {x_min: slip, x_max: slip}}",
                     "min: [0.2], max: [0.8]"),
      one_average<2>("{coordinates: axisymmetric, extent: [1, 1], cell_size: 0.1}", "min: [0, 0.2], max: [0.6, 0.8]"),
      one_average<3>("{origin: [0, 0, 0], extent: [1, 1, 1], cell_size: 0.1}",
                     "min: [0.2, 0.2, 0.2], max: [0.6, 0.6, 0.6]")};
  for (std::size_t k = 0; k < r.size(); ++k) {
    std::printf("[ measured ] case %zu: sum m J %.15g -> %.15g, strain energy %.6g, of which removed %.6g\n", k,
                r[k][0], r[k][1], r[k][2], r[k][4]);
    EXPECT_NEAR(r[k][1], r[k][0], 1e-12 * r[k][0]) << k;
    EXPECT_NEAR(r[k][3], r[k][2], 1e-6 * r[k][2]) << k;
    EXPECT_GT(r[k][4], 0.5 * r[k][2]) << k;
  }
}

/// The review's dam break (examples/12_dam_break: 6 m tank, free-slip walls, water 4 x 2 m, K = 4.5e6 Pa) at `cells`
/// across the tank, 2 particles per cell per axis, MUSL, pure FLIP with hats (every default), dt = 0.1 h / sqrt(K/rho).
/// `x` with 17 significant digits (a cell size that divides the tank exactly).
std::string exact(double x) {
  std::ostringstream s;
  s.precision(17);
  s << x;
  return s.str();
}

std::string dam_break(int cells, int smoothing, const std::string& end) {
  const double h = 6.0 / cells;
  return test::fill(
      R"yaml(dimension: 2
grid: {origin: [0, 0], extent: [6, 6], cell_size: @H@, boundary: {x_min: slip, x_max: slip, y_min: slip, y_max: slip}}
materials:
  water: {model: newtonian_fluid, density: 1000, bulk_modulus: 4.5e6, viscosity: 1.0e-3, pressure_smoothing: @S@}
bodies:
  - {name: water, material: water, shape: {type: box, min: [0, 0], max: [4, 2]}, particles_per_cell: 2}
solver: {scheme: musl, dt: @DT@, gravity: [0, -9.81], end_time: @END@}
)yaml",
      {{"H", exact(h)}, {"S", std::to_string(smoothing)}, {"DT", exact(0.1 * h / std::sqrt(4.5e3))}, {"END", end}});
}

struct DamBreakBooks {
  double largest_rise = 0;  ///< max over steps of (E - E0) / E0
  double final_change = 0;  ///< (E(end) - E0) / E0
  double densest = 0;       ///< max over steps of rho/rho0 - 1
};
DamBreakBooks run_dam_break(int cells, int smoothing, const std::string& end) {
  auto sim = test::simulation_from_yaml<2>(dam_break(cells, smoothing, end), "dam_break.yaml");
  const double e0 = sim->energy().total();
  DamBreakBooks r;
  sim->run([&](const Simulation<2>& s) {
    r.largest_rise = std::max(r.largest_rise, (s.energy().total() - e0) / std::abs(e0));
    for (const auto& b : s.bodies())
      for (Index i = 0; i < b.particles.size(); ++i)
        r.densest = std::max(r.densest, 1 / Mat<2>(b.particles.F[i]).determinant() - 1);
  });
  r.final_change = (sim->energy().total() - e0) / std::abs(e0);
  return r;
}

// The review's dam break in its closed tank to 1 s (the wall impact at 0.45-0.6 s and the run-up), every default but
// the smoothing. Measured (an energy history every step of `mpm run`; physics/fluids/README.md, "Pressure
// smoothing"): each particle's J: largest rise +0.99% of E0 (35 cells) and +0.78% (70), the density warning (35
// cells here: the densest particle 5.92% above rho0 over all steps); the node-averaged J: never above E0 at either
// resolution, -7.44% / -9.75% at 1 s, no warning (densest +1.67% at 35 cells). Asserted at 35 cells (6 s): the rise
// above and below the issue's 0.5%, the density within the 3% of weak compressibility with the average only, and the
// average's loss within 9%.
TEST(PressureSmoothing, DamBreakInAClosedTankGainsNoEnergy) {
  const DamBreakBooks own = run_dam_break(35, 0, "1.0"), averaged = run_dam_break(35, 1, "1.0");
  std::printf(
      "[ measured ] dam break, 35 cells, to 1 s: own J: largest rise %+.3f%%, final %+.3f%%, densest %+.2f%%; "
      "node-averaged J: largest rise %+.3f%%, final %+.3f%%, densest %+.2f%%\n",
      100 * own.largest_rise, 100 * own.final_change, 100 * own.densest, 100 * averaged.largest_rise,
      100 * averaged.final_change, 100 * averaged.densest);
  EXPECT_GT(own.largest_rise, 0.005);
  EXPECT_LT(averaged.largest_rise, 0.005);
  EXPECT_GT(own.densest, 0.03);
  EXPECT_LT(averaged.densest, 0.03);
  EXPECT_GT(averaged.final_change, -0.09);
}

/// RMS over the particles of p_p - rho0 g (H - y_p), over rho0 g H: a water column H = 1 m high and 0.5 m wide in a
/// closed tank (K = 2.8e5 Pa: sound speed 44 m/s), 20 cells over H, FLIP with hats, brought to rest by the local
/// damping 0.05 over 1.5 s (about 16 acoustic periods 4H/c).
double hydrostatic_error(int smoothing) {
  auto sim = test::simulation_from_yaml<2>(test::fill(R"yaml(dimension: 2
grid: {origin: [0, 0], extent: [0.5, 1.2], cell_size: 0.05, boundary: {x_min: slip, x_max: slip, y_min: slip, y_max: slip}}
materials:
  water: {model: newtonian_fluid, density: 1000, bulk_modulus: 2.8e5, viscosity: 1.0e-3, pressure_smoothing: @S@}
bodies:
  - {name: water, material: water, shape: {type: box, min: [0, 0], max: [0.5, 1.0]}, particles_per_cell: 2}
solver: {scheme: musl, cfl: 0.5, damping: 0.05, gravity: [0, -9.81], end_time: 1.5}
)yaml",
                                                      {{"S", std::to_string(smoothing)}}),
                                           "column.yaml");
  sim->run();
  const double rho_g = 1000 * 9.81;
  double sum = 0;
  Index n = 0;
  for (const auto& b : sim->bodies())
    for (Index i = 0; i < b.particles.size(); ++i, ++n) {
      const auto& c = b.particles.stress[i].c;
      const double p = -(c[0] + c[1] + c[2]) / 3, e = (p - rho_g * (1.0 - b.particles.x[i][1])) / rho_g;
      sum += e * e;
    }
  return std::sqrt(sum / static_cast<double>(n));
}

// The price of averaging J itself: a column at rest is not a fixed point of the average (eq. PS.1 is a diffusion of
// J; at the floor and the free surface the hats see particles on one side only), so every step moves volume between
// the layers and the pressure no longer balances the weight. Measured (`mpm run`, the same scene, last frame): RMS of
// p - rho0 g (H - y) 2.06% of rho0 g H with each particle's J, 13.5% with the average (largest 4.6% / 27.9%).
// Averaging the step's change of J instead (J0 + average of J - J0, tried in this session, not kept) kept a state at
// rest in principle but was unstable: RMS 59% on the column, and the 35-cell dam break blew up at 0.785 s.
TEST(PressureSmoothing, HydrostaticColumnPaysForTheAverage) {
  const double own = hydrostatic_error(0), averaged = hydrostatic_error(1);
  std::printf(
      "[ measured ] hydrostatic column, 20 cells over H: RMS pressure error %.4f (own J), %.4f (averaged J) "
      "of rho0 g H\n",
      own, averaged);
  EXPECT_LT(own, 0.03);
  EXPECT_GT(averaged, 0.10);
  EXPECT_LT(averaged, 0.17);
}

}  // namespace
}  // namespace mpm
