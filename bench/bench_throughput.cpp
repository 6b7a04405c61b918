/// \file bench_throughput.cpp
/// Throughput of the explicit engine: particle-updates per second (particles x steps / wall seconds),
/// memory per particle (state bytes, and the heap the whole simulation holds) and, with --profile, the
/// time per phase (P2G, grid update, G2P, stress update, other), for an elastic block of about 1e6
/// particles, in 2D and 3D, with linear (hat) and cubic B-spline functions, USL and MUSL, on 1 and 2 threads.
///
/// The scene is written as YAML text and goes through parse_scene() and build_simulation<Dim>(), exactly
/// as a user scene does. Only Simulation::advance() is timed: no output is written. This is a program,
/// not a test: timings depend on the machine and never decide whether a test passes. See bench/README.md.

#include <fmt/format.h>
#include <fmt/ostream.h>
#include <malloc.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "mpm/app/modules.hpp"
#include "mpm/app/scene_builder.hpp"
#include "mpm/grid/grid.hpp"
#include "mpm/scene/scene_loader.hpp"
#include "mpm/simulation/simulation.hpp"
#include "mpm/simulation/step_profile.hpp"

namespace {

using Clock = std::chrono::steady_clock;

struct Case {
  std::string name;  ///< e.g. 2d_linear_usl
  int dim;
  std::string shape;          ///< "linear" or "cubic_bspline" (the scene-file names)
  std::string scheme;         ///< "usl" or "musl"
  bool axisymmetric = false;  ///< 2D only: the same block and grid in axisymmetric coordinates (x = r)
};

struct Options {
  bool quick = false;
  std::optional<long> steps;       ///< fixed number of timed steps (else calibrated)
  std::vector<std::string> cases;  ///< empty: all
  std::vector<int> threads{1, 2};
  std::string csv;
  double target_seconds = 3.0;  ///< wall time aimed at per timed run when steps are calibrated
  int repeat = 1;               ///< timed runs per thread count; the row reports the median rate
  bool profile = false;         ///< one more run of the same steps with the phase timers on
  std::string print_scene;      ///< --print-scene NAME: print that case's scene and exit
};

struct Row {
  std::string name;
  int dim = 0;
  std::string shape, scheme;
  int threads = 0;
  long long particles = 0, nodes = 0;
  long steps = 0;
  double wall = 0, rate = 0;
  std::optional<double> speedup;  ///< against the 1-thread run of the same case, if there is one
  std::size_t bytes_state = 0;    ///< particle state bytes per particle
  double bytes_grid = 0;          ///< grid node records per particle
  double bytes_heap = 0;          ///< heap held by the built and warmed-up simulation, per particle (NaN: not measured)
  std::vector<double> rates;      ///< every repeat's rate (the row's rate is their median)
  std::optional<mpm::StepProfile> profile;
};

/// Bytes the process has allocated with malloc and not freed (heap and mmapped blocks): measures what a
/// simulation holds (particles, the guard's snapshot, grid, bins, caches) independently of how the
/// allocator returns memory to the system, which makes RSS differences unreliable within one process.
/// Only the first case of a process is measured: the particle reordering keeps per-thread scratch arrays
/// for the process's lifetime (particle_set.hpp, gather_vector), which later cases reuse without allocating.
double heap_in_use() {
  const struct mallinfo2 m = mallinfo2();
  return static_cast<double>(m.uordblks + m.hblkhd);
}

std::vector<Case> all_cases() {
  std::vector<Case> out;
  for (int dim : {2, 3})
    for (const char* shape : {"linear", "cubic_bspline"})
      for (const char* scheme : {"usl", "musl"})
        out.push_back({fmt::format("{}d_{}_{}", dim, shape, scheme), dim, shape, scheme});
  // The 2D cases again in axisymmetric coordinates: the cost of the hoop terms against plane strain.
  for (const char* shape : {"linear", "cubic_bspline"})
    for (const char* scheme : {"usl", "musl"})
      out.push_back({fmt::format("2d_{}_{}_axisymmetric", shape, scheme), 2, shape, scheme, true});
  return out;
}

/// Block of `n` cells per axis (1 m side), 2 particles per cell per axis, inside a grid with a margin of
/// (in the axisymmetric cases x is the radius: the block is a thick tube three cells off the axis)
/// 3 cells on every side; linear elastic, with a small smooth initial velocity field so that it deforms.
std::string scene_yaml(const Case& c, int n) {
  const int margin = 3;
  const double h = 1.0 / n;
  const double extent = (n + 2 * margin) * h;
  const double lo = margin * h, hi = (margin + n) * h;
  auto vec = [&](double v) {
    std::string s = "[";
    for (int d = 0; d < c.dim; ++d) s += fmt::format("{}{:.17g}", d ? ", " : "", v);
    return s + "]";
  };
  const std::string velocity = c.dim == 2 ? R"v(["0.01*sin(3*x)", "0.01*cos(2*y)"])v"
                                          : R"v(["0.01*sin(3*x)", "0.01*cos(2*y)", "0.01*sin(2*z)"])v";
  return fmt::format(R"(dimension: {dim}
grid:{coordinates}
  origin: {origin}
  extent: {extent}
  cell_size: {h:.17g}
materials:
  block:
    model: linear_elastic
    density: 1000
    youngs_modulus: 1.0e6
    poisson_ratio: 0.3
bodies:
  - name: block
    material: block
    shape: {{type: box, min: {lo}, max: {hi}}}
    particles_per_cell: 2
    velocity: {velocity}
solver:
  scheme: {scheme}
  shape_function: {shape}
  cfl: 0.3
  end_time: 1000
output:
  fields: []
)",
                     fmt::arg("dim", c.dim),
                     fmt::arg("coordinates", c.axisymmetric ? "\n  coordinates: axisymmetric" : ""),
                     fmt::arg("origin", vec(0.0)), fmt::arg("extent", vec(extent)), fmt::arg("h", h),
                     fmt::arg("lo", vec(lo)), fmt::arg("hi", vec(hi)), fmt::arg("velocity", velocity),
                     fmt::arg("scheme", c.scheme), fmt::arg("shape", c.shape));
}

