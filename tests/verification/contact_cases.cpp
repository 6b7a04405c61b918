#include "contact_cases.hpp"

#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <limits>

#include "mpm/app/modules.hpp"
#include "mpm/app/scene_builder.hpp"
#include "mpm/core/stability_error.hpp"
#include "mpm/scene/scene_loader.hpp"

namespace mpm::verification {
namespace {

/// Block 0.2 x 0.1 m on the plane y = 0, 30 degrees, mu = 0.2, PIC transfer, to t = 0.4 s; the acceleration
/// is the least-squares slope of the block's mean velocity over t >= 0.1 s.
CaseRun run_incline_block(const std::string& scheme, const std::string& shape, int n) {
  const double g = 9.81, theta = M_PI / 6, mu = 0.2;
  const double h = 0.1 / n;
  const std::string yaml = fmt::format(
      R"(
dimension: 2
grid: {{origin: [0, {o}], extent: [1.2, {e}], cell_size: {h}}}
materials:
  rubber: {{model: linear_elastic, density: 1000, youngs_modulus: 1.0e6, poisson_ratio: 0.3}}
bodies:
  - {{name: block, material: rubber, shape: {{type: box, min: [0.1, 0.0], max: [0.3, 0.1]}}, particles_per_cell: 2}}
solver: {{scheme: {scheme}, shape_function: {shape}, flip_fraction: 0, cfl: 0.4, end_time: 0.4,
         gravity: [{gx}, {gy}]}}
contact:
  planes: [{{point: [0, 0], normal: [0, 1], friction: {mu}}}]
)",
      fmt::arg("o", -4 * h), fmt::arg("e", 0.2 + 4 * h), fmt::arg("h", h), fmt::arg("scheme", scheme),
      fmt::arg("shape", shape), fmt::arg("gx", g * std::sin(theta)), fmt::arg("gy", -g * std::cos(theta)),
      fmt::arg("mu", mu));
  app::register_modules();
  const auto start = std::chrono::steady_clock::now();
  CaseRun run;
  run.h = h;
  auto sim = app::build_simulation<2>(parse_scene(yaml, "incline_block.yaml"));
  run.particles = sim->particle_count();
  double st = 0, sv = 0, stt = 0, stv = 0, count = 0;
  try {
    sim->run([&](const Simulation<2>& s) {
      if (s.time() < 0.1) return;
      const auto& p = s.bodies()[0].particles;
      double mv = 0, m = 0;
      for (Index i = 0; i < p.size(); ++i) mv += p.mass[i] * p.v[i][0], m += p.mass[i];
      const double t = s.time(), v = mv / m;
      st += t, sv += v, stt += t * t, stv += t * v, ++count;
    });
    const double a = (count * stv - st * sv) / (count * stt - st * st);
    const double exact = g * (std::sin(theta) - mu * std::cos(theta));
    run.error = std::abs(a / exact - 1);
  } catch (const StabilityError& e) {
    run.failure = e.what();
    run.error = std::numeric_limits<double>::infinity();
  }
  run.steps = sim->step();
  run.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return run;
}

}  // namespace

void add_contact_cases(std::vector<VerificationCase>& list, bool quick, int refinements) {
  std::vector<int> ladder = quick ? std::vector<int>{5} : std::vector<int>{5, 10, 20};
  for (int r = 0; !quick && r < refinements; ++r) ladder.push_back(2 * ladder.back());
  for (const auto& [scheme, shape] :
       {std::pair<const char*, const char*>{"musl", "linear"}, {"usf", "linear"}, {"musl", "cubic_bspline"}}) {
    add_case(list, "incline_block", 2,
             "rigid-body mechanics: a = g (sin 30 - 0.2 cos 30) = 3.2059 m/s^2 (contact/README.md)",
             "relative error of the sliding acceleration (-)", scheme, shape, ladder,
             [scheme = std::string(scheme), shape = std::string(shape)](int n) {
               return run_incline_block(scheme, shape, n);
             });
  }
}

}  // namespace mpm::verification
