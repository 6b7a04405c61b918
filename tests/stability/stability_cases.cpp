#include "stability_cases.hpp"

#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <fstream>
#include <numbers>
#include <sstream>
#include <stdexcept>

#include "extended_stability_cases.hpp"
#include "mms.hpp"
#include "mpm/app/modules.hpp"
#include "mpm/app/run_scene.hpp"
#include "mpm/app/scene_builder.hpp"
#include "mpm/core/stability_error.hpp"
#include "mpm/scene/scene_error.hpp"
#include "mpm/scene/scene_loader.hpp"

namespace mpm::verification {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;
using Status = StabilityOutcome::Status;

double velocity_x(const std::map<std::string, double>& row) { return row.at("momentum_x") / row.at("mass"); }

// ---- the bar (review §6.1.1), scaled with the wave speed ------------------------------------------

/// The velocity amplitude is 1% of the wave speed c = sqrt(E / rho), so that the strain amplitude, the
/// relative error and the number of steps do not depend on E: only the time scale T = 4L/c does.
std::string bar_yaml(double E, int cells, const std::string& time_step, double end_time, double interval,
                     const std::string& scheme) {
  const double h = 25.0 / cells, c = std::sqrt(E);
  return fmt::format(
      "dimension: 1\n"
      "grid: {{origin: [0], extent: [{:.17g}], cell_size: {:.17g}, boundary: {{x_min: fixed}}}}\n"
      "materials: {{bar: {{model: linear_elastic, density: 1, youngs_modulus: {:.17g}, poisson_ratio: 0}}}}\n"
      "bodies: [{{name: bar, material: bar, shape: {{type: box, min: [0], max: [25]}}, particles_per_cell: 2,\n"
      "          velocity: [\"{:.17g}*sin(_pi*x/50)\"]}}]\n"
      "solver: {{scheme: {}, shape_function: linear, {}, end_time: {:.17g}}}\n"
      "output: {{interval: {:.17g}, fields: [velocity, stress, deformation_gradient]}}\n",
      h * (cells + 2), h, E, 0.01 * c, scheme, time_step, end_time, interval);
}

StabilityOutcome stiff_bar(const fs::path& dir) {
  const BarRun soft = run_bar(dir / "soft", 100, 16, 0.1, 1, 40);
  BarRun stiff = run_bar(dir, 1e12, 16, 0.1, 1, 40);
  auto& o = stiff.outcome;
  o.summary = fmt::format(
      "E = 1e12 Pa (c = 1e6 m/s, period 1e-4 s, dt = {:.4g} s): max |v_cm error| / amplitude {:.4e}, the same as at "
      "E = 100 Pa ({:.4e}); energy change {:+.2e}; {}",
      0.1 * stiff.stable_dt, o.measured, soft.outcome.measured, o.output.energy_change(), o.output.finite_text());
  return o;
}

StabilityOutcome fixed_dt(const fs::path& dir, double factor) {
  BarRun r = run_bar(dir, 100, 16, factor, 1, 40);
  auto& o = r.outcome;
  if (o.completed())
    o.summary =
        fmt::format("dt = {} x the CFL bound {:.6g} s: max |v_cm error| / amplitude {:.4e}; energy change {:+.2e}; {}",
                    factor, r.stable_dt, o.measured, o.output.energy_change(), o.output.finite_text());
  else
    o.summary = "refused before the first step: " + o.message;
  return o;
}

StabilityOutcome long_run(const fs::path& dir) {
  // 16 cells, dt = 0.1 h / c: 1e5 steps are 154.7 periods of mode 1.
  const double h = 25.0 / 16, dt = 0.1 * h / 10, end = 1e5 * dt;
  StabilityOutcome o =
      run_scene_text(bar_yaml(100, 16, fmt::format("dt: {:.17g}", dt), end, end / 100, "musl"), "long_run.yaml", dir);
  o.measured = o.output.energy_change();
  o.summary = fmt::format(
      "{} steps ({:.1f} periods), MUSL, FLIP: total energy change {:+.3e}, largest growth over the 101 frames {:+.3e}; "
      "{}",
      o.steps, end / 10, o.measured, o.output.max_energy_growth(), o.output.finite_text());
  return o;
}

// ---- 2D scenes --------------------------------------------------------------------------------------

/// Block of E = 1e12 Pa (rho = 7850, c_p = 1.31e4 m/s), 10 x 10 cells of 1 cm, at 100 m/s half a cell
/// from a fixed wall.
StabilityOutcome stiff_block(const fs::path& dir) {
  const std::string yaml =
      "dimension: 2\n"
      "grid: {origin: [0, 0], extent: [0.2, 0.2], cell_size: 0.01, boundary: {x_max: fixed}}\n"
      "materials: {hard: {model: linear_elastic, density: 7850, youngs_modulus: 1.0e12, poisson_ratio: 0.3}}\n"
      "bodies: [{name: block, material: hard, shape: {type: box, min: [0.09, 0.05], max: [0.19, 0.15]},\n"
      "          particles_per_cell: 2, velocity: [100, 0]}]\n"
      "solver: {scheme: musl, shape_function: linear, cfl: 0.5, end_time: 1.5e-4}\n"
      "output: {interval: 5.0e-6, fields: [velocity, stress, deformation_gradient]}\n";
  StabilityOutcome o = run_scene_text(yaml, "stiff_block.yaml", dir);
  o.measured = velocity_x(o.output.energy.back());
  o.summary = fmt::format(
      "{} steps; rebound at v_cm = {:.2f} m/s (from +100 m/s); total energy grows by at most {:+.3f} of E0 over the "
      "frames, {:+.3f} at the end; {}",
      o.steps, o.measured, o.output.max_energy_growth(), o.output.energy_change(), o.output.finite_text());
  return o;
}

StabilityOutcome nearly_incompressible(const fs::path& dir) {
  const std::string yaml =
      "dimension: 2\n"
      "grid: {origin: [0, 0], extent: [1, 1], cell_size: 0.05}\n"
      "materials: {rubber: {model: neo_hookean, density: 1000, youngs_modulus: 1.0e6, poisson_ratio: 0.4999}}\n"
      "bodies: [{name: disk, material: rubber, shape: {type: disk, center: [0.5, 0.5], radius: 0.3},\n"
      "          particles_per_cell: 2, velocity: [\"-2*(y-0.5)\", \"2*(x-0.5)\"]}]\n"
      "solver: {scheme: musl, shape_function: linear, cfl: 0.5, end_time: 0.1}\n"
      "output: {interval: 0.005, fields: [velocity, stress, deformation_gradient]}\n";
  StabilityOutcome o = run_scene_text(yaml, "nearly_incompressible.yaml", dir);
  o.measured = std::max(std::abs(o.output.min_det_F - 1), std::abs(o.output.max_det_F - 1));
  o.summary = fmt::format(
      "{} steps (c_p / c_s = 70.7, dt set by c_p = 1291 m/s); max |det F - 1| = {:.2e}; energy change {:+.2e}; "
      "max |stress| {:.3g} Pa against rho omega^2 R^2 / 2 = 180 Pa of the exact rigid rotation (pressure noise); {}",
      o.steps, o.measured, o.output.energy_change(), o.output.max_abs_stress, o.output.finite_text());
  return o;
}

/// Steel-like Neo-Hookean disk (E = 200 GPa, rho = 7850, nu = 0.29, c_p = 5.9 km/s), radius 1 cm, 1 mm cells,
/// at 5 km/s, 4 mm from a fixed wall.
StabilityOutcome hypervelocity(const fs::path& dir, const std::string& scheme) {
  const std::string yaml = fmt::format(
      "dimension: 2\n"
      "grid: {{origin: [0, 0], extent: [0.04, 0.06], cell_size: 0.001, boundary: {{x_max: fixed}}}}\n"
      "materials: {{steel: {{model: neo_hookean, density: 7850, youngs_modulus: 2.0e11, poisson_ratio: 0.29}}}}\n"
      "bodies: [{{name: projectile, material: steel, shape: {{type: disk, center: [0.024, 0.03], radius: 0.01}},\n"
      "          particles_per_cell: 2, velocity: [5000, 0]}}]\n"
      "solver: {{scheme: {}, shape_function: linear, cfl: 0.5, end_time: 8.0e-6}}\n"
      "output: {{interval: 2.0e-7, fields: [velocity, stress, deformation_gradient]}}\n",
      scheme);
  StabilityOutcome o = run_scene_text(yaml, "hypervelocity.yaml", dir);
  o.measured = velocity_x(o.output.energy.back());
  o.summary = o.completed()
                  ? fmt::format(
                        "{} steps to 8 us: rebound at v_cm = {:.0f} m/s; smallest det F {:.3f}; total energy "
                        "grows by up to {:+.3f}; {}",
                        o.steps, o.measured, o.output.min_det_F, o.output.max_energy_growth(), o.output.finite_text())
                  : fmt::format("stopped at step {}: {}; the last good frame: {}", o.steps + 1, o.message,
                                o.output.finite_text());
  return o;
}

/// A plate half a cell thick (one row of particles) translating at (1, 0.3) m/s and bending, across 16
/// columns and 5 rows of cells: the nodes at its edges carry almost no mass.
StabilityOutcome thin_plate(const fs::path& dir, const std::string& scheme) {
  const std::string yaml = fmt::format(
      "dimension: 2\n"
      "grid: {{origin: [0, 0], extent: [2, 1], cell_size: 0.05}}\n"
      "materials: {{plate: {{model: linear_elastic, density: 1000, youngs_modulus: 1.0e6, poisson_ratio: 0.3}}}}\n"
      "bodies: [{{name: plate, material: plate, shape: {{type: box, min: [0.2, 0.4], max: [0.8, 0.425]}},\n"
      "          particles_per_cell: 2, velocity: [1, \"0.3 + 0.5*sin(_pi*(x-0.2)/0.6)\"]}}]\n"
      "solver: {{scheme: {}, shape_function: linear, cfl: 0.5, end_time: 0.8}}\n"
      "output: {{interval: 0.02, fields: [velocity, stress, deformation_gradient]}}\n",
      scheme);
  StabilityOutcome o = run_scene_text(yaml, "thin_plate.yaml", dir);
  const auto& e = o.output.energy;
  o.measured = o.output.energy_change();
  const double dp = std::abs(e.back().at("momentum_x") - e.front().at("momentum_x")) / e.front().at("momentum_x");
  o.summary = o.completed() ? fmt::format("{} steps, 0.8 s: energy change {:+.2e}, x-momentum change {:.1e}; {}",
                                          o.steps, o.measured, dp, o.output.finite_text())
                            : fmt::format("stopped at step {}: {}; the last good frame: {}", o.steps + 1, o.message,
                                          o.output.finite_text());
  return o;
}

/// The 1D manufactured solution (review §6.2.1) with G = 0.95/pi: F_11 = 1 + pi G cos(pi X) sin(c pi t) goes
/// down to 0.05 at X = 0, t = 3T/4. 64 cells; `cfl` 0: the runner's fixed dt = 0.2 h / c.
StabilityOutcome extreme_compression(const fs::path& dir, const std::string& scheme, const std::string& shape,
                                     double cfl) {
  fs::remove_all(dir);
  MmsSpec spec{1, scheme, shape, 64, 2, 0.95 / std::numbers::pi, 1.0};
  spec.cfl = cfl;
  spec.output_directory = dir.string();
  const MmsResult r = run_mms(spec);
  StabilityOutcome o;
  o.status = r.failure.empty() ? Status::completed : Status::stopped_by_guard;
  o.message = r.failure;
  o.steps = r.steps;
  o.wall_seconds = r.wall_seconds;
  o.output = scan_output(dir);
  o.time = o.output.energy.empty() ? 0 : o.output.energy.back().at("time");
  o.measured = r.e1;
  o.summary = o.completed() ? fmt::format("smallest det F {:.4f} (exact 0.05); e1 = {:.3e} m (G = 0.302 m); {}",
                                          r.min_J, r.e1, o.output.finite_text())
                            : fmt::format("stopped: {}; the last good frame: {}", o.message, o.output.finite_text());
  return o;
}

}  // namespace

