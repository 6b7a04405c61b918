// Fluids module (review §5.4): the Sod shock tube (§6.1.4) against the exact Riemann solution; the exact
// solver against Toro's published star state; the Tait fluid's hydrostatic column and its equation of
// state; the gas energy audit (kinetic + internal energy conserved).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <sstream>
#include <string>

#include "../libmpm/scene_fixture.hpp"
#include "dam_break.hpp"
#include "mpm/app/run_scene.hpp"
#include "mpm/fluids/tait_fluid.hpp"
#include "mpm/grid/tile_binning.hpp"
#include "mpm/materials/material_batch.hpp"
#include "mpm/scene/scene_error.hpp"
#include "sod.hpp"
#include "sod_exact.hpp"

namespace mpm {
namespace {

// Toro, Table 4.2 / 4.3, test 1 (Sod): p* = 0.30313, u* = 0.92745.
TEST(ExactRiemann, SodStarState) {
  const test::ExactRiemann r({1, 0, 1}, {0.125, 0, 0.1}, 1.4);
  EXPECT_NEAR(r.p_star(), 0.30313, 1e-5);
  EXPECT_NEAR(r.u_star(), 0.92745, 1e-5);
  // Toro test 3 (strong left shock / right rarefaction): p* = 460.894, u* = 19.5975.
  const test::ExactRiemann s({1, 0, 1000}, {1, 0, 0.01}, 1.4);
  EXPECT_NEAR(s.p_star(), 460.894, 1e-3);
  EXPECT_NEAR(s.u_star(), 19.5975, 1e-4);
}

verification::SodResult sod(int cells, const std::string& shape, double c1, double c2, double end_time = 0.143) {
  verification::SodSpec s;
  s.cells = cells;
  s.shape_function = shape;
  s.viscosity_linear = c1;
  s.viscosity_quadratic = c2;
  s.end_time = end_time;
  const verification::SodResult r = verification::run_sod(s);
  std::printf(
      "[ measured ] Sod t = %.3f, %s, %d cells, c1 = %.1f, c2 = %.1f: L1 particles rho %.4f u %.4f p %.4f, grid "
      "rho %.4f u %.4f p %.4f; sum V %.4f, energy change %.2e (%lld steps)\n",
      end_time, shape.c_str(), cells, c1, c2, r.particles.density, r.particles.velocity, r.particles.pressure,
      r.grid.density, r.grid.velocity, r.grid.pressure, r.volume_sum, r.energy_change, r.steps);
  EXPECT_TRUE(r.failure.empty()) << r.failure;
  EXPECT_LT(r.energy_change, 0);  // the transfers dissipate; nothing is created
  EXPECT_GT(r.energy_change, -1e-2);
  return r;
}

void expect_decrease(const verification::SodErrors& coarse, const verification::SodErrors& fine, double factor) {
  EXPECT_LT(fine.density, factor * coarse.density);
  EXPECT_LT(fine.velocity, factor * coarse.velocity);
  EXPECT_LT(fine.pressure, factor * coarse.pressure);
}

// Sod (review §6.1.4): 1D tube [0, 1], fixed ends, 3 PPC, MUSL with pure FLIP, CFL 0.2; L1 errors against
// the exact solution normalised by the jump of each quantity (sod.hpp), on the particles and on the grid.
// With cpGIMP the particle volumes follow the particle spacing and every error falls with refinement
// (measured, particles rho / u / p at t = 0.143, c1 = 1, c2 = 2: 100 cells 0.0129 / 0.0362 / 0.0167,
// 200: 0.0073 / 0.0216 / 0.0096, 400: 0.0044 / 0.0115 / 0.0059; observed order about 0.8).
// The grid values (review Fig. 68: nodal density m_I / h, mass-weighted velocity and pressure) are smoother;
// their density converges more slowly (0.0134 / 0.0092 / 0.0079 at t = 0.143: the hat mapping smears the
// contact over two cells and aliases the particle spacing). Asserted: the particle errors at least 25% smaller
// per halving of h, the grid errors at least 25% smaller from 100 to 400 cells, at both times.
TEST(Sod, ConvergesWithCpGimp) {
  for (double t : {0.143, 0.2}) {
    const auto r100 = sod(100, "cpgimp", 1, 2, t), r200 = sod(200, "cpgimp", 1, 2, t),
               r400 = sod(400, "cpgimp", 1, 2, t);
    expect_decrease(r100.particles, r200.particles, 0.75);
    expect_decrease(r200.particles, r400.particles, 0.75);
    expect_decrease(r100.grid, r400.grid, 0.75);
    EXPECT_LT(r400.particles.density, 0.006);
    EXPECT_LT(std::abs(r400.volume_sum - 1), 4e-3);  // the particle volumes tile the tube
  }
}

// Without artificial viscosity the post-shock particles ring (review Fig. 66): the errors are larger and fall
// more slowly (particles rho / u / p: 200 cells 0.0137 / 0.0481 / 0.0181, 400: 0.0107 / 0.0363 / 0.0142).
TEST(Sod, WithoutArtificialViscosity) {
  const auto r200 = sod(200, "cpgimp", 0, 0), r400 = sod(400, "cpgimp", 0, 0);
  expect_decrease(r200.particles, r400.particles, 0.85);
  EXPECT_LT(r400.grid.velocity, 0.85 * r200.grid.velocity);
  EXPECT_LT(r400.grid.pressure, 0.9 * r200.grid.pressure);
  EXPECT_LT(r400.particles.velocity, 0.04);
  EXPECT_LT(r400.particles.density, 0.012);
}

// With hat functions, the review's choice, the density does not converge: in the expanded gas (about one
// particle per cell at 3 PPC) each cell crossing adds a volume error, so det F drifts away from the
// particle spacing (sum of particle volumes 1.007 at 100 cells, 1.046 at 400 for a tube of length 1) and
// the left plateau ends at rho 0.33 instead of 0.426, although the particles themselves are spaced right
// (their spacing gives 0.4255). Measured (c1 = 1, c2 = 2), particles rho / u / p: 100 cells 0.0156 / 0.0423 /
// 0.0190, 200: 0.0176 / 0.0326 / 0.0184, 400: 0.0290 / 0.0275 / 0.0267. The velocity converges. Asserted
// as measured so that a change of the hat-function transfers shows: the drift, and the bounds.
TEST(Sod, HatFunctionsDriftInVolume) {
  const auto r100 = sod(100, "linear", 1, 2), r400 = sod(400, "linear", 1, 2);
  EXPECT_LT(r400.particles.velocity, 0.8 * r100.particles.velocity);
  EXPECT_GT(r400.volume_sum - 1, 0.02);  // the documented drift: worse with refinement
  EXPECT_LT(r100.volume_sum - 1, 0.015);
  EXPECT_LT(r400.particles.density, 0.035);
  EXPECT_LT(r400.particles.pressure, 0.035);
}

// Tait EOS and Newtonian stress at a material point (eqs 5.29-5.31).
TEST(TaitFluid, PressureAndViscousStress) {
  const fluids::TaitFluid::Params c{1000, 2.0e5, 7, 1.0e-3, 0};
  PointKinematics k;
  k.J = 0.99;
  k.F = Mat3::Identity() * std::cbrt(0.99);
  k.L = Mat3::Zero();
  k.L(0, 1) = 2;  // simple shear rate: D_01 = 1
  k.dt = 1e-4;
  const Mat3 s = fluids::TaitFluid::update_point(c, k, Mat3::Zero());
  const double p = 2.0e5 * (std::pow(0.99, -7) - 1);
  EXPECT_NEAR(-s.trace() / 3, p, 1e-9 * p);
  EXPECT_NEAR(s(0, 1), 2 * 1.0e-3 * 1, 1e-15);
  EXPECT_NEAR(fluids::TaitFluid::wave_speed(c, 1), std::sqrt(7 * 2.0e5 / 1000), 1e-12);
  // dW/dJ = -p (central difference of the stored energy).
  const double dJ = 1e-6;
  const double W1 = fluids::TaitFluid::energy_density(c, Mat3::Identity() * std::cbrt(0.99 + dJ), Mat3::Zero());
  const double W0 = fluids::TaitFluid::energy_density(c, Mat3::Identity() * std::cbrt(0.99 - dJ), Mat3::Zero());
  EXPECT_NEAR((W1 - W0) / (2 * dJ), -p, 1e-5 * p);
}

// cavitation_pressure p_c: p = max(K (J^-gamma - 1), p_c); the stored energy keeps dW/dJ = -p on both sides of J_c
// (where the Tait pressure reaches p_c) and is continuous there, so the energy audit stays exact; p_c = 0 stores
// nothing in expansion. Without p_c the law is the Tait one (checked above).
TEST(TaitFluid, CavitationPressureLimitsTheTension) {
  for (const double pc : {0.0, -5.0e4}) {
    fluids::TaitFluid::Params c{1000, 2.0e5, 7, 0, 0};
    c.cavitation_pressure = pc;
    const double Jc = fluids::TaitFluid::cavitation_volume_ratio(c);
    EXPECT_NEAR(2.0e5 * (std::pow(Jc, -7) - 1), pc, 1e-9 * 2.0e5);
    const auto W = [&](double J) {
      return fluids::TaitFluid::energy_density(c, Mat3::Identity() * std::cbrt(J), Mat3::Zero());
    };
    for (const double J : {0.99, 1.0005, Jc * 1.01, 1.3, 2.0}) {
      const double p = std::max(2.0e5 * (std::pow(J, -7) - 1), pc);
      EXPECT_NEAR(fluids::TaitFluid::pressure(c, J), p, 1e-9 * 2.0e5) << J;
      const double dJ = 1e-7;
      if (std::abs(J - Jc) > 10 * dJ) {
        EXPECT_NEAR((W(J + dJ) - W(J - dJ)) / (2 * dJ), -p, 1e-4 * 2.0e5) << J;
      }
    }
    EXPECT_NEAR(W(Jc * (1 - 1e-12)), W(Jc * (1 + 1e-12)), 1e-6);  // continuous at J_c (slope p_c: 1e-7 apart)
    if (pc == 0) {
      EXPECT_EQ(W(1.7), 0.0);  // no energy in expansion
    }
  }
}

// volumetric_deformation: the batch keeps only the volume of a fluid particle's F. A 2D particle sheared at
// L_01 = 100 1/s with a slight compression for 2e4 steps of 1e-4 s (shear strain 200): with the full F its entries
// grow to ~200 while det F follows the compression; with the option F stays J^(1/2) I with the same J to round-off,
// and the stress (which reads J alone) agrees.
TEST(TaitFluid, VolumetricDeformationKeepsOnlyTheVolume) {
  fluids::TaitFluid::Params c{1000, 2.0e5, 7, 1.0e-3, 0};
  Mat<2> L = Mat<2>::Zero();
  L(0, 1) = 100;
  L(0, 0) = L(1, 1) = -1e-3;
  const MatU<2> Lu = L;
  std::array<ParticleSet<2>, 2> p;
  for (int k = 0; k < 2; ++k) {
    c.volumetric_deformation = k == 1;
    MaterialBatch<2, fluids::TaitFluid> m(c);
    p[k].add(Vec<2>::Zero(), 1, 1);
    for (int s = 0; s < 20000; ++s) {
      p[k].F[0] = (Mat<2>::Identity() + 1e-4 * L) * Mat<2>(p[k].F[0]);
      m.update_stress(p[k], 0, 1, &Lu, 1e-4);
    }
  }
  const Mat<2> full = p[0].F[0], volumetric = p[1].F[0];
  EXPECT_GT(std::abs(full(0, 1)), 100);
  EXPECT_NEAR(volumetric(0, 1), 0, 0);
  EXPECT_NEAR(volumetric(0, 0), volumetric(1, 1), 0);
  EXPECT_NEAR(volumetric.determinant(), full.determinant(), 1e-9);
  EXPECT_NEAR(volumetric.determinant(), std::exp(-2 * 1e-3 * 2.0), 1e-6);  // det(I + dt L)^n ~ exp(tr L t)
  EXPECT_NEAR(p[1].stress[0].full()(0, 0), p[0].stress[0].full()(0, 0), 1e-6 * 2.0e5);
}

// With the full F (volumetric_deformation 0) a fluid particle keeps its distortion until its determinant would be
// round-off (eps ||F||^2 > 1e-8 J in 2D, ||F|| ~ 6.7e3 at J = 1): sheared at L_01 = 1e4 1/s for steps of 1e-4 s, its
// shear F_01 grows by 1 a step up to ~6.7e3, then F is reset to J^(1/2) I with the same J, and grows again; det F
// stays exact (the isochoric shear keeps J = 1) where the unbounded F of 1e8 would give a round-off determinant.
TEST(TaitFluid, FullDeformationIsResetBeforeItsDeterminantIsRoundOff) {
  fluids::TaitFluid::Params c{1000, 2.0e5, 7, 1.0e-3, 0};
  Mat<2> L = Mat<2>::Zero();
  L(0, 1) = 1e4;
  const MatU<2> Lu = L;
  ParticleSet<2> p;
  MaterialBatch<2, fluids::TaitFluid> m(c);
  p.add(Vec<2>::Zero(), 1, 1);
  Real largest = 0;
  int resets = 0;
  for (int s = 0; s < 20000; ++s) {
    p.F[0] = (Mat<2>::Identity() + 1e-4 * L) * Mat<2>(p.F[0]);
    const Real before = std::abs(p.F[0](0, 1));
    m.update_stress(p, 0, 1, &Lu, 1e-4);
    largest = std::max(largest, before);
    if (p.F[0](0, 1) == 0) {
      ++resets;
      EXPECT_GT(before, 6.0e3) << s;  // kept whole while det F is exact
      EXPECT_EQ(p.F[0](0, 0), p.F[0](1, 1));
    }
  }
  EXPECT_LT(largest, 7.1e3);
  EXPECT_EQ(resets, 2);  // at ~6.7e3 and ~1.34e4 steps
  EXPECT_NEAR(Mat<2>(p.F[0]).determinant(), 1, 1e-9);
  EXPECT_NEAR(p.stress[0].full()(0, 0), 0, 1e-6);  // J = 1: no pressure (and the viscous stress is deviatoric)
}

// volumetric_deformation is a switch: 0 or 1, anything else refused at its key.
TEST(NewtonianFluid, VolumetricDeformationIsZeroOrOne) {
  const std::string scene = R"(
dimension: 2
grid: {extent: [1, 1], cell_size: 0.1}
materials:
  water: {model: newtonian_fluid, density: 1000, bulk_modulus: 2.0e6, volumetric_deformation: 0.5}
bodies:
  - {name: water, material: water, shape: {type: box, min: [0, 0], max: [0.5, 0.5]}}
solver: {scheme: musl, shape_function: linear, cfl: 0.5, end_time: 0.01}
)";
  try {
    test::simulation_from_yaml<2>(scene, "half.yaml");
    FAIL() << "volumetric_deformation: 0.5 was accepted";
  } catch (const SceneError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("volumetric_deformation: must be 0 (the full F) or 1 (its volume only)"), std::string::npos)
        << what;
    EXPECT_EQ(e.where.line, 5) << what;
  }
}

