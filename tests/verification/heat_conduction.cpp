#include "heat_conduction.hpp"

#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <numbers>

#include "mpm/app/modules.hpp"
#include "mpm/app/scene_builder.hpp"
#include "mpm/core/stability_error.hpp"
#include "mpm/scene/scene_loader.hpp"
#include "mpm/shape/shape_functions.hpp"

namespace mpm::verification {

double heat_bar_exact(double x, double t) {
  // eq. 5.27 with T0 = 0, T1 = 1: x + 2 sum (-1)^n / (n pi) exp(-(n pi)^2 t) sin(n pi x)
  double T = x;
  for (int n = 1; n <= 400; ++n) {
    const double a = n * std::numbers::pi;
    T += 2 * (n % 2 ? -1.0 : 1.0) / a * std::exp(-a * a * t) * std::sin(a * x);
  }
  return T;
}

double heat_plate_exact(double x, double y, double t) {
  // eq. 5.28 with T0 = 0, T1 = 100, L = H = 1: T1 + 16 (T0 - T1)/pi^2 sum_{i,j odd} e^{-pi^2 (i^2 + j^2) t}/(ij)
  // sin(i pi x) sin(j pi y)
  const double pi = std::numbers::pi;
  double s = 0;
  for (int i = 1; i <= 199; i += 2)
    for (int j = 1; j <= 199; j += 2)
      s += std::exp(-pi * pi * (i * i + j * j) * t) / (i * j) * std::sin(i * pi * x) * std::sin(j * pi * y);
  return 100 - 1600 / (pi * pi) * s;
}

namespace {

/// T_h(x_I) = sum_J phi_J(x_I) T_J at every node, for the grid functions (the others: T_I, their grid basis is
/// the hat).
template <int Dim>
std::vector<double> field_at_nodes(const std::string& shape, const GridGeometry<Dim>& g, const std::vector<Real>& T) {
  std::vector<double> field(T.begin(), T.end());
  dispatch_shape(shape, [&]<class Shape>() {
    if constexpr (shape_exists_in<Shape, Dim> && !shape_uses_domain<Shape> && !shape_corner_domain<Shape>) {
      Stencil<Dim, Shape> st;
      for (Index n = 0; n < g.node_count(); ++n) {
        st.compute(g.node_position(g.node_indices(n)), g);
        field[n] = 0;
        for (int a = 0; a < st.count; ++a) field[n] += st.w[a] * T[st.node[a]];
      }
    }
  });
  return field;
}

template <int Dim>
std::string scene_yaml(const HeatSpec& s) {
  const double h = 1.0 / s.cells;
  std::string yaml = fmt::format(
      "dimension: {0}\n"
      "grid: {{origin: [{1}], extent: [{2}], cell_size: {3}}}\n"
      "materials: {{m: {{model: linear_elastic, density: 1, youngs_modulus: 1.0e-9, poisson_ratio: 0,\n"
      "                 specific_heat: 1, thermal_conductivity: 1}}}}\n"
      "bodies: [{{material: m, shape: {{type: box, min: [{1}], max: [{2}]}}, particles_per_cell: {4}}}]\n"
      "solver: {{scheme: {5}, shape_function: {6}, cfl: {7}, end_time: {8}}}\n"
      "thermal:\n"
      "  initial_temperature: 0\n",
      Dim, Dim == 1 ? "0" : "0, 0", Dim == 1 ? "1" : "1, 1", h, s.particles_per_cell, s.scheme, s.shape_function, s.cfl,
      s.end_time);
  if (s.stretch_rate != 0)  // the body's velocity, v = a x
    yaml.replace(yaml.find("particles_per_cell"), 0, fmt::format("velocity: [\"{} * x\"], ", s.stretch_rate));
  if (Dim == 1) {
    yaml += "  boundary: {x_min: {temperature: 0}, x_max: {temperature: 1}}\n";
  } else if (!s.particle_boundary) {
    yaml +=
        "  boundary: {x_min: {temperature: 100}, x_max: {temperature: 100}, y_min: {temperature: 100}, "
        "y_max: {temperature: 100}}\n";
  } else {  // the particles of the boundary cells (review §5.3.3)
    yaml += fmt::format(
        "  fixed_temperature:\n"
        "    - {{min: [0, 0], max: [{0}, 1], temperature: 100}}\n"
        "    - {{min: [{1}, 0], max: [1, 1], temperature: 100}}\n"
        "    - {{min: [0, 0], max: [1, {0}], temperature: 100}}\n"
        "    - {{min: [0, {1}], max: [1, 1], temperature: 100}}\n",
        h, 1 - h);
  }
  return yaml;
}

template <int Dim>
HeatResult run(const HeatSpec& s) {
  app::register_modules();
  HeatResult r;
  r.h = 1.0 / s.cells;
  const auto start = std::chrono::steady_clock::now();
  try {
    auto sim = app::build_simulation<Dim>(parse_scene(scene_yaml<Dim>(s), "heat_conduction.yaml"));
    r.particles = sim->particle_count();
    r.dt = sim->next_time_step();
    sim->run();
    r.steps = sim->step();
    r.thermal_energy = sim->energy().thermal;
    const auto& T = sim->grid().node_fields.at("temperature");
    const auto& g = sim->grid().geometry;
    const double scale = Dim == 1 ? 1.0 : 100.0;
    const std::vector<double> field = field_at_nodes<Dim>(s.shape_function, g, T);
    for (Index n = 0; n < g.node_count(); ++n) {
      const auto ijk = g.node_indices(n);
      const double x = ijk[0] * r.h, y = Dim > 1 ? ijk[1] * r.h : 0;
      const double a = s.stretch_rate, tau = a != 0 ? std::log1p(a * sim->time()) / a : sim->time();
      const double exact = Dim == 1 ? heat_bar_exact(x, tau) : heat_plate_exact(x, y, tau);
      r.max_error = std::max(r.max_error, std::abs(T[n] - exact) / scale);
      r.max_field_error = std::max(r.max_field_error, std::abs(field[n] - exact) / scale);
      const bool probe = ijk[0] * 2 == s.cells && (Dim == 1 || ijk[1] * 2 == s.cells);
      if (probe) {
        r.probe = T[n];
        r.probe_exact = exact;
      }
    }
  } catch (const StabilityError& e) {
    r.failure = e.what();
  }
  r.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

}  // namespace

HeatResult run_heat(const HeatSpec& spec) { return spec.dimension == 1 ? run<1>(spec) : run<2>(spec); }

}  // namespace mpm::verification
