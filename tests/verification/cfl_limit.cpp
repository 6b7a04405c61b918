#include "cfl_limit.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "mpm/app/scene_builder.hpp"
#include "mpm/core/stability_error.hpp"
#include "mpm/scene/scene_loader.hpp"

namespace mpm::verification {
namespace {

/// Bar of review §6.1.1 (E = 100 Pa, rho = 1, L = 25 m, c = 10 m/s), 32 cells of 0.78125 m, fixed at x = 0,
/// 50 periods: 6400 steps at factor 1, so that a slowly growing instability shows.
std::string bar_yaml(const std::string& scheme, const std::string& shape) {
  const int cells = 32, extra = shape == "linear" ? 2 : 4;
  const double h = 25.0 / cells;
  return fmt::format(
      "dimension: 1\n"
      "grid: {{origin: [0], extent: [{}], cell_size: {}, boundary: {{x_min: fixed}}}}\n"
      "materials: {{bar: {{model: linear_elastic, density: 1, youngs_modulus: 100, poisson_ratio: 0}}}}\n"
      "bodies: [{{material: bar, shape: {{type: box, min: [0], max: [25]}}, particles_per_cell: 2,\n"
      "          velocity: [\"0.1*sin(_pi*x/50)\"]}}]\n"
      "solver: {{scheme: {}, shape_function: {}, cfl: 0.5, end_time: {}}}\n",
      h * (cells + extra), h, scheme, shape, 500.0);
}

/// examples/02_two_disks/scene.yaml with the adaptive time step.
std::string two_disks_yaml(const std::string& scheme, const std::string& shape) {
  return fmt::format(
      "dimension: 2\n"
      "grid: {{origin: [0, 0], extent: [1, 1], cell_size: 0.05}}\n"
      "materials: {{elastic: {{model: linear_elastic, density: 1000, youngs_modulus: 1000, poisson_ratio: 0.3}}}}\n"
      "bodies:\n"
      "  - {{name: lower_left, material: elastic, shape: {{type: disk, center: [0.2, 0.2], radius: 0.2}},\n"
      "     particles_per_cell: 2, velocity: [0.1, 0.1]}}\n"
      "  - {{name: upper_right, material: elastic, shape: {{type: disk, center: [0.8, 0.8], radius: 0.2}},\n"
      "     particles_per_cell: 2, velocity: [-0.1, -0.1]}}\n"
      "solver: {{scheme: {}, shape_function: {}, flip_fraction: 1.0, cfl: 0.5, end_time: 3.5}}\n",
      scheme, shape);
}

/// Energy growth that counts as unstable. The time integration alone makes the energy of the resolved
/// modes oscillate by a few per cent at factors near 1 (1% on the bar already at 0.36): a smaller limit
/// would measure accuracy, not stability.
constexpr double growth_limit = 0.1;

template <int Dim>
CflProbe run(const std::string& yaml, const std::string& name, double cfl) {
  CflProbe p;
  p.cfl = cfl;
  auto sim = app::build_simulation<Dim>(parse_scene(yaml, name));
  const double e0 = sim->energy().total(), end = sim->settings().end_time;
  try {
    while (sim->time() < end - 1e-9 * end) {
      sim->advance(std::min(cfl * sim->stable_time_step(), end - sim->time()));
      p.max_energy_growth = std::max(p.max_energy_growth, (sim->energy().total() - e0) / std::abs(e0));
      if (p.max_energy_growth > growth_limit) {
        p.failure = fmt::format("total energy grew by {:.3g} of E0 at t = {:.4g} s", p.max_energy_growth, sim->time());
        break;
      }
    }
  } catch (const StabilityError& e) {
    p.failure = e.what();
  }
  p.steps = sim->step();
  p.stable = p.failure.empty();
  return p;
}

}  // namespace

std::vector<std::string> cfl_problems() { return {"bar", "two_disks"}; }

CflProbe probe_cfl(const std::string& problem, const std::string& scheme, const std::string& shape, double cfl) {
  if (problem == "bar") return run<1>(bar_yaml(scheme, shape), "cfl_bar.yaml", cfl);
  if (problem == "two_disks") {
    if (scheme == "tlmpm")
      throw std::invalid_argument(
          "two_disks: not a test of TLMPM (no contact between bodies: the disks pass through "
          "each other undeformed)");
    return run<2>(two_disks_yaml(scheme, shape), "cfl_two_disks.yaml", cfl);
  }
  throw std::invalid_argument("unknown CFL problem '" + problem + "' (bar, two_disks)");
}

CflLimit largest_stable_cfl(const std::string& problem, const std::string& scheme, const std::string& shape,
                            double step, double max, int refinements) {
  CflLimit limit{problem, scheme, shape};
  double stable = 0, unstable = 0;
  for (int k = 1; k * step <= max + 1e-12; ++k) {
    const CflProbe p = probe_cfl(problem, scheme, shape, k * step);
    limit.probes.push_back(p);
    if (!p.stable) {
      unstable = p.cfl;
      limit.failure = p.failure;
      break;
    }
    stable = p.cfl;
  }
  for (int r = 0; unstable > 0 && r < refinements; ++r) {
    const CflProbe p = probe_cfl(problem, scheme, shape, 0.5 * (stable + unstable));
    limit.probes.push_back(p);
    if (p.stable) {
      stable = p.cfl;
    } else {
      unstable = p.cfl;
      limit.failure = p.failure;
    }
  }
  limit.largest_stable = stable;
  limit.smallest_unstable = unstable;
  return limit;
}

}  // namespace mpm::verification