/// Cells per axis of the block: 2D 500^2 x 4 PPC = 1e6 (quick: 250^2 x 4 = 2.5e5);
/// 3D 50^3 x 8 PPC = 1e6 (quick: 32^3 x 8 = 2.6e5).
int block_cells(int dim, bool quick) {
  if (dim == 2) return quick ? 250 : 500;
  return quick ? 32 : 50;
}

template <int Dim>
void advance_steps(mpm::Simulation<Dim>& sim, long steps) {
  for (long i = 0; i < steps; ++i) sim.advance(sim.next_time_step());
}

template <int Dim>
std::vector<Row> run_case(const Case& c, const Options& opt) {
  const int n = block_cells(Dim, opt.quick);
  static bool first_case = true;
  const bool measure_heap = first_case;
  first_case = false;
  const double heap_before = heap_in_use();
  const auto t_build = Clock::now();
  const mpm::SceneDescription scene = mpm::parse_scene(scene_yaml(c, n), c.name + ".yaml");
  auto sim = mpm::app::build_simulation<Dim>(scene);
  const double build_seconds = std::chrono::duration<double>(Clock::now() - t_build).count();

  const long long particles = sim->particle_count();
  std::size_t state_bytes = 0;
  for (const auto& b : sim->bodies()) state_bytes = std::max(state_bytes, b.particles.bytes_per_particle());
  const long long nodes = sim->grid().size();
  const double grid_bytes =
      static_cast<double>(nodes) * (sizeof(mpm::NodeRecord<Dim>) + sizeof(mpm::NodeVelocity<Dim>)) / particles;
  fmt::print(std::cerr, "{}: {} particles, {} nodes, built in {:.2f} s, dt = {:.4g} s\n", c.name, particles, nodes,
             build_seconds, sim->next_time_step());

  std::vector<Row> rows;
  constexpr int warmup = 2, probe = 2;
  for (int threads : opt.threads) {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(threads));
    // Warm-up (first touch, thread pool start, caches), untimed.
    advance_steps(*sim, warmup);
    const double heap = measure_heap ? (heap_in_use() - heap_before) / static_cast<double>(particles)
                                     : std::numeric_limits<double>::quiet_NaN();
    // Unless --steps is given, a short probe sets the number of timed steps to last about target_seconds.
    long steps = 0;
    if (opt.steps) {
      steps = *opt.steps;
    } else {
      const auto p0 = Clock::now();
      advance_steps(*sim, probe);
      const double per_step = std::chrono::duration<double>(Clock::now() - p0).count() / probe;
      steps = std::clamp(static_cast<long>(std::lround(opt.target_seconds / std::max(per_step, 1e-9))), 5L, 5000L);
    }

    std::vector<double> rates, walls;
    for (int k = 0; k < opt.repeat; ++k) {
      const auto t0 = Clock::now();
      advance_steps(*sim, steps);
      walls.push_back(std::chrono::duration<double>(Clock::now() - t0).count());
      rates.push_back(static_cast<double>(particles) * steps / std::max(walls.back(), 1e-300));
    }
    std::vector<double> sorted = walls;
    std::sort(sorted.begin(), sorted.end());
    const double wall = sorted[sorted.size() / 2];  // the median run

    Row r;
    r.name = c.name;
    r.dim = Dim;
    r.shape = c.shape;
    r.scheme = c.scheme;
    r.threads = threads;
    r.particles = particles;
    r.nodes = nodes;
    r.steps = steps;
    r.wall = wall;
    r.rate = static_cast<double>(particles) * steps / std::max(wall, 1e-300);
    r.bytes_state = state_bytes;
    r.bytes_grid = grid_bytes;
    r.bytes_heap = heap;
    r.rates = rates;
    fmt::print(std::cerr, "  {} thread(s): {} steps in {:.3f} s, {:.4g} particle-updates/s{}\n", threads, steps, wall,
               r.rate, opt.repeat > 1 ? fmt::format(" (median of {})", opt.repeat) : std::string());
    if (opt.profile) {  // the same steps again, with the phase timers on
      sim->enable_profiling(true);
      const mpm::StepProfile before = sim->profile();
      advance_steps(*sim, steps);
      mpm::StepProfile p = sim->profile();
      for (int i = 0; i < mpm::step_phase_count; ++i) p.seconds[i] -= before.seconds[i];
      p.steps -= before.steps;
      p.particle_updates -= before.particle_updates;
      sim->enable_profiling(false);
      r.profile = p;
      fmt::print(std::cerr, "  profiled: {:.4g} particle-updates/s\n{}\n",
                 static_cast<double>(p.particle_updates) / p.stepping_seconds(), mpm::format_profile(p));
    }
    rows.push_back(r);
  }
  // Speed-up against the 1-thread run of the same case, when there is one.
  for (auto& r : rows)
    for (const auto& base : rows)
      if (base.threads == 1) r.speedup = r.rate / base.rate;
  return rows;
}

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> out;
  std::stringstream ss(s);
  std::string item;
  while (std::getline(ss, item, sep))
    if (!item.empty()) out.push_back(item);
  return out;
}

