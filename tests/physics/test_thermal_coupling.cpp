// Thermo-mechanical coupling of the thermal module (review §5.3.2, Alg. 9): thermal expansion (eq. 5.26) of a bar
// heated uniformly by a source, free (strain alpha dT, no stress), held at both ends (uniaxial stress
// -E alpha dT) and confined in every direction (-3 K alpha dT); and the energy balance of plastic heating
// (eq. B.13): the heat stored equals chi times the plastic work. The heating follows a smooth ramp,
// gamma(t) = gamma0 (1 - cos(2 pi t / t_end)), whose integral is gamma0 t_end, so that the bar stays
// quasi-static (the ramp lasts 50 transit times of the elastic wave).
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <cmath>
#include <cstdio>

#include "mpm/app/modules.hpp"
#include "mpm/app/scene_builder.hpp"
#include "mpm/plasticity/elastoplastic.hpp"
#include "mpm/scene/scene_loader.hpp"

namespace mpm {
namespace {

constexpr double E = 100, nu = 0.3, alpha = 1e-3, t_end = 5;  // Pa, -, 1/K, s (rho = c = 1)
constexpr double dT_target = 1;                               // K: gamma0 t_end / (rho c)

template <int Dim>
std::unique_ptr<Simulation<Dim>> heated_bar(const std::string& grid, const std::string& box, const std::string& model,
                                            double poisson) {
  app::register_modules();
  const std::string yaml = fmt::format(
      "dimension: {}\n"
      "grid: {}\n"
      "materials: {{m: {{model: {}, density: 1, youngs_modulus: {}, poisson_ratio: {}, specific_heat: 1,\n"
      "                 thermal_conductivity: 0.01, thermal_expansion: {}, room_temperature: 300}}}}\n"
      "bodies: [{{material: m, shape: {}, particles_per_cell: 2}}]\n"
      "solver: {{scheme: musl, cfl: 0.5, end_time: {}}}\n"
      "thermal: {{source: \"{} * (1 - cos(2 * _pi * t / {}))\"}}\n",
      Dim, grid, model, E, poisson, alpha, box, t_end, dT_target / t_end, t_end);
  auto sim = app::build_simulation<Dim>(parse_scene(yaml, "heated_bar.yaml"));
  sim->run();
  return sim;
}

struct Measured {
  double dT = 0;                     ///< mean temperature rise, K
  double log_strain[3] = {0, 0, 0};  ///< mean ln F_aa
  Mat3 stress = Mat3::Zero();        ///< mean Cauchy stress
};

template <int Dim>
Measured measure(const Simulation<Dim>& sim) {
  Measured m;
  const auto& p = sim.bodies()[0].particles;
  const auto& T = p.template field<Real>("temperature");
  for (Index i = 0; i < p.size(); ++i) {
    m.dT += (T[i] - 300) / p.size();
    for (int d = 0; d < Dim; ++d) m.log_strain[d] += std::log(p.F[i](d, d)) / p.size();
    m.stress += p.stress[i].full() / p.size();
  }
  return m;
}

TEST(ThermalExpansion, FreeBarStrainsByAlphaDeltaTAndStaysStressFree) {
  // 3D bar 1 x 0.25 x 0.25 m in a larger grid, nothing held: every axis strains by alpha dT.
  auto sim = heated_bar<3>("{origin: [0, 0, 0], extent: [1.5, 0.75, 0.75], cell_size: 0.25}",
                           "{type: box, min: [0.25, 0.25, 0.25], max: [1.25, 0.5, 0.5]}", "linear_elastic", nu);
  const Measured m = measure(*sim);
  std::printf(
      "[ measured ] free bar: dT = %.6f K, ln F = (%.6e, %.6e, %.6e) (alpha dT = %.6e), max |sigma| = %.3e Pa\n", m.dT,
      m.log_strain[0], m.log_strain[1], m.log_strain[2], alpha * m.dT, m.stress.cwiseAbs().maxCoeff());
  // gamma* is per current volume and the bar grows by 3 alpha dT: the mean rise exceeds gamma0 t_end / (rho c)
  // by about the mean volume change, 1.5e-3.
  EXPECT_NEAR(m.dT, dT_target * (1 + 1.5 * alpha), 2e-4);
  for (int d = 0; d < 3; ++d) EXPECT_NEAR(m.log_strain[d], alpha * m.dT, 1e-3 * alpha * m.dT);
  EXPECT_LT(m.stress.cwiseAbs().maxCoeff(), 2e-3 * E * alpha * m.dT);  // stress-free (to the residual vibration)
}

TEST(ThermalExpansion, BarHeldAtBothEndsReachesMinusEAlphaDeltaT) {
  // The bar spans the grid along x, whose end faces hold the normal velocity (slip); free laterally:
  // uniaxial stress sigma_xx = -E alpha dT, the other components zero.
  auto sim = heated_bar<3>(
      "{origin: [0, 0, 0], extent: [1, 0.75, 0.75], cell_size: 0.25, boundary: {x_min: slip, x_max: slip}}",
      "{type: box, min: [0, 0.25, 0.25], max: [1, 0.5, 0.5]}", "linear_elastic", nu);
  const Measured m = measure(*sim);
  const double expected = -E * alpha * m.dT;
  std::printf("[ measured ] bar held at both ends: sigma_xx = %.6e Pa (-E alpha dT = %.6e), sigma_yy = %.3e\n",
              m.stress(0, 0), expected, m.stress(1, 1));
  EXPECT_NEAR(m.stress(0, 0), expected, 0.01 * std::abs(expected));
  EXPECT_LT(std::abs(m.stress(1, 1)), 0.01 * std::abs(expected));
  EXPECT_LT(std::abs(m.stress(2, 2)), 0.01 * std::abs(expected));
}

template <int Dim>
void expect_confined(const std::string& model, const std::string& grid, const std::string& box) {
  auto sim = heated_bar<Dim>(grid, box, model, nu);
  const Measured m = measure(*sim);
  const double K = E / (3 * (1 - 2 * nu)), expected = -3 * K * alpha * m.dT;
  std::printf("[ measured ] %s confined in %dD: sigma = (%.6e, %.6e, %.6e) Pa (-3 K alpha dT = %.6e)\n", model.c_str(),
              Dim, m.stress(0, 0), m.stress(1, 1), m.stress(2, 2), expected);
  for (int d = 0; d < 3; ++d) EXPECT_NEAR(m.stress(d, d), expected, 0.01 * std::abs(expected)) << "axis " << d;
  if (model != "linear_elastic") return;
  // The books: the work of the thermal strain, W_T = -sum V tr(sigma) alpha dT (the module's negative removed energy),
  // is the strain energy the heating stored, 9/2 K (alpha dT)^2 V, so the run's balance E(t) - E(0) + removed
  // closes.
  double removed = 0;
  for (const auto& module : sim->modules()) removed += module->removed_energy();
  const EnergyBalance e = sim->energy();
  const double volume = [&] {
    double v = 0;
    const auto& p = sim->bodies()[0].particles;
    for (Index i = 0; i < p.size(); ++i) v += p.volume0[i];
    return v;
  }();
  const double stored = 4.5 * K * alpha * m.dT * alpha * m.dT * volume;
  std::printf(
      "[ measured ] %dD: thermal expansion work %.6e J, strain energy %.6e J (9/2 K (alpha dT)^2 V = %.6e), "
      "kinetic %.3e J\n",
      Dim, -removed, e.strain, stored, e.kinetic);
  EXPECT_NEAR(-removed, stored, 0.02 * stored);
  EXPECT_NEAR(e.strain + e.kinetic + removed, 0, 1e-3 * stored);
}

TEST(ThermalExpansion, ConfinedInEveryDirectionReachesMinusThreeKAlphaDeltaT) {
  // Every face holds the normal velocity: no strain at all, hydrostatic stress -3 K alpha dT. In 1D and 2D the
  // out-of-plane axes are held by the kinematics (uniaxial and plane strain): the same state.
  expect_confined<3>("linear_elastic",
                     "{origin: [0, 0, 0], extent: [0.5, 0.5, 0.5], cell_size: 0.25, boundary: {x_min: slip, x_max: "
                     "slip, y_min: slip, y_max: slip, z_min: slip, z_max: slip}}",
                     "{type: box, min: [0, 0, 0], max: [0.5, 0.5, 0.5]}");
  expect_confined<2>("linear_elastic",
                     "{origin: [0, 0], extent: [1, 1], cell_size: 0.25, boundary: {x_min: slip, x_max: slip, y_min: "
                     "slip, y_max: slip}}",
                     "{type: box, min: [0, 0], max: [1, 1]}");
  expect_confined<1>("linear_elastic",
                     "{origin: [0], extent: [1], cell_size: 0.25, boundary: {x_min: fixed, x_max: fixed}}",
                     "{type: box, min: [0], max: [1]}");
}

TEST(ThermalExpansion, PlasticModelConfinedReachesMinusThreeKAlphaDeltaT) {
  // j2_plasticity below yield: the expansion enters its equation of state through J exp(-3 alpha dT).
  expect_confined<1>("j2_plasticity, yield_stress: 1.0e6",
                     "{origin: [0], extent: [1], cell_size: 0.25, boundary: {x_min: fixed, x_max: fixed}}",
                     "{type: box, min: [0], max: [1]}");
}

/// Heat in through a face and from a source, nothing out: the heat stored grows at exactly the rate put in
/// (eq. 5.21: Q_ext = sum V gamma* phi - sum q* A on the face nodes).
TEST(ThermalBoundary, FluxAndSourceAddHeatAtTheirRates) {
  app::register_modules();
  const std::string yaml =
      "dimension: 2\n"
      "grid: {origin: [0, 0], extent: [1, 0.5], cell_size: 0.125}\n"
      "materials: {m: {model: linear_elastic, density: 2, youngs_modulus: 1.0e-9, poisson_ratio: 0, specific_heat: 3,\n"
      "                thermal_conductivity: 0.5, room_temperature: 10}}\n"
      "bodies: [{material: m, shape: {type: box, min: [0, 0], max: [1, 0.5]}, particles_per_cell: 2}]\n"
      "solver: {scheme: musl, cfl: 0.5, end_time: 0.2}\n"
      "thermal:\n"
      "  source: 4\n"                       // W/m^3 over 0.5 m^2 (per m): 2 W/m
      "  boundary: {x_max: {flux: -7}}\n";  // W/m^2 inward over a 0.5 m face: 3.5 W/m
  auto sim = app::build_simulation<2>(parse_scene(yaml, "flux.yaml"));
  sim->run();
  const double expected = (4 * 0.5 + 7 * 0.5) * sim->time();  // J per m out of plane
  std::printf("[ measured ] heat stored %.12f J/m, put in %.12f J/m\n", sim->energy().thermal, expected);
  EXPECT_NEAR(sim->energy().thermal, expected, 1e-9 * expected);
  // the flux made x_max the hot side
  const auto& T = sim->grid().node_fields.at("temperature");
  EXPECT_GT(T[8], T[0]);
}

/// k = diag(1, 0): heat flows along x only, so a 2D plate held at T = 0 and 1 on its x faces is the 1D bar of
/// eq. 5.27 on every row (the series at t = 0.05, to the 1D accuracy at 40 cells).
TEST(ThermalBoundary, AnisotropicConductivityConductsAlongItsAxisOnly) {
  app::register_modules();
  const std::string yaml =
      "dimension: 2\n"
      "grid: {origin: [0, 0], extent: [1, 0.1], cell_size: 0.025}\n"
      "materials: {m: {model: linear_elastic, density: 1, youngs_modulus: 1.0e-9, poisson_ratio: 0, specific_heat: 1,\n"
      "                thermal_conductivity_xx: 1}}\n"
      "bodies: [{material: m, shape: {type: box, min: [0, 0], max: [1, 0.1]}, particles_per_cell: 2}]\n"
      "solver: {scheme: usl, cfl: 0.8, end_time: 0.05}\n"
      "thermal:\n"
      "  initial_temperature: 0\n"
      "  boundary: {x_min: {temperature: 0}, x_max: {temperature: 1}}\n";
  auto sim = app::build_simulation<2>(parse_scene(yaml, "anisotropic.yaml"));
  // the bound uses k_max = 1: h^2 rho c / (2 dim k) = 0.025^2 / 4
  EXPECT_NEAR(sim->stable_time_step(), 0.025 * 0.025 / 4, 1e-15);
  sim->run();
  const auto& T = sim->grid().node_fields.at("temperature");
  const auto& g = sim->grid().geometry;
  double worst = 0, row_spread = 0;
  for (Index n = 0; n < g.node_count(); ++n) {
    const auto ij = g.node_indices(n);
    const double x = ij[0] * 0.025;
    double exact = x;  // eq. 5.27, T0 = 0, T1 = 1
    for (int k = 1; k <= 400; ++k) {
      const double a = k * 3.141592653589793;
      exact += 2 * (k % 2 ? -1.0 : 1.0) / a * std::exp(-a * a * sim->time()) * std::sin(a * x);
    }
    worst = std::max(worst, std::abs(T[n] - exact));
    row_spread = std::max(row_spread, std::abs(T[n] - T[ij[0]]));  // against the node of row 0
  }
  std::printf("[ measured ] k = diag(1, 0): max |T - T_1D exact| = %.3e, spread across rows %.3e\n", worst, row_spread);
  EXPECT_LT(worst, 6e-4);  // measured 3.6e-4
  EXPECT_LT(row_spread, 1e-12);
}

/// A steel bar (J2, perfectly plastic, sigma_y = 400 MPa) compressed in uniaxial strain by its x_max face moving
/// at 5 m/s: plastic flow heats it by chi sigma_f d eps_p / (rho c) (eq. B.13, the plasticity module), and
/// conduction (the thermal module) moves that heat without creating or losing any (no held temperature, insulated
/// faces): the heat stored sum m c (T - T_r) must equal chi times the plastic work (energy.csv columns
/// thermal_energy and plastic_work).
struct PlasticHeating {
  double thermal = 0, plastic_work = 0, max_rise = 0;
  double worst_particle = 0;  ///< max |T - T_r - chi w_p / (rho c)| over the particles, K
};

PlasticHeating compress_plastic_bar(double conductivity) {
  app::register_modules();
  const std::string yaml = fmt::format(
      "dimension: 1\n"
      "grid: {{origin: [0], extent: [0.01], cell_size: 0.001, boundary: {{x_min: fixed, x_max: {{velocity: [-5]}}}}}}\n"
      "materials: {{steel: {{model: j2_plasticity, density: 7850, youngs_modulus: 200.0e9, poisson_ratio: 0.3,\n"
      "  yield_stress: 400.0e6, specific_heat: 477, taylor_quinney_coefficient: 0.9, room_temperature: 293.15,\n"
      "  thermal_conductivity: {}}}}}\n"
      "bodies: [{{material: steel, shape: {{type: box, min: [0], max: [0.01]}}, particles_per_cell: 2}}]\n"
      "solver: {{scheme: musl, cfl: 0.5, end_time: 4.0e-5}}\n"
      "thermal:\n",
      conductivity);
  auto sim = app::build_simulation<1>(parse_scene(yaml, "plastic_heating.yaml"));
  sim->run();
  const EnergyBalance e = sim->energy();
  PlasticHeating r{e.thermal, e.plastic_work, 0, 0};
  const auto& p = sim->bodies()[0].particles;
  const auto& T = p.template field<Real>("temperature");
  const auto& state = p.template field<plasticity::PlasticState<1>>("plasticity");
  for (Index i = 0; i < p.size(); ++i) {
    r.max_rise = std::max(r.max_rise, T[i] - 293.15);
    // each particle's rise: chi w_p / (rho c), w_p = its plastic work per reference volume
    r.worst_particle = std::max(r.worst_particle, std::abs(T[i] - 293.15 - 0.9 * state[i].plastic_work / (7850 * 477)));
  }
  return r;
}

TEST(ThermalCoupling, AdiabaticPlasticHeatingStoresChiTimesThePlasticWork) {
  const PlasticHeating adiabatic = compress_plastic_bar(0);
  std::printf("[ measured ] k = 0: thermal energy %.9e J, 0.9 x plastic work %.9e J, max rise %.4f K\n",
              adiabatic.thermal, 0.9 * adiabatic.plastic_work, adiabatic.max_rise);
  ASSERT_GT(adiabatic.plastic_work, 0);
  EXPECT_NEAR(adiabatic.thermal, 0.9 * adiabatic.plastic_work, 1e-9 * adiabatic.plastic_work);
  EXPECT_GT(adiabatic.max_rise, 0.1);
  EXPECT_LT(adiabatic.worst_particle, 1e-9 * adiabatic.max_rise);  // k = 0: every particle on its own
  const PlasticHeating conducted = compress_plastic_bar(50);
  std::printf("[ measured ] k = 50 W/(m K): thermal energy %.9e J, 0.9 x plastic work %.9e J\n", conducted.thermal,
              0.9 * conducted.plastic_work);
  EXPECT_NEAR(conducted.thermal, 0.9 * conducted.plastic_work, 1e-9 * conducted.plastic_work);
}

}  // namespace
}  // namespace mpm
