#include "extended_stability_cases.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <utility>

#include "frame_reader.hpp"

namespace mpm::verification {
namespace {

namespace fs = std::filesystem;

/// The step of the energy sentinel's warning in the run's log ("warning: energy sentinel: at step N"), or -1.
double sentinel_warning_step(const std::string& log) {
  const std::string key = "warning: energy sentinel: at step ";
  const auto at = log.find(key);
  return at == std::string::npos ? -1 : std::stod(log.substr(at + key.size()));
}

/// What the user was told, in words: the guard's stop, the sentinel's warning (with its hint) or
/// nothing.
std::string told(const StabilityOutcome& o) {
  std::string text;
  const double warned = sentinel_warning_step(o.log);
  if (warned >= 0) {
    const auto hint = o.log.find("Hint: ", o.log.find("warning: energy sentinel"));
    const auto end = o.log.find(" (measured", hint);  // the hint without the measurement it quotes
    text = fmt::format("the energy sentinel warned at step {:.0f} ({})", warned,
                       hint == std::string::npos ? "no hint" : o.log.substr(hint, end - hint));
  } else if (o.completed()) {
    text = fmt::format("no warning (sentinel's largest balance / tolerance {:.3g})", o.largest_energy_ratio);
  }
  if (o.stopped()) text += (text.empty() ? "" : "; ") + std::string("the guard stopped it: ") + o.message;
  return text;
}

// ---- locking: a nu = 0.49999 block under its own weight ---------------------------------------------

/// Rubber block 0.2 m x 0.1 m (20 x 10 cells of 1 cm, 2 x 2 particles each) on a slip floor, free sides, under
/// g = 9.81 m/s^2 switched on at t = 0, to t = 0.02 s (near the deepest compression of its first vertical
/// oscillation, at 0.024 s: the strain energy is 90% of its peak). E = 1e5 Pa, nu = 0.49999: K / G = 5e4, c_p = 1291
/// m/s sets dt, c_s = 5.8 m/s. The implicit scheme needs hencky_j2 (elastic, K = E / (3 (1 - 2 nu)), G = E / (2 (1 +
/// nu))) and a fixed dt (1 ms).
std::string locking_yaml(const std::string& scheme) {
  const double E = 1e5, nu = 0.49999;
  const bool implicit = scheme == "implicit";
  const std::string material =
      implicit
          ? fmt::format("{{model: hencky_j2, density: 1000, bulk_modulus: {:.17g}, shear_modulus: {:.17g}}}",
                        E / (3 * (1 - 2 * nu)), E / (2 * (1 + nu)))
          : fmt::format("{{model: neo_hookean, density: 1000, youngs_modulus: {:.17g}, poisson_ratio: {}}}", E, nu);
  return fmt::format(
      "dimension: 2\n"
      "grid: {{origin: [0, 0], extent: [0.3, 0.13], cell_size: 0.01, boundary: {{y_min: slip}}}}\n"
      "materials: {{rubber: {}}}\n"
      "bodies: [{{name: block, material: rubber, shape: {{type: box, min: [0.05, 0], max: [0.25, 0.1]}},\n"
      "          particles_per_cell: 2}}]\n"
      "solver: {{scheme: {}, shape_function: linear, {}, gravity: [0, -9.81], end_time: 0.02}}\n"
      "output: {{interval: 0.002, fields: [velocity, stress, pressure, deformation_gradient, displacement]}}\n",
      material, scheme, implicit ? "dt: 0.001" : "cfl: 0.5");
}

/// The pressure p = -tr(sigma)/3 of the last frame on the lattice of the particles' reference positions X = x - u
/// (40 x 20, spacing s = 5 mm, two per cell and axis). The checkerboard amplitude is half the rms over the
/// interior particles of c = p - (mean of the four lattice neighbours' p): a checkerboard +-A gives c = +-2A, a
/// field linear in x and y gives 0. The smooth part is the least-squares fit a + b Y of all particles (the
/// hydrostatic profile), reported by its value at the floor. Both over rho g H = 981 Pa.
void measure_pressure(const fs::path& dir, StabilityOutcome& o) {
  const auto files = frame_files(dir);
  if (files.empty()) return;
  const Frame f = read_frame(files.back());
  constexpr int nx = 40, ny = 20;
  const double s = 0.005, scale = 1000 * 9.81 * 0.1;
  std::vector<double> lattice(nx * ny, std::numeric_limits<double>::quiet_NaN());
  double sy = 0, sp = 0, syy = 0, syp = 0;
  const double n = static_cast<double>(f.size());
  for (std::size_t i = 0; i < f.size(); ++i) {
    const double X = f.points[i][0] - f.at("displacement", i, 0), Y = f.points[i][1] - f.at("displacement", i, 1);
    const long a = std::lround((X - 0.05 - s / 2) / s), b = std::lround((Y - s / 2) / s);
    const double pressure = f.at("pressure", i);
    if (a >= 0 && a < nx && b >= 0 && b < ny) lattice[static_cast<std::size_t>(b * nx + a)] = pressure;
    sy += Y, sp += pressure, syy += Y * Y, syp += Y * pressure;
  }
  double sum = 0;
  int count = 0;
  for (int b = 1; b + 1 < ny; ++b)
    for (int a = 1; a + 1 < nx; ++a) {
      auto at = [&](int i, int j) { return lattice[static_cast<std::size_t>(j * nx + i)]; };
      const double c = at(a, b) - (at(a - 1, b) + at(a + 1, b) + at(a, b - 1) + at(a, b + 1)) / 4;
      sum += c * c;  // NaN (a lattice site without its particle) makes the measure NaN: the test fails
      ++count;
    }
  const double slope = (n * syp - sy * sp) / (n * syy - sy * sy);
  o.measured = std::sqrt(sum / count) / 2 / scale;
  o.measures["checkerboard"] = o.measured;
  o.measures["base_pressure"] = (sp - slope * sy) / n / scale;  // the fit at Y = 0
  o.measures["particles"] = n;
}

StabilityOutcome locking(const fs::path& dir, const std::string& scheme) {
  StabilityOutcome o = run_scene_text(locking_yaml(scheme), "locking.yaml", dir);
  measure_pressure(dir, o);
  o.summary = fmt::format(
      "{} steps; pressure checkerboard amplitude {:.3g} rho g H between neighbouring particles, fitted base pressure "
      "{:.3g} rho g H (static, small strain: (1 + nu) / 3 = 0.5); smallest det F {:.6f}; "
      "the user: {}; {}",
      o.steps, o.measured, o.measures["base_pressure"], o.output.min_det_F, told(o), o.output.finite_text());
  return o;
}

// ---- a steel disk at 10 km/s with Johnson-Cook and Mie-Gruneisen --------------------------------------

/// 4340 steel (Johnson-Cook A, B, n, C of Johnson & Cook 1985; Mie-Gruneisen c0 = 4569 m/s, S = 1.49,
/// Gamma0 = 2.17, LASL shock data), the disk of the 5 km/s cases (radius 1 cm, 1 mm cells) at 10 km/s onto a
/// fixed wall, to 3 us. The 1D Hugoniot of a rigid-wall impact (u_p = 10 km/s): U_s = c0 + S u_p = 19.47 km/s,
/// p_H = rho0 U_s u_p = 1.524e12 Pa, J_H = 1 - u_p / U_s = 0.486; the linear EOS p = K (1 - J) of the same E
/// and nu would give 86 GPa at that J.
StabilityOutcome impact_10km_s(const fs::path& dir, const std::string& scheme) {
  const std::string yaml = fmt::format(
      "dimension: 2\n"
      "grid: {{origin: [0, 0], extent: [0.04, 0.12], cell_size: 0.001, boundary: {{x_max: fixed}}}}\n"
      "materials:\n"
      "  steel: {{model: johnson_cook, density: 7830, youngs_modulus: 2.0e11, poisson_ratio: 0.29,\n"
      "          yield_stress: 792.0e6, hardening_coefficient: 510.0e6, hardening_exponent: 0.26,\n"
      "          strain_rate_coefficient: 0.014, bulk_sound_speed: 4569, hugoniot_slope: 1.49, gruneisen_gamma: "
      "2.17}}\n"
      "bodies: [{{name: projectile, material: steel, shape: {{type: disk, center: [0.024, 0.06], radius: 0.01}},\n"
      "          particles_per_cell: 2, velocity: [10000, 0]}}]\n"
      "solver: {{scheme: {}, shape_function: linear, cfl: 0.5, end_time: 3.0e-6}}\n"
      "output: {{interval: 1.0e-7, fields: [velocity, stress, pressure, deformation_gradient, plastic_strain]}}\n",
      scheme);
  StabilityOutcome o = run_scene_text(yaml, "impact_10km_s.yaml", dir);
  double p_max = 0;
  for (const auto& file : frame_files(dir)) {
    const Frame f = read_frame(file);
    for (std::size_t i = 0; i < f.size(); ++i) p_max = std::max(p_max, f.at("pressure", i));
  }
  o.measured = o.output.min_det_F;
  o.measures["max_pressure"] = p_max;
  o.measures["energy_growth"] = o.output.max_energy_growth();
  o.measures["warning_step"] = sentinel_warning_step(o.log);
  const std::string held = o.completed() ? "the EOS held it" : "the guard stopped it";
  o.summary = fmt::format(
      "{}: {} steps to t = {:.3g} s; smallest det F {:.3f} (1D Hugoniot J_H = 0.486), largest pressure {:.3g} Pa "
      "(p_H = 1.524e12 Pa); total energy grows by up to {:+.3f}; the user: {}; {}",
      held, o.steps, o.time, o.output.min_det_F, p_max, o.output.max_energy_growth(), told(o), o.output.finite_text());
  return o;
}

// ---- two disks of density ratio 1e4 in contact ----------------------------------------------------

/// The two disks of examples/02 (radius 0.2 m, 20 x 20 cells, 2 x 2 particles per cell) closer together (centres
/// (0.3, 0.3) and (0.7, 0.7), 0.166 m apart along the diagonal at 0.283 m/s: first touch at t = 0.59 s), frictionless
/// multi-velocity contact with onset particle_gap (the hint table's advice). Heavy: rho = 1e4, E = 1e6 Pa; light:
/// rho = 1, E = 100 Pa: the same wave speed (c_p = 11.6 m/s, so one time step suits both) and an impedance ratio
/// of 1e4. A rigid elastic collision sends the light disk back at 2 v_heavy - v_light = (0.29996, 0.29996) m/s.
StabilityOutcome density_ratio(const fs::path& dir, const std::string& scheme, double cfl) {
  const std::string yaml = fmt::format(
      "dimension: 2\n"
      "grid: {{origin: [0, 0], extent: [1, 1], cell_size: 0.05}}\n"
      "materials:\n"
      "  heavy: {{model: linear_elastic, density: 10000, youngs_modulus: 1.0e6, poisson_ratio: 0.3}}\n"
      "  light: {{model: linear_elastic, density: 1, youngs_modulus: 100, poisson_ratio: 0.3}}\n"
      "bodies:\n"
      "  - {{name: heavy, material: heavy, shape: {{type: disk, center: [0.3, 0.3], radius: 0.2}}, particles_per_cell: "
      "2,\n"
      "     velocity: [0.1, 0.1]}}\n"
      "  - {{name: light, material: light, shape: {{type: disk, center: [0.7, 0.7], radius: 0.2}}, particles_per_cell: "
      "2,\n"
      "     velocity: [-0.1, -0.1]}}\n"
      "contact: {{onset: particle_gap}}\n"
      "solver: {{scheme: {}, shape_function: linear, cfl: {}, end_time: 0.9}}\n"
      "output: {{interval: 0.05, fields: [velocity, stress, mass, body]}}\n",
      scheme, cfl);
  StabilityOutcome o = run_scene_text(yaml, "density_ratio.yaml", dir);
  // Per body: momentum (from the frames' mass and velocity) and the closest approach of two particles of different
  // bodies, over the frames, against the particle spacing h / 2.
  double gap = std::numeric_limits<double>::infinity();
  std::array<std::array<double, 2>, 2> p0{}, p1{};
  std::array<double, 2> m{};
  const auto files = frame_files(dir);
  for (std::size_t k = 0; k < files.size(); ++k) {
    const Frame f = read_frame(files[k]);
    std::array<std::vector<std::size_t>, 2> of;
    std::array<std::array<double, 2>, 2> p{};
    for (std::size_t i = 0; i < f.size(); ++i) {
      const auto b = static_cast<std::size_t>(std::lround(f.at("body", i)));
      of[b].push_back(i);
      for (int c = 0; c < 2; ++c) p[b][c] += f.at("mass", i) * f.at("velocity", i, c);
      if (k == 0) m[b] += f.at("mass", i);
    }
    if (k == 0) p0 = p;
    p1 = p;
    for (std::size_t i : of[0])
      for (std::size_t j : of[1])
        gap = std::min(gap, std::hypot(f.points[i][0] - f.points[j][0], f.points[i][1] - f.points[j][1]));
  }
  // Along the line of centres n = (1, 1)/sqrt(2): the restitution e = -(v_l - v_h).n / (v_l0 - v_h0).n.
  auto along = [](const std::array<double, 2>& v) { return (v[0] + v[1]) / std::sqrt(2.0); };
  const double vh = along(p1[0]) / m[0], vl = along(p1[1]) / m[1];
  const double vh0 = along(p0[0]) / m[0], vl0 = along(p0[1]) / m[1];
  const double transfer = std::hypot(p1[1][0] - p0[1][0], p1[1][1] - p0[1][1]);
  const double imbalance =
      std::hypot(p1[0][0] + p1[1][0] - p0[0][0] - p0[1][0], p1[0][1] + p1[1][1] - p0[0][1] - p0[1][1]);
  o.measured = -(vl - vh) / (vl0 - vh0);
  o.measures["restitution"] = o.measured;
  o.measures["light_velocity"] = vl / std::sqrt(2.0);  // per axis
  o.measures["heavy_velocity_change"] = (vh - vh0) / std::sqrt(2.0);
  o.measures["momentum_imbalance"] = imbalance / std::max(transfer, 1e-300);  // of the momentum handed over
  o.measures["closest_over_spacing"] = gap / 0.025;
  o.summary = fmt::format(
      "{} steps to t = {:.3g} s; light disk leaves at {:.4f} m/s per axis (rigid elastic limit 0.29996), restitution "
      "{:.3f}; heavy disk slowed by {:.2e} m/s; total momentum kept to {:.1e} of the momentum handed over; closest "
      "particles of the two bodies {:.2f} particle spacings apart; total energy change {:+.2e}; the user: {}; {}",
      o.steps, o.time, o.measures["light_velocity"], o.measured, -o.measures["heavy_velocity_change"],
      o.measures["momentum_imbalance"], o.measures["closest_over_spacing"], o.output.energy_change(), told(o),
      o.output.finite_text());
  return o;
}

// ---- 1e5 steps at the CFL bound -----------------------------------------------------------------------

/// A 2D elastic block, 16 x 4 cells of 0.1 m (256 particles), fixed at x = 0, in its first axial mode (v_x =
/// 0.37 sin(pi x / 3.2) m/s, 1% of the plane-strain c_p = 37.06 m/s), with cfl 1: every step is exactly the bound
/// h / (c + max|v|) of its state (eq. 2.73), 1e5 steps (about 270 s, 1600 periods of the 1D bar mode).
StabilityOutcome cfl_bound(const fs::path& dir, const std::string& scheme) {
  const std::string yaml = fmt::format(
      "dimension: 2\n"
      "grid: {{origin: [0, 0], extent: [2, 1.2], cell_size: 0.1, boundary: {{x_min: fixed}}}}\n"
      "materials: {{elastic: {{model: linear_elastic, density: 1000, youngs_modulus: 1.0e6, poisson_ratio: 0.3}}}}\n"
      "bodies: [{{name: block, material: elastic, shape: {{type: box, min: [0, 0.4], max: [1.6, 0.8]}},\n"
      "          particles_per_cell: 2, velocity: [\"0.37*sin(_pi*x/3.2)\", 0]}}]\n"
      "solver: {{scheme: {}, shape_function: linear, cfl: 1, end_time: 300}}\n"
      "output: {{interval: 10, fields: [velocity, stress]}}\n",
      scheme);
  StabilityOutcome o = run_scene_text(yaml, "cfl_bound.yaml", dir, 100000);
  o.measured = o.output.energy_change();
  o.measures["warning_step"] = sentinel_warning_step(o.log);
  o.measures["energy_growth"] = o.output.max_energy_growth();
  o.summary = fmt::format(
      "{} steps to t = {:.4g} s at cfl 1: total energy change {:+.3e} (largest over the frames {:+.3e}); the user: "
      "{}; {}",
      o.steps, o.time, o.measured, o.output.max_energy_growth(), told(o), o.output.finite_text());
  return o;
}

}  // namespace

std::vector<StabilityCase> extended_stability_cases() {
  std::vector<StabilityCase> cases;
  for (const std::string scheme : {"usl", "musl", "usf", "tlmpm"})
    cases.push_back({"locking_" + scheme,
                     "2D Neo-Hookean block, nu = 0.49999, under its weight on a slip floor, " + scheme +
                         ": pressure checkerboard amplitude / rho g H",
                     [scheme](const fs::path& d) { return locking(d, scheme); }});
#ifdef MPM_WITH_IMPLICIT
  cases.push_back({"locking_implicit",
                   "the same block, elastic hencky_j2 (same K, G), implicit scheme (Q1/P0 mixed volume), dt 1 ms: "
                   "checkerboard amplitude / rho g H",
                   [](const fs::path& d) { return locking(d, "implicit"); }});
#endif
#ifdef MPM_WITH_PLASTICITY
  for (const std::string scheme : {"musl", "usl", "usf"})
    cases.push_back({"impact_10km_s_" + scheme,
                     "2D 4340 steel disk (Johnson-Cook, Mie-Gruneisen) at 10 km/s onto a fixed wall, " + scheme +
                         ": smallest det F",
                     [scheme](const fs::path& d) { return impact_10km_s(d, scheme); }});
#endif
#ifdef MPM_WITH_CONTACT
  cases.push_back({"density_ratio_musl",
                   "2D disks of density ratio 1e4 in frictionless contact (particle_gap), MUSL, cfl 0.5: restitution",
                   [](const fs::path& d) { return density_ratio(d, "musl", 0.5); }});
  cases.push_back({"density_ratio_usf", "the same with USF, cfl 0.5: restitution",
                   [](const fs::path& d) { return density_ratio(d, "usf", 0.5); }});
  cases.push_back({"density_ratio_usl", "the same with USL at its documented limit, cfl 0.2: restitution",
                   [](const fs::path& d) { return density_ratio(d, "usl", 0.2); }});
#endif
  for (const std::string scheme : {"usl", "musl", "usf", "tlmpm"})
    cases.push_back({"cfl_bound_" + scheme,
                     "2D block in its first axial mode, 1e5 steps at cfl 1 (dt = the bound), " + scheme +
                         ": relative energy change",
                     [scheme](const fs::path& d) { return cfl_bound(d, scheme); }});
  return cases;
}

}  // namespace mpm::verification