void usage(std::ostream& os) {
  os << "usage: bench_throughput [--quick] [--steps N] [--case NAME[,NAME...]] [--threads 1,2] [--seconds S] "
        "[--repeat N] [--profile] [--csv FILE] [--print-scene NAME]\n"
        "  --quick      blocks of about 2.5e5 particles and ~0.5 s per timed run (smoke run)\n"
        "  --steps N    time exactly N steps per run (default: set by a 2-step probe after the warm-up to last "
        "~--seconds)\n"
        "  --seconds S  wall time aimed at per timed run when calibrating (default 3, quick 0.5)\n"
        "  --case NAME  run only these cases; NAME is e.g. 2d_linear_usl, 3d_cubic_bspline_musl\n"
        "  --threads L  comma-separated thread counts (tbb::global_control max_allowed_parallelism)\n"
        "  --repeat N   N timed runs per thread count; report the median (default 1)\n"
        "  --profile    then run the same steps again with the phase timers on and print the time per phase\n"
        "  --csv FILE   also write the table as CSV\n"
        "  --print-scene NAME  print the YAML scene of case NAME (with --quick: its quick size) and exit (for "
        "bench/python_overhead.py and `mpm run`)\n"
        "cases:";
  for (const auto& c : all_cases()) os << ' ' << c.name;
  os << '\n';
}

