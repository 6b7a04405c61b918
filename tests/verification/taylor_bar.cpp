#include "taylor_bar.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>

#include "mpm/app/modules.hpp"
#include "mpm/app/scene_builder.hpp"
#include "mpm/output_writer.hpp"
#include "mpm/scene_loader.hpp"
#include "mpm/stability_error.hpp"

namespace mpm {
namespace {

constexpr double R0 = 3.2e-3, L0 = 32.4e-3;
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
  const double height = (std::ceil(L0 / s.h - 1e-9) + 1) * s.h;  // one free cell above the bar
  const double radius = std::ceil(8.8e-3 / s.h - 1e-9) * s.h;
  return fmt::format(
             "# Love & Sulsky's Taylor bar (reference 003 §4.1) with an explicit scheme, axisymmetric (x = r, y = z):\n"
             "# copper, R0 = 3.2 mm, L0 = 32.4 mm, 227 m/s onto a rigid frictionless wall at z = 0, J2 with linear\n"
             "# hardening, 80 us. Written by bench_taylor_bar --print-scene (tests/verification/taylor_bar.cpp).\n"
             "dimension: 2\n"
             "grid:\n"
             "  coordinates: axisymmetric\n"
             "  extent: [{:.6g}, {:.6g}]\n"
             "  cell_size: {:.6g}\n"
             "  boundary: {{y_min: slip}}\n"
             "materials:\n"
             "  copper:\n",
             radius, height, s.h) +
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
             "  cfl: {:g}\n"
             "  end_time: {:g}\n"
             "output:\n"
             "  interval: 10.0e-6\n"
             "  fields: [velocity, stress, plastic_strain, pressure, von_mises_stress, displacement]\n",
             s.particles_per_cell, s.scheme, s.shape_function, s.cfl, s.end_time);
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
  try {
    if (writer) writer->write(*sim);
    sim->run([&](const Simulation<2>& s) {
      if (writer) writer->write_if_due(s);
    });
    if (writer) writer->write(*sim);
  } catch (const StabilityError& e) {
    r.failure = e.what();
  }
  r.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  r.steps = sim->step();
  const EnergyBalance e = sim->energy();
  r.energy_error = std::abs(e.total() - e0.total()) / e0.total();
  r.kinetic_fraction = e.kinetic / e0.kinetic;
  const auto [length, radius] = extents(body.particles);
  r.length = length + (L0 - length0);
  r.radius = radius + (R0 - radius0);
  return r;
}

}  // namespace mpm