// docs/errata.md #10 (§5.4.1): the Stokes condition is lambda_N = -2 mu / 3 (printed +2 mu / 3), so that the
// default bulk viscosity zeta = lambda_N + 2 mu / 3 is 0: a uniaxial strain rate D = diag(r, 0, 0) gives the
// deviatoric stress 2 mu dev(D) and no viscous mean stress (the printed lambda_N would add 4 mu r / 3 to it).
TEST(TaitFluid, StokesConditionLeavesNoViscousMeanStress) {
  const Real mu = 1.0e-3, r = 50;
  const fluids::TaitFluid::Params c{1000, 2.0e5, 7, mu, 0};
  PointKinematics k;
  k.J = 1;
  k.F = Mat3::Identity();
  k.L = Mat3::Zero();
  k.L(0, 0) = r;
  k.dt = 1e-4;
  const Mat3 s = fluids::TaitFluid::update_point(c, k, Mat3::Zero());
  EXPECT_NEAR(s.trace() / 3, 0, 1e-15);  // J = 1: no pressure, and no viscous mean stress
  EXPECT_NEAR(s(0, 0), 2 * mu * (2 * r / 3), 1e-15);
  EXPECT_NEAR(s(1, 1), 2 * mu * (-r / 3), 1e-15);
}

// Martin & Moyce (1952) dam break, n^2 = 2, a = 2.25 in (dam_break.hpp): free-slip tank, MUSL, hat functions,
// FLIP, 16 cells across the column, 2x2 particles per cell, Mach 0.05. The surge front Z = x/a at
// T = t sqrt(2g/a) = 1, 2, 3 against the experiment (tests/data/dam_break_martin_moyce.csv, interpolated).
// Measured: Z = 1.376 / 2.541 / 4.012 against 1.329 / 2.296 / 3.642, i.e. +3.6% / +10.7% / +10.2% (density within
// 2.5%); in the 12a tank of examples/12_dam_break at 32 cells
// +10.4% / +15.2% / +12.7% (cpGIMP at 16 cells: +7.3 / +13.4 / +12.1%). The inviscid, free-slip front leads the
// experiment, as inviscid simulations of this experiment generally do (the measured surge is slowed by the
// bed friction and the release of the gate, which the model has not got); a no-slip floor brings the coarse
// runs within 4% only by numerical drag, which vanishes with refinement (examples/12_dam_break/README.md).
// Asserted: the front is ahead of the experiment by less than 12% at this resolution, the water stays in the
// tank, and the density stays within the 3% tolerance of weak compressibility.
TEST(DamBreak, SurgeFrontAgainstMartinMoyce) {
  const auto data = verification::martin_moyce(std::string(MPM_SOURCE_DIR) + "/tests/data/dam_break_martin_moyce.csv");
  ASSERT_GE(data.T.size(), 10u);
  verification::DamBreakSpec spec;
  const auto r = verification::run_dam_break(spec);
  ASSERT_TRUE(r.failure.empty()) << r.failure;
  EXPECT_TRUE(r.inside_tank);
  EXPECT_LT(r.max_density_deviation, 0.03);
  for (double T : {1.0, 2.0, 3.0}) {
    const double z = r.front_at(T), z_exp = data.front_at(T);
    std::printf("[ measured ] dam break T = %.0f: Z = %.3f, experiment %.3f, deviation %+.1f%%\n", T, z, z_exp,
                100 * (z / z_exp - 1));
    EXPECT_GT(z / z_exp, 1.0) << "T = " << T;
    EXPECT_LT(z / z_exp, 1.12) << "T = " << T;
  }
  std::printf("[ measured ] dam break: %lld particles, %lld steps, max |rho/rho0 - 1| = %.2e\n", r.particles, r.steps,
              r.max_density_deviation);
}