Options parse_args(int argc, char** argv) {
  Options o;
  std::optional<double> seconds;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) throw std::invalid_argument(a + " needs a value");
      return argv[++i];
    };
    if (a == "--quick") {
      o.quick = true;
    } else if (a == "--steps") {
      o.steps = std::stol(value());
      if (*o.steps < 1) throw std::invalid_argument("--steps must be >= 1");
    } else if (a == "--seconds") {
      seconds = std::stod(value());
      if (!(*seconds > 0)) throw std::invalid_argument("--seconds must be > 0");
    } else if (a == "--case") {
      for (auto& name : split(value(), ',')) o.cases.push_back(name);
    } else if (a == "--threads") {
      o.threads.clear();
      for (auto& t : split(value(), ',')) {
        const int n = std::stoi(t);
        if (n < 1) throw std::invalid_argument("--threads: counts must be >= 1");
        o.threads.push_back(n);
      }
      if (o.threads.empty()) throw std::invalid_argument("--threads needs at least one count");
    } else if (a == "--csv") {
      o.csv = value();
    } else if (a == "--repeat") {
      o.repeat = std::stoi(value());
      if (o.repeat < 1) throw std::invalid_argument("--repeat must be >= 1");
    } else if (a == "--profile") {
      o.profile = true;
    } else if (a == "--print-scene") {
      o.print_scene = value();
    } else if (a == "-h" || a == "--help") {
      usage(std::cout);
      std::exit(0);
    } else {
      throw std::invalid_argument("unknown option '" + a + "'");
    }
  }
  o.target_seconds = seconds.value_or(o.quick ? 0.5 : 3.0);
  const auto known = all_cases();
  std::vector<std::string> named = o.cases;
  if (!o.print_scene.empty()) named.push_back(o.print_scene);
  for (const auto& name : named)
    if (std::none_of(known.begin(), known.end(), [&](const Case& c) { return c.name == name; }))
      throw std::invalid_argument("unknown case '" + name + "'");
  return o;
}

void print_table(const std::vector<Row>& rows, std::ostream& os) {
  os << "| case | dim | shape | scheme | threads | particles | steps | wall s | particle-updates/s | "
        "speed-up vs 1 thread | bytes/particle (state) | grid bytes/particle | heap bytes/particle |\n"
        "|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const auto& r : rows) {
    fmt::print(os, "| {} | {} | {} | {} | {} | {} | {} | {:.3f} | {:.3e} | ", r.name, r.dim, r.shape, r.scheme,
               r.threads, r.particles, r.steps, r.wall, r.rate);
    fmt::print(os, "{} | {} | {:.1f} | {} |\n", r.speedup ? fmt::format("{:.2f}", *r.speedup) : std::string("-"),
               r.bytes_state, r.bytes_grid,
               std::isnan(r.bytes_heap) ? std::string("-") : fmt::format("{:.0f}", r.bytes_heap));
  }
  if (std::none_of(rows.begin(), rows.end(), [](const Row& r) { return r.profile.has_value(); })) return;
  // Per-phase breakdown: share of the stepping time and nanoseconds per particle-update.
  os << "\n| case | threads | particle-updates/s (profiled) |";
  for (int i = 0; i < mpm::step_phase_count; ++i)
    if (i != static_cast<int>(mpm::StepPhase::output)) os << ' ' << mpm::step_phase_names[i] << " |";
  os << "\n|---|---|---|";
  for (int i = 1; i < mpm::step_phase_count; ++i) os << "---|";
  os << '\n';
  for (const auto& r : rows) {
    if (!r.profile) continue;
    const auto& p = *r.profile;
    const double total = p.stepping_seconds();
    fmt::print(os, "| {} | {} | {:.3e} |", r.name, r.threads, static_cast<double>(p.particle_updates) / total);
    for (int i = 0; i < mpm::step_phase_count; ++i)
      if (i != static_cast<int>(mpm::StepPhase::output))
        fmt::print(os, " {:.1f}% ({:.1f} ns) |", 100 * p.seconds[i] / total,
                   1e9 * p.seconds[i] / static_cast<double>(p.particle_updates));
    os << '\n';
  }
}

