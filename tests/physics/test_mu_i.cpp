// mu_i (physics/soils/mu_i.hpp, docs/theory.md §18, eqs. 18.20-18.24): the mu(I) rheology of Jop, Forterre &
// Pouliquen (2006) at one material point, driven by the material-test driver's library function, against its
// closed form:
//  - steady shear at a given pressure P and shear rate gamma_dot: sqrt(J2) = mu(I) P with
//    mu(I) = mu_s + (mu_2 - mu_s) / (I_0 / I + 1), I = gamma_dot d / sqrt(P / rho_s), to 1e-10, over I from 1e-3 to
//    3 and P from 1 kPa to 100 kPa (the rate of deformation of a simple shear without its spin, eq. 18.24, so that
//    the steady state has D_p = D exactly); the driver's own simple_shear path (with the spin) within the
//    corotational term's (mu P / G)^2;
//  - the rate-independent limit I -> 0: mu_s;
//  - no tension: a point pulled apart (from rest or from flow) has zero stress exactly, and no plastic work; open
//    grains carry nothing until compressed back to the density at which they opened;
//  - objectivity: a point at rest spun rigidly keeps its principal stresses and does not flow; the driver's check
//    (the path with a rigid rotation superposed);
//  - in a run: a column of glass beads collapsing under gravity stays admissible (P >= 0, sqrt(J2) <= mu_2 P), its
//    energy audit closes, and a restart from its saved state ends with the same bits.
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
#include "mpm/soils/mu_i.hpp"
#include "mpm/soils/soil_batch.hpp"
#include "soil_restart.hpp"