// The explicit viscous bound dt <= h^2 / (2 Dim nu), nu = (4 mu / 3 + zeta) / rho0, joins the CFL bound:
// with a syrup-like viscosity it governs (CFL bound h / c = 0.02 / 14.1 = 1.4e-3 s, viscous 3.0e-5 s).
TEST(NewtonianFluid, ViscousTimeStepBound) {
  const std::string scene =
      "dimension: 2\n"
      "grid: {origin: [0, 0], extent: [1, 1], cell_size: 0.02}\n"
      "materials: {syrup: {model: newtonian_fluid, density: 1000, bulk_modulus: 2.0e5, eos_exponent: 7, viscosity: "
      "VISC}}\n"
      "bodies: [{name: drop, material: syrup, shape: {type: box, min: [0.2, 0.2], max: [0.4, 0.4]}}]\n"
      "solver: {cfl: 0.5, end_time: 0.01}\n";
  auto with = [&](const std::string& mu) {
    std::string text = scene;
    text.replace(text.find("VISC"), 4, mu);
    return test::simulation_from_yaml<2>(text, "viscous.yaml")->stable_time_step();
  };
  const double c = std::sqrt(7 * 2.0e5 / 1000.0);
  EXPECT_NEAR(with("0"), 0.02 / c, 1e-12);
  const double nu = 4.0 * 1000 / 3 / 1000;  // mu = 1000 Pa s
  EXPECT_NEAR(with("1000"), 0.02 * 0.02 / (2 * 2 * nu), 1e-12);
}

