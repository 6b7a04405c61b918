#include "sod.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "mpm/app/modules.hpp"
#include "mpm/app/scene_builder.hpp"
#include "mpm/core/stability_error.hpp"
#include "mpm/scene/scene_loader.hpp"
#include "sod_exact.hpp"

namespace mpm::verification {

std::string sod_scene(const SodSpec& s) {
  const std::string gas =
      fmt::format("{{model: ideal_gas, gamma: 1.4, artificial_viscosity_linear: {}, artificial_viscosity_quadratic: {}",
                  s.viscosity_linear, s.viscosity_quadratic);
  return fmt::format(
      "dimension: 1\n"
      "grid: {{origin: [0], extent: [1], cell_size: {}, boundary: {{x_min: fixed, x_max: fixed}}}}\n"
      "materials:\n"
      "  left: {}, density: 1, initial_pressure: 1}}\n"
      "  right: {}, density: 0.125, initial_pressure: 0.1}}\n"
      "bodies:\n"
      "  - {{name: high, material: left, shape: {{type: box, min: [0], max: [0.5]}}, particles_per_cell: {}}}\n"
      "  - {{name: low, material: right, shape: {{type: box, min: [0.5], max: [1]}}, particles_per_cell: {}}}\n"
      "solver: {{scheme: {}, shape_function: {}, flip_fraction: {}, cfl: {}, end_time: {}}}\n",
      1.0 / s.cells, gas, gas, s.particles_per_cell, s.particles_per_cell, s.scheme, s.shape_function, s.flip_fraction,
      s.cfl, s.end_time);
}

namespace {

/// L1 distance of (rho, u, p) samples at positions x with weights w from the exact solution at time t.
struct L1 {
  const test::ExactRiemann& exact;
  double t;
  SodErrors sum;
  void add(double x, double w, double rho, double u, double p) {
    const test::GasState ref = exact.sample((x - 0.5) / t);
    sum.density += w * std::abs(rho - ref.rho);
    sum.velocity += w * std::abs(u - ref.u);
    sum.pressure += w * std::abs(p - ref.p);
  }
  SodErrors normalised() const {
    return {sum.density / (1 - 0.125), sum.velocity / exact.u_star(), sum.pressure / (1 - 0.1)};
  }
};

}  // namespace

SodResult run_sod(const SodSpec& s) {
  const auto start = std::chrono::steady_clock::now();
  app::register_modules();
  auto sim = app::build_simulation<1>(parse_scene(sod_scene(s), "sod.yaml"));
  SodResult r;
  const double e0 = sim->energy().total();
  try {
    sim->run();
  } catch (const StabilityError& e) {
    r.failure = e.what();
  }
  r.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  r.steps = sim->step();
  r.particle_count = sim->particle_count();
  r.energy_change = (sim->energy().total() - e0) / e0;

  const test::ExactRiemann exact({1, 0, 1}, {0.125, 0, 0.1}, 1.4);
  const double t = sim->time(), h = 1.0 / s.cells;
  L1 on_particles{exact, t, {}};
  std::vector<double> m(s.cells + 1, 0.0), mv(s.cells + 1, 0.0), mp(s.cells + 1, 0.0);
  for (const auto& b : sim->bodies()) {
    const auto& p = b.particles;
    for (Index i = 0; i < p.size(); ++i) {
      const double x = p.x[i][0], V = p.volume0[i] * p.F[i].determinant();
      const double pressure = -p.stress[i].full()(0, 0);
      r.volume_sum += V;
      on_particles.add(x, V, p.mass[i] / V, p.v[i][0], pressure);
      // hat-function mapping to the two nodes of the particle's cell
      const int c = std::clamp(static_cast<int>(x / h), 0, s.cells - 1);
      const double xi = x / h - c;
      for (const auto& [node, w] : {std::pair{c, 1 - xi}, std::pair{c + 1, xi}}) {
        m[node] += w * p.mass[i];
        mv[node] += w * p.mass[i] * p.v[i][0];
        mp[node] += w * p.mass[i] * pressure;
      }
    }
  }
  L1 on_grid{exact, t, {}};
  for (int I = 1; I < s.cells; ++I)  // interior nodes: a wall node's support is half a cell
    if (m[I] > 0) on_grid.add(I * h, h, m[I] / h, mv[I] / m[I], mp[I] / m[I]);
  r.particles = on_particles.normalised();
  r.grid = on_grid.normalised();
  return r;
}

}  // namespace mpm::verification
