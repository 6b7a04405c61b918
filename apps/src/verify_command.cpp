#include "mpm/app/verify_command.hpp"

#include <fmt/format.h>
#include <fmt/ostream.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ostream>
#include <stdexcept>

#include "mpm/app/run_scene.hpp"
#include "mpm/app/scene_builder.hpp"
#include "mpm/core/stability_error.hpp"
#include "mpm/history/history_writer.hpp"
#include "mpm/io/csv_log.hpp"
#include "mpm/scene/scene_error.hpp"
#include "mpm/scene/scene_loader.hpp"

namespace mpm::app {
namespace {

namespace fs = std::filesystem;

/// Bad options: reported, exit status 2, nothing run.
using BadOption = std::invalid_argument;

/// HISTORY.COLUMN[@TIME] or HISTORY.COLUMN@START:TIME (the change from START to TIME)
struct Quantity {
  std::string text, history, column;
  std::optional<double> time;   ///< s; empty: at the end
  std::optional<double> start;  ///< s; the value is the change since then
};

/// A time of a --quantity, in [0, end_time].
double quantity_time(const std::string& quantity, const std::string& text, const SceneDescription& scene) {
  char* end = nullptr;
  const double time = std::strtod(text.c_str(), &end);
  if (text.empty() || *end || !std::isfinite(time) || time < 0)
    throw BadOption(fmt::format("--quantity {}: '{}' is not a time in seconds", quantity, text));
  if (time > scene.solver.end_time * (1 + 1e-12))
    throw BadOption(fmt::format("--quantity {}: t = {} s is after the scene's end_time {} s", quantity, time,
                                scene.solver.end_time));
  return time;
}

Quantity parse_quantity(const std::string& text, const SceneDescription& scene) {
  Quantity q;
  q.text = text;
  std::string name = text;
  if (const auto at = name.find('@'); at != std::string::npos) {
    const std::string t = name.substr(at + 1);
    if (const auto colon = t.find(':'); colon != std::string::npos) {
      q.start = quantity_time(text, t.substr(0, colon), scene);
      q.time = quantity_time(text, t.substr(colon + 1), scene);
      if (!(*q.start < *q.time))
        throw BadOption(fmt::format("--quantity {}: the start must come before the end", text));
    } else {
      q.time = quantity_time(text, t, scene);
    }
    name = name.substr(0, at);
  }
  const auto dot = name.find('.');
  std::vector<std::string> histories;
  for (const auto& h : scene.output.histories) histories.push_back(h.name);
  if (dot == std::string::npos || dot == 0 || dot + 1 == name.size())
    throw BadOption(fmt::format("--quantity {}: expected HISTORY.COLUMN[@TIME], e.g. {}.{}", text,
                                histories.empty() ? "tip" : histories.front(), "displacement_y"));
  q.history = name.substr(0, dot);
  q.column = name.substr(dot + 1);
  if (std::find(histories.begin(), histories.end(), q.history) == histories.end())
    throw BadOption(fmt::format("--quantity {}: the scene has no history '{}'{}", text, q.history,
                                histories.empty() ? " (it has no output.histories)"
                                                  : fmt::format("; its histories: {}", fmt::join(histories, ", "))));
  return q;
}

/// The scene with its cell size divided by `factor` (rounded to whole cells on every axis; particles per
/// cell unchanged, a fixed dt scaled with the representative cell size). `changes` gets "key: value" lines.
SceneDescription refined(const SceneDescription& base, double factor, std::vector<std::string>& changes) {
  SceneDescription s = base;
  auto representative = [&](const SceneDescription& x) {
    double h = 1;
    for (int d = 0; d < x.dimension; ++d) h *= x.grid.cell_size[d];
    return std::pow(h, 1.0 / x.dimension);
  };
  std::vector<double> sizes;
  for (int d = 0; d < s.dimension; ++d) {
    s.grid.cells[d] = static_cast<int>(std::lround(base.grid.cells[d] * factor));
    if (s.grid.cells[d] < 1)
      throw BadOption(
          fmt::format("the coarsest run would have no cell along {} ({} cells / {:g}): use fewer runs or a "
                      "smaller --ratio",
                      "xyz"[d], base.grid.cells[d], 1 / factor));
    s.grid.cell_size[d] = s.grid.extent[d] / s.grid.cells[d];
    sizes.push_back(s.grid.cell_size[d]);
  }
  changes.push_back(fmt::format("grid.cell_size: [{:.9g}]", fmt::join(sizes, ", ")));
  if (s.solver.dt) {
    s.solver.dt = *base.solver.dt * representative(s) / representative(base);
    changes.push_back(fmt::format("solver.dt: {:.9g}", *s.solver.dt));
  }
  return s;
}

double representative_h(const SceneDescription& s) {
  double h = 1;
  for (int d = 0; d < s.dimension; ++d) h *= s.grid.cell_size[d];
  return std::pow(h, 1.0 / s.dimension);
}

/// One run: the scene to the last time any quantity needs, landing exactly on every quantity's time; the
/// histories are written to `dir` as by `mpm run` (and a row at each quantity's time).
template <int Dim>
VerifyRun run_once(const SceneDescription& scene, const std::vector<Quantity>& quantities, const fs::path& dir,
                   std::ostream& log) {
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  auto sim = build_simulation<Dim>(scene);
  std::vector<std::string> warnings;
  auto built = build_histories<Dim>(scene, *sim, warnings);
  for (const auto& w : warnings) fmt::print(log, "warning: {}\n", w);
  // Each quantity's history and column, checked before any step.
  std::vector<std::pair<std::size_t, std::size_t>> where;
  for (const auto& q : quantities) {
    std::size_t k = 0;
    while (built[k].description->name != q.history) ++k;
    auto columns = built[k].history->columns();
    std::vector<std::string> names;
    for (const auto& c : columns) names.push_back(c.substr(0, c.find(" [")));
    const auto it = std::find(names.begin(), names.end(), q.column);
    if (it == names.end())
      throw BadOption(fmt::format("--quantity {}: history '{}' has no column '{}'; its columns: {}", q.text, q.history,
                                  q.column, fmt::join(names, ", ")));
    where.emplace_back(k, static_cast<std::size_t>(it - names.begin()) + 2);  // after time and step
  }
  VerifyRun run;
  for (const auto& body : sim->bodies()) {
    double mass = 0;
    for (Index i = 0; i < body.particles.size(); ++i) mass += body.particles.mass[i];
    run.body_masses.push_back(mass);
  }
  HistoryWriter<Dim> writer(dir, std::move(built));
  writer.write_if_due(*sim);
  std::vector<double> times;
  for (const auto& q : quantities) {
    times.push_back(q.time.value_or(scene.solver.end_time));
    if (q.start) times.push_back(*q.start);
  }
  std::sort(times.begin(), times.end());
  times.erase(std::unique(times.begin(), times.end()), times.end());
  run.values.assign(quantities.size(), 0);
  std::vector<double> start_values(quantities.size(), 0);
  for (const double T : times) {
    while (sim->time() < T * (1 - 1e-12)) {
      Real dt = sim->next_time_step();
      const Real rest = T - sim->time();
      if (dt >= rest * (1 - 1e-6)) dt = rest;  // land on T (a sliver of a step would only add round-off)
      sim->advance(dt);
      writer.write_if_due(*sim);
    }
    writer.write(*sim);  // a row of every history at T
    for (std::size_t q = 0; q < quantities.size(); ++q) {
      const double value = writer.last_row(where[q].first)[where[q].second];
      if (io::is_no_data(value))
        throw BadOption(
            fmt::format("--quantity {}: history '{}' has no data at t = {:.9g} s (no particle in its "
                        "region, or the particle followed has left the run)",
                        quantities[q].text, quantities[q].history, T));
      if (quantities[q].start == T) start_values[q] = value;
      if (quantities[q].time.value_or(scene.solver.end_time) == T) run.values[q] = value - start_values[q];
    }
  }
  run.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  run.steps = sim->step();
  run.particles = sim->particle_count();
  return run;
}

VerifyRun run_dispatch(const SceneDescription& scene, const std::vector<Quantity>& quantities, const fs::path& dir,
                       std::ostream& log) {
  switch (scene.dimension) {
    case 1:
      return run_once<1>(scene, quantities, dir, log);
    case 2:
      return run_once<2>(scene, quantities, dir, log);
    default:
      return run_once<3>(scene, quantities, dir, log);
  }
}

/// A body whose mass changes by more than 1% across the runs: the runs then differ in more than the resolution
/// (a primitive's lattice fill follows the cells), and the convergence analysis mixes the two.
std::vector<std::string> mass_warnings(const SceneDescription& scene, const std::vector<VerifyRun>& runs) {
  std::vector<std::string> warnings;
  if (runs.size() < 2) return warnings;
  const bool whole = scene.dimension == 3 || scene.grid.coordinates == Coordinates::axisymmetric;
  const char* unit = whole ? "kg" : scene.dimension == 2 ? "kg/m" : "kg/m^2";
  for (std::size_t b = 0; b < runs[0].body_masses.size(); ++b) {
    std::vector<std::string> masses;
    double worst = 0;
    for (const auto& run : runs) {
      masses.push_back(fmt::format("{:.6g}", run.body_masses[b]));
      worst = std::max(worst, std::abs(run.body_masses[b] / runs[0].body_masses[b] - 1));
    }
    if (worst <= 0.01) continue;
    warnings.push_back(fmt::format(
        "body '{}': its mass changes by up to {:.2f}% across the runs ({} {}, coarsest first): the particles fill "
        "the shape on each run's lattice, so the runs differ in more than the resolution; give the body `volume: "
        "exact` (shapes of known volume, docs/scene-reference.md) to keep its mass",
        scene.bodies[b].name, 100 * worst, fmt::join(masses, ", "), unit));
  }
  return warnings;
}

}  // namespace

VerifyReport run_verification(const VerifyOptions& o, std::ostream& log) {
  if (o.runs < 2) throw BadOption(fmt::format("--refine {}: at least two runs", o.runs));
  if (o.runs == 2 && !o.order)
    throw BadOption(
        "--refine 2: two runs give no observed order; give --order P (the GCI then uses Fs = 3) or use "
        "three runs");
  if (!(o.ratio > 1) || !std::isfinite(o.ratio))
    throw BadOption(fmt::format("--ratio {}: the refinement ratio must be > 1", o.ratio));
  if (o.quantities.empty()) throw BadOption("give at least one --quantity HISTORY.COLUMN[@TIME]");
  const SceneDescription scene = load_scene(o.scene);
  std::vector<Quantity> quantities;
  for (const auto& text : o.quantities) quantities.push_back(parse_quantity(text, scene));
  VerifyReport report;
  report.scene_file = o.scene.string();
  report.dimension = scene.dimension;
  report.ratio = o.ratio;
  std::vector<std::string> quantity_names;
  for (const auto& q : quantities) quantity_names.push_back("--quantity " + q.text);
  report.command = fmt::format("mpm verify {} --refine {} --ratio {:g}{} {}", o.scene.string(), o.runs, o.ratio,
                               o.scene_is_finest ? " --finest" : "", fmt::join(quantity_names, " "));
  for (int level = 0; level < o.runs; ++level) {
    std::vector<std::string> changes;
    const int finer = o.scene_is_finest ? level - (o.runs - 1) : level;  // <= 0 with --finest
    SceneDescription s = refined(scene, std::pow(o.ratio, finer), changes);
    const fs::path dir = o.output / fmt::format("run_{}", level + 1);
    s.output.directory = dir.string();  // modules' own files (contact forces) too
    fmt::print(log, "run {} of {}: h = {:.6g} m, cells {}\n", level + 1, o.runs, representative_h(s),
               fmt::join(s.grid.cells.begin(), s.grid.cells.begin() + s.dimension, " x "));
    try {
      VerifyRun run = run_dispatch(s, quantities, dir, log);
      run.h = representative_h(s);
      for (int d = 0; d < 3; ++d) run.cells[d] = s.grid.cells[d];
      fmt::print(log, "  {} particles, {} steps, {:.3f} s; {}\n", run.particles, run.steps, run.seconds,
                 fmt::join(run.values, ", "));
      report.runs.push_back(std::move(run));
    } catch (const StabilityError& e) {
      report.stopped = fmt::format("run {} (h = {:.6g} m) was stopped by the stability guard: {}", level + 1,
                                   representative_h(s), e.what());
      fmt::print(log, "error: {}\n", report.stopped);
      break;
    }
  }
  report.warnings = mass_warnings(scene, report.runs);
  for (const auto& w : report.warnings) fmt::print(log, "warning: {}\n", w);
  ConvergenceOptions options;
  options.assumed_order = o.order;
  for (std::size_t q = 0; q < quantities.size(); ++q) {
    VerifyQuantity vq;
    vq.name = quantities[q].text;
    vq.column = quantities[q].column;
    vq.time = quantities[q].time;
    vq.start = quantities[q].start;
    std::vector<ConvergenceRun> runs;
    for (const auto& r : report.runs) runs.push_back({r.h, r.values[q], r.seconds});
    if (runs.size() >= 3 || (runs.size() == 2 && o.order))
      vq.result = analyse_convergence(runs, options);
    else
      vq.result.verdict = fmt::format("only {} run(s) finished: no analysis", runs.size());
    report.quantities.push_back(std::move(vq));
  }
  return report;
}

int verify_command(const VerifyOptions& o, std::ostream& out, std::ostream& log) {
  VerifyReport report;
  try {
    report = run_verification(o, log);
  } catch (const BadOption& e) {
    fmt::print(log, "error: {}\n", e.what());
    return exit_bad_input;
  }
  write_verify_report(o.output, report, o.plot, out);
  return report.stopped.empty() ? exit_ok : exit_unstable;
}

}  // namespace mpm::app