// A bulk modulus too small for the flow: the column compresses under its own weight by more than the
// density tolerance and the run warns once, naming the body and the key to change.
TEST(NewtonianFluid, WarnsWhenTheDensityDeviatesTooMuch) {
  app::register_modules();
  auto scene = parse_scene(
      "dimension: 2\n"
      "grid: {origin: [0, 0], extent: [0.4, 0.4], cell_size: 0.02, boundary: {x_min: slip, x_max: slip, y_min: "
      "slip}}\n"
      "materials: {water: {model: newtonian_fluid, density: 1000, bulk_modulus: 5.0e3, viscosity: 1.0e-3}}\n"
      "bodies: [{name: column, material: water, shape: {type: box, min: [0, 0], max: [0.4, 0.2]}}]\n"
      "solver: {cfl: 0.5, gravity: [0, -9.81], end_time: 0.3}\n"
      "output: {fields: []}\n",
      "soft.yaml");
  const auto dir = std::filesystem::temp_directory_path() / "mpm_test_fluid_warning";
  for (const auto& [bulk, warns] : {std::pair{"5.0e3", true}, std::pair{"2.0e6", false}}) {
    auto s = scene;
    s.materials.at("water").parameters["bulk_modulus"] = std::stod(bulk);
    app::RunOptions options;
    options.output_directory = dir;
    options.progress = false;
    std::ostringstream log;
    const auto summary = app::run_scene(s, options, log, log);
    EXPECT_EQ(summary.warnings.size(), warns ? 1u : 0u) << log.str();
    if (warns) {
      EXPECT_NE(log.str().find("warning: body column"), std::string::npos) << log.str();
      EXPECT_NE(log.str().find("raise bulk_modulus"), std::string::npos) << log.str();
    }
  }
  std::filesystem::remove_all(dir);
}