StabilityOutcome run_scene_text(const std::string& yaml, const std::string& name, const fs::path& dir,
                                std::optional<long long> steps) {
  StabilityOutcome o;
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "scene.yaml") << yaml;  // to rerun the case with `mpm run DIR/scene.yaml`
  std::ostringstream log;
  const auto start = Clock::now();
  try {
    app::register_modules();  // the modules' materials, schemes and sections, as `mpm run` has them
    const SceneDescription scene = parse_scene(yaml, name);
    app::RunOptions options;
    options.output_directory = dir;
    options.steps = steps;
    const app::RunSummary summary = app::run_scene(scene, options, log, log);  // the summary in the log too
    o.steps = summary.steps;
    o.largest_energy_ratio = summary.largest_energy_ratio;
  } catch (const SceneError& e) {
    o.status = Status::refused_by_loader;
    o.message = e.what();
  } catch (const StabilityError& e) {
    o.status = Status::stopped_by_guard;
    o.message = e.what();
    o.steps = e.report().step - 1;
  }
  o.wall_seconds = std::chrono::duration<double>(Clock::now() - start).count();
  o.log = log.str();
  if (fs::exists(dir)) o.output = scan_output(dir);
  if (!o.output.energy.empty()) o.time = o.output.energy.back().at("time");
  return o;
}

