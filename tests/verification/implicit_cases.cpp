#include "implicit_cases.hpp"

#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <limits>
#include <numbers>

#include "mpm/app/modules.hpp"
#include "mpm/app/scene_builder.hpp"
#include "mpm/scene_loader.hpp"
#include "mpm/stability_error.hpp"

namespace mpm::verification {
namespace {

/// Max over the run of |v_cm - (2 v0 / pi) cos(2 pi t / 10)| relative to the amplitude (review eq. 6.4), one
/// period; c = 10 m/s, v0 = 1e-3 m/s.
CaseRun bar_mode1_hencky(const std::string& scheme, int cells, double courant) {
  const double L = 25, h = L / cells, c = 10, v0 = 1e-3;
  const double amplitude = 2 * v0 / std::numbers::pi, omega = 2 * std::numbers::pi / 10;
  const std::string yaml = fmt::format(
      "dimension: 1\n"
      "grid: {{origin: [0], extent: [{:.17g}], cell_size: {:.17g}, boundary: {{x_min: fixed}}}}\n"
      "materials: {{bar: {{model: hencky_j2, density: 1, bulk_modulus: 40, shear_modulus: 45}}}}\n"
      "bodies: [{{material: bar, shape: {{type: box, min: [0], max: [25]}}, particles_per_cell: 2,\n"
      "          velocity: [\"{}*sin(_pi*x/50)\"]}}]\n"
      "solver: {{scheme: {}, shape_function: linear, dt: {:.17g}, end_time: 10}}\n",
      h * (cells + 2), h, v0, scheme, courant * h / c);
  CaseRun run;
  run.h = h;
  const auto start = std::chrono::steady_clock::now();
  try {
    app::register_modules();  // hencky_j2 and the implicit scheme
    auto sim = app::build_simulation<1>(parse_scene(yaml, "bar_mode1_hencky_j2"));
    run.particles = sim->particle_count();
    double worst = 0;
    sim->run([&](const Simulation<1>& s) {
      const auto e = s.energy();
      worst = std::max(worst, std::abs(e.momentum[0] / e.mass - amplitude * std::cos(omega * s.time())));
    });
    run.steps = sim->step();
    run.error = worst / amplitude;
  } catch (const StabilityError& e) {
    run.error = std::numeric_limits<double>::infinity();
    run.failure = e.what();
  }
  run.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return run;
}

}  // namespace

void add_implicit_cases(std::vector<VerificationCase>& list, bool quick, int refinements) {
  std::vector<int> ladder = quick ? std::vector<int>{8} : std::vector<int>{8, 16, 32, 64};
  for (int r = 0; !quick && r < refinements; ++r) ladder.push_back(2 * ladder.back());
  const std::string reference = "analytic, review eq. 6.4 (mode 1 of a fixed-free bar), hencky_j2 at strain 1e-4";
  const std::string measure = "max |v_cm - exact| over one period / amplitude (-)";
  add_case(list, "bar_mode1_hencky_j2", 1, reference, measure, "implicit", "linear", ladder,
           [](int n) { return bar_mode1_hencky("implicit", n, 2.0); });
  add_case(list, "bar_mode1_hencky_j2", 1, reference, measure, "musl", "linear", ladder,
           [](int n) { return bar_mode1_hencky("musl", n, 0.1); });
}

}  // namespace mpm::verification