// APIC with hat functions on a weakly compressible fluid (docs/theory.md §2, velocity transfers).
// The review's water (K = 4.5e6 Pa, gamma = 7, rho0 = 1000) in its 6 m tank at dt = 0.1 h / sqrt(K/rho0); the
// reference is the energy audit: kinetic + Tait stored + gravity potential is conserved by the continuum
// (the walls are free-slip, the viscosity is that of water), and the density stays within weak
// compressibility. Before the fix both scenes below diverged (det F <= 0), for two causes isolated here.
std::string apic_water(int dim, const std::string& cell, const std::string& body, const std::string& scheme,
                       const std::string& dt, const std::string& end) {
  const bool two = dim == 2;
  return "dimension: " + std::to_string(dim) + "\ngrid: {origin: " + (two ? "[0, 0]" : "[0]") +
         ", extent: " + (two ? "[6, 6]" : "[6]") + ", cell_size: " + cell + ", boundary: {x_min: slip, x_max: slip" +
         (two ? ", y_min: slip, y_max: slip" : "") +
         "}}\n"
         "materials: {water: {model: newtonian_fluid, density: 1000, bulk_modulus: 4.5e6, eos_exponent: 7, "
         "viscosity: 1.0e-3}}\n"
         "bodies: [{name: water, material: water, shape: {type: box, " +
         body +
         "}, particles_per_cell: 2}]\n"
         "solver: {scheme: " +
         scheme + ", shape_function: linear, velocity_transfer: apic, dt: " + dt +
         ", gravity: " + (two ? "[0, -9.81]" : "[-9.81]") + ", end_time: " + end + "}\n";
}

template <int Dim>
double largest_density_deviation(const Simulation<Dim>& sim) {
  double worst = 0;
  for (const auto& b : sim.bodies())
    for (Index i = 0; i < b.particles.size(); ++i)
      worst = std::max(worst, std::abs(1 / Mat<Dim>(b.particles.F[i]).determinant() - 1));
  return worst;
}

// Cause 1, the re-map of MUSL: a 1D water column 2 m high settling under gravity (47 particles, 70 cells over
// 6 m). MUSL re-mapped the new v_p with the previous step's C_p, so the velocity gradient that drives the
// stress lagged by steps (a running average of past gradients): the column diverged at t = 0.091 s, USL
// (no re-map) kept it. With C_p taken from the same trial velocities as v_p it settles: measured energy change
// -1.8e-6 to 0.3 s (-1.2e-6 to 1 s), max |rho/rho0 - 1| = 9.4e-4 (hydrostatic 6.2e-4 at the floor, more in the
// overshoot of the released column).
TEST(ApicFluid, MuslColumnSettlesUnderGravity) {
  auto sim = test::simulation_from_yaml<1>(
      apic_water(1, "0.0857142857142857", "min: [0], max: [2]", "musl", "1.277e-4", "0.3"), "column.yaml");
  const double e0 = sim->energy().total();
  ASSERT_NO_THROW(sim->run());
  const double change = (sim->energy().total() - e0) / std::abs(e0), rho = largest_density_deviation(*sim);
  std::printf("[ measured ] APIC + hats, MUSL, 1D column to 0.3 s: energy change %+.2e, max |rho/rho0 - 1| %.2e\n",
              change, rho);
  EXPECT_LT(std::abs(change), 1e-4);
  EXPECT_LT(rho, 3e-3);
}

// Cause 2, nearly empty nodes: the review's dam break at half its resolution (35 x 35 cells, 1,081 particles),
// run past its old blow-up. For hats C_p = sum v_I (x) grad phi_I takes a nearly empty node's trial velocity
// dt f_I / m_I with the weight grad phi_I (PIC/FLIP weigh it by phi_I): with the re-map fixed but such nodes
// kept, MUSL still inverted a particle at 0.099 s (USF at 0.095 s); before either fix MUSL failed at 0.212 s.
// Measured with both fixes to 0.3 s: see the printed line; asserted: energy within the issue's 2% and the
// density within the 3% of weak compressibility (the wall impact comes later, at about 0.6 s).
TEST(ApicFluid, CoarseDamBreakRunsPastTheOldBlowUp) {
  for (const std::string scheme : {"musl", "usf"}) {
    auto sim = test::simulation_from_yaml<2>(
        apic_water(2, "0.171428571428571", "min: [0, 0], max: [4, 2]", scheme, "2.556e-4", "0.3"), "dam.yaml");
    const double e0 = sim->energy().total();
    ASSERT_NO_THROW(sim->run()) << scheme;
    const double change = (sim->energy().total() - e0) / std::abs(e0), rho = largest_density_deviation(*sim);
    std::printf(
        "[ measured ] APIC + hats, %s, coarse dam break to 0.3 s: energy change %+.2e, max |rho/rho0 - 1| "
        "%.2e\n",
        scheme.c_str(), change, rho);
    EXPECT_LT(std::abs(change), 0.02) << scheme;
    EXPECT_LT(rho, 0.03) << scheme;
  }
}

// APIC's energy loss on the review's dam break against the cell size (docs/theory.md §2, velocity transfers;
// physics/fluids/README.md, Limits). The continuum (inviscid to within mu = 1e-3 Pa s, free-slip walls, no breaking
// before the run-up falls back) conserves kinetic + Tait stored + gravity energy through the wall impact at
// 0.45-0.6 s; APIC loses energy there, and the loss falls with the cell: measured at 0.7 s -8.47% (35 cells across the
// tank), -2.92% (70, the example), -1.42% (140), -1.40% (280); the frames never rise above E0 (largest change
// +0.00%). Asserted on the two coarse grids (5 s): the loss at 35 cells is more than twice that at 70 cells, the
// 70-cell loss lies within 2-4%, and no step gains more than 1e-4 E0. (To 1.7 s the loss does not converge: -13.4%,
// -4.85%, -2.80%, -3.23%; the per-step transfer loss of the flow after the impact grows with the number of steps.)
TEST(ApicFluid, DamBreakImpactLossFallsWithTheCell) {
  double loss[2] = {0, 0};
  const char* cells[2] = {"0.171428571428571", "0.0857142857142857"};
  const char* dts[2] = {"2.554e-4", "1.277e-4"};
  for (int k = 0; k < 2; ++k) {
    auto sim = test::simulation_from_yaml<2>(apic_water(2, cells[k], "min: [0, 0], max: [4, 2]", "musl", dts[k], "0.7"),
                                             "dam.yaml");
    const double e0 = sim->energy().total();
    double largest = -1;
    ASSERT_NO_THROW(
        sim->run([&](const Simulation<2>& s) { largest = std::max(largest, s.energy().total() / e0 - 1); }));
    loss[k] = 1 - sim->energy().total() / e0;
    std::printf(
        "[ measured ] APIC + hats, MUSL, dam break with %s m cells to 0.7 s: energy change %+.3e, largest %+.1e\n",
        cells[k], -loss[k], largest);
    EXPECT_LT(largest, 1e-4) << cells[k];
  }
  EXPECT_GT(loss[0], 2 * loss[1]);
  EXPECT_GT(loss[1], 0.02);
  EXPECT_LT(loss[1], 0.04);
}