BarRun run_bar(const fs::path& dir, double E, int cells, double dt_over_bound, double periods, int frames_per_period,
               const std::string& scheme) {
  const double period = 4 * 25 / std::sqrt(E), amplitude = 0.01 * std::sqrt(E) * 2 / std::numbers::pi;
  BarRun r;
  // The bound of the initial state, h / (c + max|v_p|), from the engine itself.
  r.stable_dt = app::build_simulation<1>(parse_scene(bar_yaml(E, cells, "cfl: 1", period, period, scheme), "bar.yaml"))
                    ->stable_time_step();
  const double dt = dt_over_bound * r.stable_dt;
  r.outcome = run_scene_text(
      bar_yaml(E, cells, fmt::format("dt: {:.17g}", dt), periods * period, period / frames_per_period, scheme),
      "bar.yaml", dir);
  if (r.outcome.completed()) {
    double worst = 0;
    for (const auto& row : r.outcome.output.energy)
      worst = std::max(
          worst, std::abs(velocity_x(row) - amplitude * std::cos(2 * std::numbers::pi * row.at("time") / period)));
    r.outcome.measured = worst / amplitude;
  }
  return r;
}

std::vector<StabilityCase> stability_cases() {
  std::vector<StabilityCase> cases{
      {"stiff_bar", "1D bar mode 1, E = 1e12 Pa, MUSL: max |v_cm error| / amplitude over one period", stiff_bar},
      {"stiff_block_impact", "2D block, E = 1e12 Pa, at 100 m/s onto a fixed wall, MUSL: rebound velocity (m/s)",
       stiff_block},
      {"nearly_incompressible", "2D Neo-Hookean disk, nu = 0.4999, spinning at 2 rad/s, MUSL: max |det F - 1|",
       nearly_incompressible},
      {"hypervelocity_musl", "2D steel disk at 5 km/s onto a fixed wall, MUSL: rebound velocity (m/s)",
       [](const fs::path& d) { return hypervelocity(d, "musl"); }},
      {"hypervelocity_usl", "the same impact with USL: rebound velocity (m/s)",
       [](const fs::path& d) { return hypervelocity(d, "usl"); }},
      {"extreme_compression_fixed_dt",
       "1D manufactured solution with det F down to 0.05, TLMPM, linear, fixed dt = 0.2 h / c of the undeformed "
       "material",
       [](const fs::path& d) { return extreme_compression(d, "tlmpm", "linear", 0); }},
      {"extreme_compression_tlmpm", "the same with the adaptive time step, cfl 0.2: e1 (m)",
       [](const fs::path& d) { return extreme_compression(d, "tlmpm", "linear", 0.2); }},
      {"extreme_compression_tlmpm_cubic", "the same, TLMPM with cubic B-splines: e1 (m)",
       [](const fs::path& d) { return extreme_compression(d, "tlmpm", "cubic_bspline", 0.2); }},
      {"extreme_compression_musl", "the same with MUSL and cubic B-splines: e1 (m)",
       [](const fs::path& d) { return extreme_compression(d, "musl", "cubic_bspline", 0.2); }},
      {"thin_plate_musl", "2D plate half a cell thick crossing cells, MUSL, linear: energy change",
       [](const fs::path& d) { return thin_plate(d, "musl"); }},
      {"thin_plate_usl", "the same plate with USL: energy change",
       [](const fs::path& d) { return thin_plate(d, "usl"); }},
      {"fixed_dt_0.9", "1D bar, fixed dt = 0.9 x the CFL bound: max |v_cm error| / amplitude",
       [](const fs::path& d) { return fixed_dt(d, 0.9); }},
      {"fixed_dt_1.1", "1D bar, fixed dt = 1.1 x the CFL bound: refused by the scene loader",
       [](const fs::path& d) { return fixed_dt(d, 1.1); }},
      {"long_run", "1D bar, 1e5 steps, MUSL: relative energy change", long_run},
  };
  for (auto& c : extended_stability_cases()) cases.push_back(std::move(c));  // the extended cases
  return cases;
}

StabilityOutcome run_stability_case(const std::string& name, const fs::path& dir) {
  for (const auto& c : stability_cases())
    if (c.name == name) return c.run(dir);
  throw std::invalid_argument("unknown stability case '" + name + "'");
}

}  // namespace mpm::verification
