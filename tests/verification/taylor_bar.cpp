#include "taylor_bar.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>

#include "mpm/app/modules.hpp"
#include "mpm/app/scene_builder.hpp"
#include "mpm/core/stability_error.hpp"
#include "mpm/output/output_writer.hpp"
#include "mpm/plasticity/field_keys.hpp"
#include "mpm/scene/scene_loader.hpp"

namespace mpm {
namespace {

constexpr double bar_radius0 = 3.2e-3, bar_length0 = 32.4e-3;
constexpr double E = 116.9e9, nu = 0.35;  // the scene text gives rho = 8930 kg/m^3, sigma_Y = 0.4 GPa, H = 0.1 GPa

/// Axial extent and largest radius of the particle centres (r = x, z = y).
std::pair<double, double> extents(const ParticleSet<2>& p) {
  double z_min = 1e300, z_max = -1e300, r_max = 0;
  for (Index i = 0; i < p.size(); ++i) {
    z_min = std::min(z_min, p.x[i][1]);
    z_max = std::max(z_max, p.x[i][1]);
    r_max = std::max(r_max, p.x[i][0]);
  }
  return {z_max - z_min, r_max};
}

std::string material(const std::string& model) {
  if (model == "hencky_j2")  // K = E / (3 (1 - 2 nu)), G = E / (2 (1 + nu))
    return fmt::format(
        "    model: hencky_j2\n"
        "    density: 8930             # kg/m^3\n"
        "    bulk_modulus: {:.6g}e9   # Pa, E / (3 (1 - 2 nu)) with E = 116.9 GPa, nu = 0.35\n"
        "    shear_modulus: {:.6g}e9  # Pa, E / (2 (1 + nu))\n"
        "    yield_stress: 0.4e9       # Pa\n"
        "    hardening_modulus: 0.1e9  # Pa, linear\n",
        E / (3 * (1 - 2 * nu)) / 1e9, E / (2 * (1 + nu)) / 1e9);
  return "    model: " + model +
         "\n"
         "    density: 8930             # kg/m^3\n"
         "    youngs_modulus: 116.9e9   # Pa\n"
         "    poisson_ratio: 0.35\n"
         "    yield_stress: 0.4e9       # Pa\n"
         "    hardening_modulus: 0.1e9  # Pa, linear\n";
}

}  // namespace

std::string taylor_bar_scene(const TaylorBarSpec& s) {
  const double h_z = s.h_z > 0 ? s.h_z : s.h;
  double height = (std::ceil(bar_length0 / h_z - 1e-9) + 1) * h_z;  // one free cell above the bar
  double radius = std::ceil(8.8e-3 / s.h - 1e-9) * s.h;
  if (s.paper_box) height = bar_length0, radius = 7.2e-3;
  const bool implicit = s.scheme == "implicit";
  const std::string cell_size = h_z == s.h ? fmt::format("{:.6g}", s.h) : fmt::format("[{:.6g}, {:.6g}]", s.h, h_z);
  const std::string step =
      implicit ? fmt::format("  dt: {:g}\n  implicit: {{max_newton_iterations: {}}}\n", s.dt, s.max_newton_iterations)
               : fmt::format("  cfl: {:g}\n", s.cfl);
  return fmt::format(
             "# Love & Sulsky's Taylor bar (reference 003 §4.1) with {}, axisymmetric (x = r, y = z):\n"
             "# copper, R0 = 3.2 mm, L0 = 32.4 mm, 227 m/s onto a rigid frictionless wall at z = 0, J2 with linear\n"
             "# hardening, 80 us. Written by bench_taylor_bar --print-scene (tests/verification/taylor_bar.cpp).\n"
             "dimension: 2\n"
             "grid:\n"
             "  coordinates: axisymmetric\n"
             "  extent: [{:.6g}, {:.6g}]\n"
             "  cell_size: {}\n"
             "  boundary: {{y_min: slip}}\n"
             "materials:\n"
             "  copper:\n",
             implicit ? "the implicit scheme" : "an explicit scheme", radius, height, cell_size) +
         material(s.model) +
         fmt::format(
             "bodies:\n"
             "  - name: bar\n"
             "    material: copper\n"
             "    shape: {{type: box, min: [0, 0], max: [3.2e-3, 32.4e-3]}}\n"
             "    particles_per_cell: {}\n"
             "    velocity: [0, -227]\n"
             "solver:\n"
             "  scheme: {}\n"
             "  shape_function: {}\n"
             "{}"
             "  end_time: {:g}\n"
             "output:\n"
             "  interval: 10.0e-6\n"
             "  fields: [velocity, stress, plastic_strain, pressure, von_mises_stress, displacement]\n",
             s.particles_per_cell, s.scheme, s.shape_function, step, s.end_time);
}

TaylorBarResult run_taylor_bar(const TaylorBarSpec& spec) {
  app::register_modules();
  TaylorBarResult r;
  auto sim = app::build_simulation<2>(parse_scene(taylor_bar_scene(spec), "taylor_bar.yaml"));
  auto& body = sim->bodies()[0];
  r.particles = body.particles.size();
  const auto [length0, radius0] = extents(body.particles);
  const EnergyBalance e0 = sim->energy();
  std::unique_ptr<OutputWriter<2>> writer;
  if (!spec.output_directory.empty())
    writer = std::make_unique<OutputWriter<2>>(spec.output_directory, "particles",
                                               std::vector<std::string>{"velocity", "stress", "plastic_strain",
                                                                        "pressure", "von_mises_stress", "displacement"},
                                               false, 10e-6);
  const auto start = std::chrono::steady_clock::now();
  const std::clock_t cpu_start = std::clock();
  std::clock_t audit_clock = 0;
  double previous = e0.kinetic + e0.strain;
  // solver.csv's columns (scheme implicit), found by name
  const std::vector<std::string> columns = sim->scheme().step_log_columns();
  const auto column = [&](const std::string& name) {
    return static_cast<std::size_t>(std::find(columns.begin(), columns.end(), name) - columns.begin());
  };
  try {
    if (writer) writer->write(*sim);
    sim->run([&](const Simulation<2>& s) {
      if (writer) writer->write_if_due(s);
      const std::clock_t audit_start = std::clock();  // the runner's own per-step audit: not the method's cost
      struct Audit {
        std::clock_t start;
        std::clock_t& total;
        ~Audit() { total += std::clock() - start; }
      } audit{audit_start, audit_clock};
      const EnergyBalance e = s.energy();
      r.largest_rise = std::max(r.largest_rise, (e.kinetic + e.strain - previous) / e0.total());
      previous = e.kinetic + e.strain;
      const std::vector<double> row = s.scheme().step_log_row();
      if (row.size() != columns.size() || columns.empty()) return;
      const int newton = static_cast<int>(row[column("newton_iterations")]);
      r.newton += newton, r.max_newton = std::max(r.max_newton, newton);
      r.gmres += static_cast<long long>(row[column("gmres_iterations")]);
      r.residuals += static_cast<long long>(row[column("residual_evaluations")]);
      r.projection_seconds += row[column("projection_seconds")];
      r.residual_seconds += row[column("residual_seconds")];
      r.factorization_seconds += row[column("factorization_seconds")];
    });
    if (writer) writer->write(*sim);
  } catch (const StabilityError& e) {
    r.failure = e.what();
  }
  r.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  r.cpu_seconds = static_cast<double>(std::clock() - cpu_start - audit_clock) / CLOCKS_PER_SEC;
  r.simulated_time = sim->time();
  r.steps = sim->step();
  const EnergyBalance e = sim->energy();
  r.energy_error = std::abs(e.total() - e0.total()) / e0.total();
  r.kinetic_fraction = e.kinetic / e0.kinetic;
  r.plastic_work_fraction = e.plastic_work / e0.total();
  // the equivalent plastic strain: at the impact-face particle nearest the axis, and the largest
  const auto& p = body.particles;
  std::vector<double> strain(static_cast<std::size_t>(p.size()), 0);
  if (p.has_field(plasticity::keys::hencky_j2_state<2>)) {
    const auto& states = p.field(plasticity::keys::hencky_j2_state<2>);
    for (Index i = 0; i < p.size(); ++i) strain[i] = states[i].xi;
  } else if (p.has_field(plasticity::keys::plastic_state<2>)) {
    const auto& states = p.field(plasticity::keys::plastic_state<2>);
    for (Index i = 0; i < p.size(); ++i) strain[i] = states[i].plastic_strain;
  }
  double z_min = 1e300;
  for (Index i = 0; i < p.size(); ++i) {
    r.largest_plastic_strain = std::max(r.largest_plastic_strain, strain[i]);
    z_min = std::min(z_min, p.x[i][1]);
  }
  const double layer = 0.25 * (spec.h_z > 0 ? spec.h_z : spec.h) / spec.particles_per_cell;  // the bottom layer
  double r_face = 1e300;
  for (Index i = 0; i < p.size(); ++i)
    if (p.x[i][1] < z_min + layer && p.x[i][0] < r_face) r_face = p.x[i][0], r.face_plastic_strain = strain[i];
  const auto [length, radius] = extents(body.particles);
  r.length = length + (bar_length0 - length0);
  r.radius = radius + (bar_radius0 - radius0);
  return r;
}

}  // namespace mpm