// Cause of the FSI example's loss with APIC (examples/14_fsi_obstacle/README.md): its no-slip floor. The review's dam
// break to 0.45 s (before the wall impact) with the floor `fixed` instead of `slip`: the floor nodes are set to zero
// velocity every step and the floor's rest reaches the water through the transfer, so the first cell of water is braked
// every step, a boundary layer a cell thick (water's own, sqrt(nu t), is 0.6 mm) whose loss does not fall with the cell
// (the finer grid takes more steps). Most of it travels with the affine momentum m_p C_p (x_I - x_p) of P2G, not with
// the PIC velocity of G2P: giving the particles FLIP's velocity and keeping C_p (trial code) still lost 1.66% at 70
// cells (physics/fluids/README.md, "Which half of the transfer loses it"). Measured energy change at 0.45 s: APIC
// -1.70% (35 cells) and -2.12% (70) against -1.08% and -0.32% with the slip floor; FLIP +0.01% with either floor (its
// particles keep their slip velocity). Asserted (4 s): APIC loses more than 1.5% at 70 cells, and not less than at 35;
// FLIP within 0.1%.
TEST(ApicFluid, NoSlipFloorDissipatesWithoutConverging) {
  auto fixed_floor = [](std::string scene, const std::string& transfer) {
    scene.replace(scene.find("y_min: slip"), 11, "y_min: fixed");
    scene.replace(scene.find("velocity_transfer: apic"), 23, transfer);
    return scene;
  };
  auto change = [&](const char* cell, const char* dt, const std::string& transfer) {
    auto sim = test::simulation_from_yaml<2>(
        fixed_floor(apic_water(2, cell, "min: [0, 0], max: [4, 2]", "musl", dt, "0.45"), transfer), "dam.yaml");
    const double e0 = sim->energy().total();
    sim->run();
    const double c = sim->energy().total() / e0 - 1;
    std::printf("[ measured ] %s, no-slip floor, %s m cells, to 0.45 s: energy change %+.3e\n", transfer.c_str(), cell,
                c);
    return c;
  };
  const double coarse = change("0.171428571428571", "2.554e-4", "velocity_transfer: apic");
  const double fine = change("0.0857142857142857", "1.277e-4", "velocity_transfer: apic");
  const double flip = change("0.0857142857142857", "1.277e-4", "flip_fraction: 1");
  EXPECT_LT(fine, -0.015);
  EXPECT_LE(fine, coarse);
  EXPECT_LT(std::abs(flip), 1e-3);
}

// PolyPIC (velocity_transfer: polypic; Fu et al. 2017; docs/theory.md §2, velocity transfers) on the review's dam break
// at half resolution (35 cells across the tank, 1,081 particles, MUSL, hats, dt = 0.1 h / c), to 1.7 s (7 s of CPU).
// The particles keep the bilinear velocity field of their cell, so the transfers lose nothing at nodes of full mass
// (tests/libmpm/test_polypic.cpp); what remains shrinks with h (70 cells: -1.75%, 140: -1.14%) and dt. Measured here:
// energy change -1.49% at 0.7 s (APIC -8.47%, ApicFluid.DamBreakImpactLossFallsWithTheCell), -5.61% at 1.7 s (APIC
// -13.4%), never above E0; largest |1/J - 1| of any particle at any step, spray included, 0.073. The splash makes
// the coarse run sensitive to the step's last digits (dt = 2.5555e-4 instead of 2.554e-4: -0.72% and -4.40%), so the
// bounds leave about a quarter of the loss as margin.
TEST(PolyPicFluid, CoarseDamBreakKeepsItsEnergy) {
  std::string scene = apic_water(2, "0.171428571428571", "min: [0, 0], max: [4, 2]", "musl", "2.554e-4", "1.7");
  scene.replace(scene.find("velocity_transfer: apic"), 23, "velocity_transfer: polypic");
  auto sim = test::simulation_from_yaml<2>(scene, "dam.yaml");
  const double e0 = sim->energy().total();
  double largest = -1, at_impact = 0, rho = 0;
  ASSERT_NO_THROW(sim->run([&](const Simulation<2>& s) {
    const double change = s.energy().total() / e0 - 1;
    largest = std::max(largest, change);
    if (s.time() <= 0.7) at_impact = change;
    rho = std::max(rho, largest_density_deviation(s));
  }));
  const double change = sim->energy().total() / e0 - 1;
  std::printf(
      "[ measured ] PolyPIC + hats, MUSL, coarse dam break: energy change %+.3e at 0.7 s, %+.3e at 1.7 s, largest "
      "%+.1e, max |rho/rho0 - 1| %.3f\n",
      at_impact, change, largest, rho);
  EXPECT_GT(at_impact, -0.02);
  EXPECT_GT(change, -0.07);
  EXPECT_LT(largest, 1e-4);
  EXPECT_LT(rho, 0.09);
}

