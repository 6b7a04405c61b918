// Cost of multi-velocity contact (contact/): two elastic blocks pressed against each other (contact on
// the whole shared face at every step), run with the `contact:` section and without it (one shared velocity
// field, the same scene otherwise). Prints the wall time per step of both and their ratio (target:
// <= 1.6). The runs alternate, round by round, so that a change of machine load hits both.
//   bench_contact [--cells N] [--steps N] [--rounds N] [--scheme musl] [--shape linear] [--threads T]
#include <fmt/format.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

#include "mpm/app/modules.hpp"
#include "mpm/app/scene_builder.hpp"
#include "mpm/scene/scene_loader.hpp"

namespace {

std::string scene(int cells, const std::string& scheme, const std::string& shape, bool contact) {
  const double h = 1.0 / cells;
  return fmt::format(R"(
dimension: 2
grid: {{origin: [0, 0], extent: [1, 0.5], cell_size: {h}}}
materials:
  rubber: {{model: linear_elastic, density: 1000, youngs_modulus: 1.0e6, poisson_ratio: 0.3}}
bodies:
  - {{name: left, material: rubber, shape: {{type: box, min: [{a}, {a}], max: [0.5, {b}]}}, particles_per_cell: 2,
     velocity: [0.05, 0]}}
  - {{name: right, material: rubber, shape: {{type: box, min: [0.5, {a}], max: [{c}, {b}]}}, particles_per_cell: 2,
     velocity: [-0.05, 0]}}
solver: {{scheme: {scheme}, shape_function: {shape}, cfl: 0.4, end_time: 1}}
{contact}
)",
                     fmt::arg("h", h), fmt::arg("a", 4 * h), fmt::arg("b", 0.5 - 4 * h), fmt::arg("c", 1 - 4 * h),
                     fmt::arg("scheme", scheme), fmt::arg("shape", shape),
                     fmt::arg("contact", contact ? "contact: {friction: 0.3}" : ""));
}

double seconds_per_step(const std::string& yaml, int steps) {
  auto sim = mpm::app::build_simulation<2>(mpm::parse_scene(yaml, "bench_contact.yaml"));
  const double dt = sim->next_time_step();
  for (int i = 0; i < 5; ++i) sim->advance(dt);  // warm-up (first touch of the arrays)
  const auto t0 = std::chrono::steady_clock::now();
  for (int i = 0; i < steps; ++i) sim->advance(dt);
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() / steps;
}

}  // namespace

int main(int argc, char** argv) {
  int cells = 400, steps = 40, rounds = 3, threads = 1;
  std::string scheme = "musl", shape = "linear";
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (i + 1 >= argc) {
      std::cerr << "bench_contact: " << a << " needs a value\n";
      return 2;
    }
    const std::string v = argv[++i];
    if (a == "--cells")
      cells = std::atoi(v.c_str());
    else if (a == "--steps")
      steps = std::atoi(v.c_str());
    else if (a == "--rounds")
      rounds = std::atoi(v.c_str());
    else if (a == "--threads")
      threads = std::atoi(v.c_str());
    else if (a == "--scheme")
      scheme = v;
    else if (a == "--shape")
      shape = v;
    else {
      std::cerr << "bench_contact: unknown option " << a << '\n';
      return 2;
    }
  }
  if (cells < 16 || steps < 1 || rounds < 1 || threads < 1) {
    std::cerr << "bench_contact: --cells >= 16, --steps, --rounds and --threads >= 1\n";
    return 2;
  }
  mpm::app::register_modules();
  tbb::global_control control(tbb::global_control::max_allowed_parallelism, threads);
  std::vector<double> single, contact, ratio;
  for (int r = 0; r < rounds; ++r) {
    single.push_back(seconds_per_step(scene(cells, scheme, shape, false), steps));
    contact.push_back(seconds_per_step(scene(cells, scheme, shape, true), steps));
    ratio.push_back(contact.back() / single.back());
  }
  auto median = [](std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
  };
  const auto sim = mpm::app::build_simulation<2>(mpm::parse_scene(scene(cells, scheme, shape, true), "b.yaml"));
  std::printf(
      "bench_contact: %s/%s, %lld particles, %d x %d cells, %d threads, %d steps x %d rounds\n"
      "  single field (no contact section): %.3f ms/step (median)\n"
      "  two bodies with contact:           %.3f ms/step (median)\n"
      "  ratio contact / single field:      %.2f (median of the per-round ratios)\n",
      scheme.c_str(), shape.c_str(), static_cast<long long>(sim->particle_count()), cells, cells / 2, threads, steps,
      rounds, 1e3 * median(single), 1e3 * median(contact), median(ratio));
  return 0;
}