namespace mpm::soils {
namespace {

using app::LoadPath;
using app::MaterialTestOptions;
using app::MaterialTestResult;

/// Glass beads of Jop, Forterre & Pouliquen (2006): mu_s = tan 20.9 deg, mu_2 = tan 32.76 deg, I_0 = 0.279,
/// d = 0.5 mm, rho_s = 2450 kg/m^3; a packing of solid fraction 0.6, E = 100 MPa, nu = 0.3.
SoilParams glass_beads() {
  SoilParams s;
  s.density = 0.6 * 2450;
  const Real E = 100e6, nu = 0.3;
  s.shear_modulus = E / (2 * (1 + nu));
  s.bulk_modulus = E / (3 * (1 - 2 * nu));
  s.granular = {.mu_s = 0.38, .mu_2 = 0.64, .I_0 = 0.279, .grain_diameter = 0.5e-3, .grain_density = 2450};
  return s;
}

/// The closed form mu(I) = mu_s + (mu_2 - mu_s) / (I_0 / I + 1) (eq. 18.20), written as in the paper.
Real mu_of(const GranularRheology& r, Real I) { return r.mu_s + (r.mu_2 - r.mu_s) / (r.I_0 / I + 1); }

/// sqrt(J2) of a stress, Pa.
Real shear_stress(const Mat3& sigma) {
  const Mat3 s = sigma - sigma.trace() / 3 * Mat3::Identity();
  return std::sqrt(0.5 * s.squaredNorm());
}

/// A deformation path: an isotropic compression to the pressure `pressure` (10 steps), then the rate of deformation
/// of a simple shear at `rate` without its spin, D = rate/2 (e_x e_y + e_y e_x), for `steps` steps of shear strain
/// 2e-4 each: F = lambda exp(D t), lambda^3 = exp(-P / K) (eq. 18.24).
MaterialTestResult steady_shear(SoilBatch<3, MuI>& material, Real pressure, Real rate, int steps) {
  const SoilParams& s = material.params();
  MaterialTestOptions o;
  o.path = LoadPath::deformation_csv;
  const Real dt = 2e-4 / rate;
  const Real lambda = std::exp(-pressure / s.bulk_modulus / 3);
  Real t = 0;
  for (int k = 1; k <= 10; ++k) {
    t += dt;
    o.samples.push_back({t, Mat3::Identity() * std::pow(lambda, k / 10.0)});
  }
  for (int k = 1; k <= steps; ++k) {
    t += dt;
    const Real half = 0.5 * rate * dt * k;  // exp of the off-diagonal D t: cosh and sinh of rate t / 2
    Mat3 F = Mat3::Identity();
    F(0, 0) = F(1, 1) = std::cosh(half);
    F(0, 1) = F(1, 0) = std::sinh(half);
    o.samples.push_back({t, lambda * F});
  }
  return app::run_material_test(material, o);
}

TEST(MuI, SteadyShearStressIsMuOfITimesPressure) {
  SoilBatch<3, MuI> material(glass_beads());
  const GranularRheology& r = material.params().granular;
  Real worst = 0;
  for (const Real pressure : {1e3, 1e4, 1e5})
    for (const Real I : {1e-3, 0.05, 0.279, 1.0, 3.0}) {
      const Real rate = I * std::sqrt(pressure / r.grain_density) / r.grain_diameter;
      const MaterialTestResult result = steady_shear(material, pressure, rate, 600);
      const Mat3 sigma = result.rows.back().stress;
      const Real P = result.rows.back().mean_pressure;  // the compression's, to round-off
      const Real expected = mu_of(r, r.inertial_number(rate, P)) * P;
      // D = rate/2 (e_x e_y + e_y e_x): the deviator is s_xy alone, s_xy = sqrt(J2)
      const Real error = std::abs(sigma(0, 1) - expected) / expected;
      const Real normal = std::abs(sigma(0, 0) - sigma(1, 1)) / expected;
      std::printf("[ measured ] steady shear P = %g kPa, I = %g: tau / P = %.12f, mu(I) = %.12f, error %.2e\n", P / 1e3,
                  I, sigma(0, 1) / P, expected / P, error);
      EXPECT_LT(error, 1e-10) << "P " << pressure << " I " << I;
      EXPECT_LT(normal, 1e-10);
      // the shear keeps the volume: P moves by K times the round-off of 600 unimodular increments only
      EXPECT_LT(std::abs(P - pressure), 1e-4);
      EXPECT_GT(result.rows.back().model_fields.at(0), 0.05);  // plastic_strain: it flowed
      worst = std::max(worst, error);
    }
  std::printf("[ measured ] steady shear: largest relative error of tau against mu(I) P %.2e\n", worst);
}

// The driver's simple_shear path (F = I + gamma e_x e_y, the normal stress held): the spin turns the stress, which
// tilts the deviator off D by about tau / G; the shear stress is mu(I) P to the square of that.
TEST(MuI, SimpleShearPathWithSpin) {
  SoilBatch<3, MuI> material(glass_beads());
  const GranularRheology& r = material.params().granular;
  for (const Real pressure : {1e3, 1e5}) {
    const Real I = 0.1;
    const Real rate = I * std::sqrt(pressure / r.grain_density) / r.grain_diameter;
    MaterialTestOptions o;
    o.path = LoadPath::simple_shear;
    o.confining_pressure = pressure;
    o.strain = 0.2;
    o.steps = 1000;
    o.duration = o.strain / rate;
    const MaterialTestResult result = app::run_material_test(material, o);
    const Mat3 sigma = result.rows.back().stress;
    const Real P = result.rows.back().mean_pressure;
    const Real expected = mu_of(r, r.inertial_number(rate, P)) * P;
    const Real error = std::abs(shear_stress(sigma) - expected) / expected;
    const Real tilt = expected / material.params().shear_modulus;
    std::printf(
        "[ measured ] simple_shear path P = %g kPa, I = %g: sqrt(J2) / P = %.10f, mu(I) = %.10f, error %.2e "
        "(tau/G = %.2e)\n",
        P / 1e3, I, shear_stress(sigma) / P, expected / P, error, tilt);
    EXPECT_LT(error, 10 * tilt * tilt + 1e-12);
  }
}

// I -> 0: the rate-independent limit. At I = 1e-12 and 1e-9 the shear stress is mu_s P to the rate's share,
// (mu_2 - mu_s) I / I_0 (below 1e-9).
TEST(MuI, SlowShearGivesTheStaticFriction) {
  SoilBatch<3, MuI> material(glass_beads());
  const GranularRheology& r = material.params().granular;
  const Real pressure = 1e4;
  for (const Real I : {1e-12, 1e-9}) {
    const Real rate = I * std::sqrt(pressure / r.grain_density) / r.grain_diameter;
    const MaterialTestResult result = steady_shear(material, pressure, rate, 100);
    const Real ratio = result.rows.back().stress(0, 1) / result.rows.back().mean_pressure;
    const Real error = std::abs(ratio - r.mu_s) / r.mu_s;
    std::printf("[ measured ] slow shear I = %g: tau / P = %.15f, |tau / P - mu_s| / mu_s = %.2e\n", I, ratio, error);
    EXPECT_LT(error, 2 * (r.mu_2 - r.mu_s) * I / r.I_0 / r.mu_s + 1e-13);
  }
}

// No tension: pulled apart from rest, and from steady flow, the point has zero stress at every step of the
// extension exactly, and the plastic work does not change (the stress that does it is zero).
TEST(MuI, TensionGivesZeroStress) {
  SoilBatch<3, MuI> material(glass_beads());
  MaterialTestOptions o;
  o.path = LoadPath::deformation_csv;
  for (int k = 1; k <= 10; ++k) {
    Mat3 F = Mat3::Identity() * (1 + 1e-3 * k);
    F(0, 1) = 5e-4 * k;  // and a shear: the open state has no deviator either
    o.samples.push_back({0.01 * k, F});
  }
  const MaterialTestResult from_rest = app::run_material_test(material, o);
  for (std::size_t k = 1; k < from_rest.rows.size(); ++k) EXPECT_EQ(from_rest.rows[k].stress, Mat3::Zero()) << k;

  // compressed to 10 kPa and sheared at I = 0.1, then pulled apart isotropically
  const GranularRheology& r = material.params().granular;
  const Real rate = 0.1 * std::sqrt(1e4 / r.grain_density) / r.grain_diameter;
  const MaterialTestResult flowing = steady_shear(material, 1e4, rate, 100);
  MaterialTestOptions pull;
  pull.path = LoadPath::deformation_csv;
  const Mat3 F0 = flowing.rows.back().F;
  const Real t0 = flowing.rows.back().time;
  // replay the flowing path, then stretch isotropically by 0.1% a step
  for (std::size_t k = 1; k < flowing.rows.size(); ++k)
    pull.samples.push_back({flowing.rows[k].time, flowing.rows[k].F});
  for (int k = 1; k <= 20; ++k) pull.samples.push_back({t0 + 1e-4 * k, std::pow(1 + 1e-3, k) * F0});
  const MaterialTestResult pulled = app::run_material_test(material, pull);
  const std::size_t start = flowing.rows.size();
  ASSERT_EQ(pulled.rows.size(), start + 20);
  ASSERT_GT(pulled.rows[start - 1].mean_pressure, 9e3);  // still at 10 kPa before the pull
  std::size_t first_open = 0;
  for (std::size_t k = start; k < pulled.rows.size(); ++k)
    if (pulled.rows[k].stress == Mat3::Zero()) {
      first_open = k;
      break;
    }
  ASSERT_NE(first_open, 0u) << "never opened";
  for (std::size_t k = first_open; k < pulled.rows.size(); ++k) EXPECT_EQ(pulled.rows[k].stress, Mat3::Zero()) << k;
  // P = 1e4 Pa needs a volume strain P / K = 1.2e-4 to relax: the first step (3e-3) opens it
  EXPECT_EQ(first_open, start);
  std::printf("[ measured ] tension: zero stress at every step of the pull from rest and from flow at 10 kPa\n");
}

// The open state remembers how far the grains are apart (Dunatunga & Kamrin's rho < rho_c, eq. 18.23): a point
// stretched isotropically by a volume strain of 3e-3 from zero stress stays stress-free while it is compressed back by
// 2e-3, and carries P = K (ln J) only once it is denser than where it opened; the plastic volume strain is the
// opening itself.
TEST(MuI, OpenGrainsCarryNothingUntilTheyCloseAgain) {
  SoilBatch<3, MuI> material(glass_beads());
  const Real K = material.params().bulk_modulus;
  MaterialTestOptions o;
  o.path = LoadPath::deformation_csv;
  const std::vector<Real> volume_strains = {1e-3, 2e-3, 3e-3, 2e-3, 1e-3, 0.5e-3, -0.5e-3, -1e-3};
  for (std::size_t k = 0; k < volume_strains.size(); ++k)
    o.samples.push_back({0.01 * Real(k + 1), Mat3::Identity() * std::exp(volume_strains[k] / 3)});
  const MaterialTestResult r = app::run_material_test(material, o);
  Real worst = 0;
  for (std::size_t k = 0; k < volume_strains.size(); ++k) {
    const auto& row = r.rows[k + 1];
    const Real opening = row.model_fields.at(1);  // plastic_volumetric_strain
    const Real expected_opening = std::max(volume_strains[k], 0.0);
    const Real expected_pressure = K * std::max(-volume_strains[k], 0.0);
    EXPECT_NEAR(opening, expected_opening, 1e-15) << k;
    EXPECT_NEAR(row.mean_pressure, expected_pressure, 1e-9 * K * 1e-3) << k;
    if (volume_strains[k] >= 0) {
      EXPECT_EQ(row.stress, Mat3::Zero()) << k;
    }
    worst = std::max(worst, std::abs(row.mean_pressure - expected_pressure) / (K * 1e-3));
  }
  std::printf(
      "[ measured ] open grains: pressure K max(-ln J, 0) to %.2e of K 1e-3, the opening as plastic volume "
      "strain\n",
      worst);
}

// A point at rest (p = 10 kPa, sqrt(J2) at 90% of mu_s P) spun rigidly by 4 turns in 400 steps about an oblique
// axis: the Hughes-Winget rotation is orthogonal, the principal stresses stay to round-off and nothing flows.
TEST(MuI, RigidRotationKeepsThePrincipalStressesAtRest) {
  const SoilParams s = glass_beads();
  SoilBatch<3, MuI> material(s);
  const Real P = 1e4, tau = 0.9 * s.granular.mu_s * P;
  Mat3 sigma = -P * Mat3::Identity();
  sigma(0, 0) += -2 * tau / std::sqrt(3.0);
  sigma(1, 1) += tau / std::sqrt(3.0);
  sigma(2, 2) += tau / std::sqrt(3.0);
  const Eigen::Vector3d before = Eigen::SelfAdjointEigenSolver<Mat3>(sigma).eigenvalues();
  Mat3 spin = Mat3::Zero();
  const Real omega = 2 * std::numbers::pi * 4, dt = 1.0 / 400;
  spin(0, 1) = -omega;
  spin(1, 0) = omega;
  spin(1, 2) = -0.5 * omega;
  spin(2, 1) = 0.5 * omega;
  SoilState state;
  for (int k = 0; k < 400; ++k) sigma = material.update_point(spin, dt, 1, sigma, state);
  const Eigen::Vector3d after = Eigen::SelfAdjointEigenSolver<Mat3>(sigma).eigenvalues();
  const Real error = (after - before).cwiseAbs().maxCoeff() / P;
  std::printf("[ measured ] mu_i, 400 spin steps at rest: principal stresses kept to %.2e of P\n", error);
  EXPECT_LT(error, 1e-12);
  EXPECT_EQ(state.plastic_strain, 0);
  EXPECT_EQ(state.plastic_work, 0);
}

// The driver's objectivity check on a flowing path: the simple_shear path at 10 kPa, I = 0.1, replayed with a quarter
// turn superposed: the principal stresses agree to the discrete logarithm's share (the --check bound is 1e-4).
TEST(MuI, ObjectiveUnderSuperposedRotation) {
  SoilBatch<3, MuI> material(glass_beads());
  const GranularRheology& r = material.params().granular;
  MaterialTestOptions o;
  o.path = LoadPath::simple_shear;
  o.confining_pressure = 1e4;
  o.strain = 0.2;
  o.steps = 400;
  o.duration = o.strain / (0.1 * std::sqrt(1e4 / r.grain_density) / r.grain_diameter);
  const MaterialTestResult path = app::run_material_test(material, o);
  const app::ObjectivityCheck check = app::check_objectivity(material, path);
  std::printf(
      "[ measured ] mu_i objectivity: principal stresses with and without the rotation differ by %.2e of the "
      "largest stress (t = %g s)\n",
      check.difference, check.time);
  EXPECT_LT(check.difference, 1e-5);
}

// Glass beads (the paper's constants, E = 5 MPa) as a 0.1 m square column collapsing under gravity on a fixed floor
// and wall, 2D MUSL, 0.2 s.
std::string bead_column() {
  return R"(
dimension: 2
grid: {origin: [0, 0], extent: [0.4, 0.15], cell_size: 0.01, boundary: {x_min: fixed, y_min: fixed}}
materials:
  beads: {model: mu_i, density: 1470, youngs_modulus: 5.0e6, poisson_ratio: 0.3, mu_s: 0.38, mu_2: 0.64,
          I_0: 0.279, grain_diameter: 0.5e-3, grain_density: 2450}
bodies: [{material: beads, shape: {type: box, min: [0, 0], max: [0.1, 0.1]}}]
solver: {scheme: musl, cfl: 0.4, end_time: 0.2, gravity: [0, -9.81]}
output: {fields: [plastic_strain]}
)";
}

TEST(MuI, ColumnCollapseStaysAdmissibleAndBooksItsEnergy) {
  auto sim = test::simulation_from_yaml<2>(bead_column(), "beads.yaml");
  const EnergyBalance e0 = sim->energy();
  sim->run();
  const EnergyBalance e = sim->energy();
  const auto& p = sim->bodies()[0].particles;
  Real worst_ratio = 0, largest_mean = -1e300, stress_scale = 0;
  for (Index i = 0; i < p.size(); ++i) {
    const Mat3 sigma = p.stress[i].full();
    stress_scale = std::max(stress_scale, sigma.cwiseAbs().maxCoeff());
    largest_mean = std::max(largest_mean, sigma.trace() / 3);
    worst_ratio = std::max(worst_ratio, MuI::friction_ratio(sigma));
  }
  const Real balance = std::abs(e.total() - e0.total()) / std::abs(e0.gravity);
  std::printf(
      "[ measured ] mu_i column collapse: largest sqrt(J2)/P %.6f (mu_2 = 0.64), largest mean stress %.2e Pa, "
      "plastic work %.4g J/m, energy balance %.2e of the potential\n",
      worst_ratio, largest_mean, e.plastic_work, balance);
  EXPECT_LE(worst_ratio, 0.64 * (1 + 1e-12));
  EXPECT_LE(largest_mean, 0);
  EXPECT_GT(e.plastic_work, 0);
  EXPECT_LT(balance, 0.01);
}

TEST(MuI, RestartFromSavedStateIsExact) {
  const Real plastic = test_support::expect_exact_restart(bead_column(), "beads.yaml", "mu_i");
  EXPECT_GT(plastic, 0.01);  // the saved state had flowed
}

}  // namespace
}  // namespace mpm::soils