/// The FSI example's water (K = 6.6e5 Pa, gamma = 7, no tension, F reduced to its volume) as one box of particles in a
/// square tank of side `side` with slip walls, MUSL with hats; `body` adds keys to the body (an initial velocity),
/// `solver` the transfer and the rest of the solver section.
std::string fsi_water_in_tank(const std::string& side, const std::string& cell, const std::string& box, int per_axis,
                              const std::string& body, const std::string& solver) {
  return "dimension: 2\ngrid: {origin: [0, 0], extent: [" + side + ", " + side + "], cell_size: " + cell +
         ", boundary: {x_min: slip, x_max: slip, y_min: slip, y_max: slip}}\n"
         "materials: {water: {model: newtonian_fluid, density: 1000, bulk_modulus: 6.6e5, eos_exponent: 7, "
         "viscosity: 1.0e-3, cavitation_pressure: 0, volumetric_deformation: 1}}\n"
         "bodies: [{name: water, material: water, shape: {type: box, " +
         box + "}, particles_per_cell: " + std::to_string(per_axis) + body +
         "}]\n"
         "solver: {scheme: musl, shape_function: linear, " +
         solver + "}\n";
}

// What the water alone in the FSI example's tank lost (examples/14_fsi_obstacle/README.md, fix 6): with
// hats, APIC and PolyPIC lose energy in the column's collapse and surge with 2 particles per cell per axis and little
// with 3; FLIP loses nothing with either. The particles carry more grid-scale noise with 2 per axis (FLIP: J's rms
// about its cell's mean twice as large; PolyPIC at the example's 40 cells: velocity noise 0.090 against 0.0136 m/s rms
// at 0.2 s), which FLIP keeps and the two affine transfers lose at every transfer; how the noise turns into the loss
// is not established (APIC's J is the least noisy, and it loses the most). The column of examples/14 (0.146 m x
// 0.292 m, K = 6.6e5 Pa, cavitation_pressure 0, volumetric_deformation 1) on a slip floor, 10 cells across it, to
// 0.25 s (before the surge reaches the far wall), MUSL, cfl 0.5. Measured: energy change PolyPIC -1.02% / -0.13%,
// APIC -2.33% / -0.74%, FLIP +0.019% / +0.027% at 2 / 3 per axis; FLIP's J noise (mean over frames from 0.05 s)
// 1.16e-2 / 5.9e-3.
std::string fsi_tank_water(const std::string& transfer, int per_axis) {
  return fsi_water_in_tank("0.584", "0.0146", "min: [0, 0], max: [0.146, 0.292]", per_axis, "",
                           transfer + ", cfl: 0.5, gravity: [0, -9.81], end_time: 0.25");
}

/// The grid-scale noise of J: the mass-weighted rms of J about the mass-weighted mean J of the particles in the same
/// cell (a smooth field varies by h |grad J| across a cell; a hydrostatic column by rho g h / (gamma K) = 3e-5 here,
/// and with cavitation_pressure 0 a particle expands beyond J = 1 at no cost).
double within_cell_volume_noise(const Simulation<2>& sim) {
  const ScatterCellOrder<2> place(sim.grid().geometry, 1);  // one place per cell
  const auto& p = sim.bodies().front().particles;
  const auto cell = [&](Index i) { return place.of(p.x[i]); };
  const auto volume_ratio = [&](Index i) { return Mat<2>(p.F[i]).determinant(); };
  std::map<Index, std::pair<double, double>> cells;  // sum of m J, sum of m
  for (Index i = 0; i < p.size(); ++i) {
    auto& [mj, m] = cells[cell(i)];
    mj += p.mass[i] * volume_ratio(i);
    m += p.mass[i];
  }
  double sum = 0, mass = 0;
  for (Index i = 0; i < p.size(); ++i) {
    const auto& [mj, m] = cells.at(cell(i));
    sum += p.mass[i] * std::pow(volume_ratio(i) - mj / m, 2);
    mass += p.mass[i];
  }
  return std::sqrt(sum / mass);
}

TEST(PolyPicFluid, SurgeLosesLittleWithThreeParticlesPerCellPerAxis) {
  std::map<std::string, double> change, noise;
  for (const std::string transfer : {"velocity_transfer: polypic", "velocity_transfer: apic", "flip_fraction: 1"})
    for (int per_axis : {2, 3}) {
      const std::string run = transfer + ", " + std::to_string(per_axis) + " per axis";
      auto sim = test::simulation_from_yaml<2>(fsi_tank_water(transfer, per_axis), "fsi_water.yaml");
      const double e0 = sim->energy().total();
      double sum = 0;
      int frames = 0;
      ASSERT_NO_THROW(sim->run([&](const Simulation<2>& s) {
        if (s.time() < 0.05) return;
        sum += within_cell_volume_noise(s);
        ++frames;
      }));
      change[run] = sim->energy().total() / e0 - 1;
      noise[run] = sum / frames;
      std::printf("[ measured ] %s: energy change %+.3e, J noise %.3e\n", run.c_str(), change[run], noise[run]);
    }
  EXPECT_LT(change["velocity_transfer: polypic, 2 per axis"], -0.006);
  EXPECT_GT(change["velocity_transfer: polypic, 3 per axis"], -0.003);
  EXPECT_LT(change["velocity_transfer: apic, 2 per axis"], -0.018);
  EXPECT_GT(change["velocity_transfer: apic, 3 per axis"], -0.010);
  EXPECT_NEAR(change["flip_fraction: 1, 2 per axis"], 0, 0.002);
  EXPECT_NEAR(change["flip_fraction: 1, 3 per axis"], 0, 0.002);
  EXPECT_GT(noise["flip_fraction: 1, 2 per axis"], 1.5 * noise["flip_fraction: 1, 3 per axis"]);
}