void write_csv(const std::vector<Row>& rows, const std::string& file) {
  std::ofstream f(file);
  if (!f) throw std::runtime_error("cannot write " + file);
  f << "case,dim,shape,scheme,threads,particles,grid_nodes,steps,wall_seconds,particle_updates_per_second,"
       "speedup_vs_1_thread,state_bytes_per_particle,grid_bytes_per_particle,heap_bytes_per_particle,repeat_rates";
  for (int i = 0; i < mpm::step_phase_count; ++i)
    if (i != static_cast<int>(mpm::StepPhase::output)) f << ",seconds_" << mpm::step_phase_names[i];
  f << '\n';
  for (const auto& r : rows) {
    fmt::print(f, "{},{},{},{},{},{},{},{},{:.6f},{:.6e},", r.name, r.dim, r.shape, r.scheme, r.threads, r.particles,
               r.nodes, r.steps, r.wall, r.rate);
    std::string rates;
    for (double x : r.rates) {
      if (!rates.empty()) rates += ' ';
      rates += fmt::format("{:.6e}", x);
    }
    fmt::print(f, "{},{},{:.3f},{},{}", r.speedup ? fmt::format("{:.4f}", *r.speedup) : std::string(), r.bytes_state,
               r.bytes_grid, std::isnan(r.bytes_heap) ? std::string() : fmt::format("{:.1f}", r.bytes_heap), rates);
    for (int i = 0; i < mpm::step_phase_count; ++i)
      if (i != static_cast<int>(mpm::StepPhase::output))
        f << ',' << (r.profile ? fmt::format("{:.6f}", r.profile->seconds[i]) : std::string());
    f << '\n';
  }
  if (!f) throw std::runtime_error("error writing " + file);
}

}  // namespace

int main(int argc, char** argv) {
  Options opt;
  try {
    opt = parse_args(argc, argv);
  } catch (const std::exception& e) {
    std::cerr << "bench_throughput: " << e.what() << '\n';
    usage(std::cerr);
    return 2;
  }
  if (!opt.print_scene.empty()) {
    for (const auto& c : all_cases())
      if (c.name == opt.print_scene) std::cout << scene_yaml(c, block_cells(c.dim, opt.quick));
    return 0;
  }
  try {
    // As the `mpm` program does: a build with optional modules registers them (their cost, if any, is part
    // of what this benchmark measures; bench/run_module_overhead.sh compares builds with and without).
    mpm::app::register_modules();
    std::string modules;
    for (const auto& m : mpm::app::compiled_modules()) {
      if (!modules.empty()) modules += ", ";
      modules += m;
    }
    fmt::print(std::cerr, "optional modules compiled in: {}\n", modules.empty() ? "none" : modules);
    std::vector<Row> rows;
    for (const auto& c : all_cases()) {
      if (!opt.cases.empty() && std::find(opt.cases.begin(), opt.cases.end(), c.name) == opt.cases.end()) continue;
      auto r = c.dim == 2 ? run_case<2>(c, opt) : run_case<3>(c, opt);
      rows.insert(rows.end(), r.begin(), r.end());
    }
    std::cout << '\n';
    print_table(rows, std::cout);
    std::cout << "\nparticle-updates/s = particles x steps / wall seconds of Simulation::advance() only (no output).\n"
                 "bytes/particle (state) = ParticleSet::bytes_per_particle(); the stability guard keeps one more copy "
                 "(snapshot).\n"
                 "grid bytes/particle = grid nodes x (sizeof NodeRecord + sizeof NodeVelocity) / particles.\n"
                 "heap bytes/particle = heap held by the built simulation after the warm-up steps (particles, the "
                 "guard's snapshot, grid, bins, reordering scratch) / particles; first case of the process only "
                 "(run one --case per process for the others).\n";
    if (!opt.csv.empty()) {
      write_csv(rows, opt.csv);
      std::cout << "CSV written to " << opt.csv << '\n';
    }
  } catch (const std::exception& e) {
    std::cerr << "bench_throughput: " << e.what() << '\n';
    return 1;
  }
  return 0;
}
