#include "mpm/app/run_scene.hpp"

#include <fmt/format.h>
#include <fmt/ostream.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ostream>
#include <stdexcept>

#include "mpm/app/run_description.hpp"
#include "mpm/app/scene_builder.hpp"
#include "mpm/history/history_writer.hpp"
#include "mpm/output_writer.hpp"

namespace mpm::app {
namespace {

using Clock = std::chrono::steady_clock;

template <int Dim>
void check(const SceneDescription& scene, std::ostream& out) {
  auto sim = build_simulation<Dim>(scene);
  std::vector<std::string> warnings;
  build_histories<Dim>(scene, *sim, warnings);  // what only the built bodies can refuse
  for (const auto& w : warnings) fmt::print(out, "warning: {}\n", w);
  const Real dt = sim->next_time_step();
  fmt::print(out,
             "{}: valid. {}D, {} particles in {} bodies, {} nodes; {} with {} functions; dt = {:.6g} s "
             "(stable bound {:.6g} s, {}); about {} steps to t = {:.6g} s\n",
             scene.file, Dim, sim->particle_count(), sim->bodies().size(), sim->grid().size(),
             enum_name(scene.solver.scheme), scene.solver.shape_function, dt, sim->stable_time_step(),
             sim->time_step_limiter(), static_cast<long long>(std::ceil(scene.solver.end_time / dt)),
             scene.solver.end_time);
}

/// The command line's changes to the scene, as "key: value" lines (recorded in the output files).
std::vector<std::string> overrides(const RunOptions& options) {
  std::vector<std::string> lines;
  if (options.output_directory) lines.push_back("output.directory: " + options.output_directory->string());
  if (options.end_time) lines.push_back(fmt::format("solver.end_time: {}", *options.end_time));
  if (options.steps) lines.push_back(fmt::format("steps: {}  # --steps", *options.steps));
  for (const auto& line : options.overrides) lines.push_back(line);
  return lines;
}

template <int Dim>
RunSummary run(const SceneDescription& scene_in, const RunOptions& options, std::ostream& log) {
  SceneDescription scene = scene_in;  // modules writing their own files (contact forces) follow -o too
  if (options.output_directory) scene.output.directory = options.output_directory->string();
  if (options.steps && *options.steps < 1)
    throw std::invalid_argument(fmt::format("--steps must be at least 1, not {}", *options.steps));
  if (options.end_time) {
    if (!(*options.end_time > 0) || !std::isfinite(*options.end_time))
      throw std::invalid_argument(
          fmt::format("--end-time must be a positive number of seconds, not {}", *options.end_time));
    scene.solver.end_time = *options.end_time;
  }
  auto sim = build_simulation<Dim>(scene);
  RunSummary summary;
  auto built_histories = build_histories<Dim>(scene, *sim, summary.warnings);  // output.histories
  for (const auto& w : summary.warnings) fmt::print(log, "warning: {}\n", w);
  const auto& o = scene.output;
  OutputWriter<Dim> writer(options.output_directory.value_or(o.directory), o.prefix, o.fields, o.grid, o.interval);
  HistoryWriter<Dim> histories(writer.directory(), std::move(built_histories));
  writer.set_field_data(run_field_data(scene, overrides(options)));  // self-describing files
  io::write_view_script(writer.directory() / "view.py", view_script_for(scene));
  summary.particles = static_cast<std::size_t>(sim->particle_count());
  for (const auto& b : sim->bodies())
    summary.bytes_per_particle = std::max(summary.bytes_per_particle, b.particles.bytes_per_particle());
  const Real e0 = sim->energy().total();
  // With a module that bounds the time step (heat conduction: diffusion), say which bound governs.
  if (std::any_of(sim->modules().begin(), sim->modules().end(),
                  [&](const auto& m) { return std::isfinite(m->stable_time_step(sim->bodies())); }))
    fmt::print(log, "time step: {:.6g} s, stable bound {:.6g} s governed by {}\n", sim->next_time_step(),
               sim->stable_time_step(), sim->time_step_limiter());
  if (options.profile) sim->enable_profiling();
  // Output is timed only when profiling (the profile's "output" phase).
  auto write = [&](const Simulation<Dim>& s, bool always) {
    const auto t0 = options.profile ? Clock::now() : Clock::time_point{};
    if (always) {
      writer.write(s);
      histories.write(s);
    } else {
      writer.write_if_due(s);
      histories.write_if_due(s);
    }
    if (options.profile) sim->add_to_profile(StepPhase::output, StepProfile::since(t0));
  };
  write(*sim, false);

  // The materials' validity checks (e.g. the density tolerance of a weakly compressible fluid), every
  // 50 steps and at the end; the first warning of each body is logged once.
  std::vector<bool> warned(sim->bodies().size(), false);
  auto check_state = [&](const Simulation<Dim>& s) {
    for (std::size_t b = 0; b < s.bodies().size(); ++b) {
      if (warned[b]) continue;
      const auto& body = s.bodies()[b];
      const std::string message = body.material->state_warning(body.particles);
      if (message.empty()) continue;
      warned[b] = true;
      summary.warnings.push_back(fmt::format("body {} at t = {:.6g} s: {}", body.name, s.time(), message));
      if (options.progress) log << '\n';
      fmt::print(log, "warning: {}\n", summary.warnings.back());
    }
  };

  const auto start = Clock::now();
  auto last_print = start;
  auto after_step = [&](const Simulation<Dim>& s) {
    write(s, false);
    if (s.step() % 50 == 0) check_state(s);
    if (!options.progress) return;
    const auto now = Clock::now();
    if (now - last_print < std::chrono::milliseconds(500)) return;
    last_print = now;
    const double wall = std::chrono::duration<double>(now - start).count();
    const double rate = static_cast<double>(s.particle_count()) * s.step() / wall;
    double eta = wall * (s.settings().end_time - s.time()) / std::max(s.time(), 1e-300);
    if (options.steps) eta = std::min(eta, wall * static_cast<double>(*options.steps - s.step()) / s.step());
    fmt::print(log, "\rstep {:>8}  t = {:<12.6g} s  {:9.3g} particle-updates/s  ETA {:7.1f} s ", s.step(), s.time(),
               rate, eta);
    log.flush();
  };
  try {
    sim->run(after_step, options.steps ? std::optional<Index>(*options.steps) : std::nullopt);
  } catch (const StabilityError&) {
    writer.write(*sim);  // the simulation was rolled back to the last good step
    histories.write(*sim);
    if (options.progress) log << '\n';
    throw;
  }
  summary.wall_seconds = std::chrono::duration<double>(Clock::now() - start).count();  // stepping only
  check_state(*sim);
  write(*sim, true);
  if (options.progress) log << '\n';
  summary.steps = sim->step();
  summary.particle_updates_per_second =
      static_cast<double>(summary.particles) * summary.steps / std::max(summary.wall_seconds, 1e-300);
  const Real e1 = sim->energy().total();
  summary.relative_energy_change = e0 != 0 ? (e1 - e0) / std::abs(e0) : e1;
  fmt::print(log,
             "done: {} steps to t = {:.6g} s in {:.3f} s wall, {:.4g} particle-updates/s, {} particles ({} B state "
             "each), relative energy change {:+.3e}; output in {}\n",
             summary.steps, sim->time(), summary.wall_seconds, summary.particle_updates_per_second, summary.particles,
             summary.bytes_per_particle, summary.relative_energy_change, writer.directory().string());
  if (options.profile) {
    summary.profile = sim->profile();
    fmt::print(log,
               "profile (wall time per phase; G2P and the stress update run fused and are split by their CPU "
               "time):\n{}\n",
               format_profile(summary.profile));
  }
  return summary;
}

}  // namespace

void check_scene(const SceneDescription& scene, std::ostream& out) {
  switch (scene.dimension) {
    case 1:
      return check<1>(scene, out);
    case 2:
      return check<2>(scene, out);
    default:
      return check<3>(scene, out);
  }
}

RunSummary run_scene(const SceneDescription& scene, const RunOptions& options, std::ostream& log) {
  switch (scene.dimension) {
    case 1:
      return run<1>(scene, options, log);
    case 2:
      return run<2>(scene, options, log);
    default:
      return run<3>(scene, options, log);
  }
}

}  // namespace mpm::app