// A water slab striking a slip wall: the FSI example's loss after 0.33 s is thin sheets striking walls
// (examples/14_fsi_obstacle/README.md, "The spray of the far wall"); here the same event on a body of known thickness.
// A slab 0.02 x 0.1 m (the FSI example's water: K = 6.6e5 Pa, no tension, F reduced to its volume; 3 particles per cell
// per axis), 1 m/s towards the wall from 0.02 m away, no gravity: it reaches the wall's last cell at 0.02 s and
// rebounds (mean v_x -0.5 m/s, the rest goes along the wall). At V/c = 0.04 the inviscid continuum keeps its energy.
// Measured at 0.04 s (before the sheets thrown along the wall strike the floor and ceiling, from 0.045 s), with 4 / 8
// / 16 cells across the slab: APIC -8.92% / -4.79% / -2.54% (first order), PolyPIC -1.33% / -0.98% / -0.67%, FLIP
// +0.84% / +0.41% / +0.15%. The loss of a strike falls with the cells across the striking body, so a flow whose
// sheets thin as the grid is refined keeps losing. Asserted on 4 and 8 cells (3 s).
TEST(FluidWallStrike, LossFallsWithTheCellsAcrossTheSlab) {
  const auto slab = [](const std::string& transfer, const std::string& cell) {
    return fsi_water_in_tank("0.3", cell, "min: [0.26, 0.1], max: [0.28, 0.2]", 3, ", velocity: [1, 0]",
                             transfer + ", cfl: 0.5, end_time: 0.04");
  };
  std::map<std::string, double> change;
  for (const std::string transfer : {"velocity_transfer: apic", "velocity_transfer: polypic", "flip_fraction: 1"})
    for (const std::string cell : {"0.005", "0.0025"}) {
      auto sim = test::simulation_from_yaml<2>(slab(transfer, cell), "slab.yaml");
      const double e0 = sim->energy().total();
      ASSERT_NO_THROW(sim->run());
      change[transfer + ", " + cell] = sim->energy().total() / e0 - 1;
      std::printf("[ measured ] slab striking a wall, %s, %s m cells (%.0f across the slab): energy change %+.3e\n",
                  transfer.c_str(), cell.c_str(), 0.02 / std::stod(cell), change[transfer + ", " + cell]);
    }
  const auto ratio = [&](const std::string& transfer) {
    return change[transfer + ", 0.005"] / change[transfer + ", 0.0025"];
  };
  EXPECT_LT(change["velocity_transfer: apic, 0.0025"], -0.03);  // measured -0.0479
  EXPECT_GT(ratio("velocity_transfer: apic"), 1.6);             // measured 1.86
  EXPECT_LT(change["velocity_transfer: polypic, 0.0025"], 0);   // measured -0.0098
  EXPECT_GT(ratio("velocity_transfer: polypic"), 1.2);          // measured 1.36
  EXPECT_GT(change["flip_fraction: 1, 0.0025"], 0);             // measured +0.0041
  EXPECT_GT(ratio("flip_fraction: 1"), 1.5);                    // measured 2.06
}

// The spray's strikes (examples/14_fsi_obstacle/README.md, "The spray of the far wall"): the sheets a strike throws
// are a particle or two thick and partly broken into particles alone in their cells (in the FSI example at 40 cells
// they hold 31% of the fast spray's energy at 0.35 s, 45% at 0.37 s), and a lone water particle striking a slip wall
// (3 m/s, 5 mm cells, no gravity) keeps none of its kinetic energy with APIC or PolyPIC: it takes its nodes' velocity,
// whose normal part the wall node has lost and no stress gives back. Measured: energy at 0.02 s 0 (APIC, PolyPIC, below
// 1e-6 of E0); FLIP keeps its own velocity's increments and rebounds at -3.15 m/s, +10.6% (a real droplet of that size
// does not bounce much either; the continuum of the scene is not resolved at this scale).
TEST(FluidWallStrike, LoneParticleKeepsNoneOfItsEnergyWithApicOrPolyPic) {
  const auto drop = [](const std::string& transfer) {
    return fsi_water_in_tank("0.1", "0.005", "min: [0.0801, 0.0501], max: [0.0849, 0.0549]", 1, ", velocity: [3, 0]",
                             transfer + ", cfl: 0.5, end_time: 0.02");
  };
  std::map<std::string, double> kept, vx;
  for (const std::string transfer : {"velocity_transfer: apic", "velocity_transfer: polypic", "flip_fraction: 1"}) {
    auto sim = test::simulation_from_yaml<2>(drop(transfer), "drop.yaml");
    ASSERT_EQ(sim->bodies().front().particles.size(), 1u);
    const double e0 = sim->energy().total();
    ASSERT_NO_THROW(sim->run());
    kept[transfer] = sim->energy().total() / e0;
    vx[transfer] = sim->bodies().front().particles.v[0][0];
    std::printf("[ measured ] lone water particle striking a slip wall at 3 m/s, %s: energy kept %.3e, v_x %+.3f m/s\n",
                transfer.c_str(), kept[transfer], vx[transfer]);
  }
  EXPECT_LT(kept["velocity_transfer: apic"], 1e-3);
  EXPECT_LT(kept["velocity_transfer: polypic"], 1e-3);
  EXPECT_GT(kept["flip_fraction: 1"], 0.99);  // measured 1.106
  EXPECT_LT(vx["flip_fraction: 1"], -2.9);    // measured -3.15 m/s
}

}  // namespace
}  // namespace mpm
