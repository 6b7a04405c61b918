#include "hertz_sphere.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>
#include <vector>

#include "mpm/app/modules.hpp"
#include "mpm/app/scene_builder.hpp"
#include "mpm/contact/multi_velocity_contact.hpp"
#include "mpm/core/stability_error.hpp"
#include "mpm/scene/scene_loader.hpp"

namespace mpm::verification {
namespace {

constexpr double R = 0.1, E = 1e7, nu = 0.3, rho = 1000, v0 = 1;

double axial_momentum(const Body<2>& body) {
  double p = 0;
  for (Index i = 0; i < body.particles.size(); ++i) p += body.particles.mass[i] * body.particles.v[i][1];
  return p;
}

}  // namespace

HertzResult run_hertz_sphere(const HertzSpec& s) {
  HertzResult r;
  const double Es = E / (1 - nu * nu), m = rho * 4.0 / 3 * std::numbers::pi * R * R * R;
  r.exact_duration = 2.87 * std::pow(m * m / (R * Es * Es * v0), 0.2);
  const double delta = std::pow(15 * m * v0 * v0 / (16 * Es * std::sqrt(R)), 0.4);
  r.exact_peak = 4.0 / 3 * Es * std::sqrt(R) * std::pow(delta, 1.5);
  const double h = R / s.cells_per_radius;
  const std::string yaml = fmt::format(
      "dimension: 2\n"
      "grid: {{coordinates: axisymmetric, origin: [0, {0:.17g}], extent: [{1:.17g}, {2:.17g}], cell_size: {3:.17g}}}\n"
      "materials: {{rubber: {{model: linear_elastic, density: {4}, youngs_modulus: {5}, poisson_ratio: {6}}}}}\n"
      "bodies:\n"
      "  - {{name: ball, material: rubber, shape: {{type: disk, center: [0, {7:.17g}], radius: {8}}},\n"
      "     particles_per_cell: {9}, velocity: [0, -{10}]}}\n"
      "solver: {{scheme: {11}, shape_function: {12}, cfl: 0.4, end_time: {13:.17g}}}\n"
      "contact: {{onset: {14}, planes: [{{name: floor, point: [0, 0], normal: [0, 1]}}]}}\n",
      -4 * h, R + 8 * h, 2 * R + 12 * h, h, rho, E, nu, R + 0.25 * h, R, s.particles_per_cell, v0, s.scheme,
      s.shape_function, 1.3 * r.exact_duration, s.onset);
  std::vector<double> time, force;  // end of each step, contact force of the step
  const auto start = std::chrono::steady_clock::now();
  try {
    app::register_modules();
    auto sim = app::build_simulation<2>(parse_scene(yaml, "hertz_sphere.yaml"));
    r.particles = sim->particle_count();
    contact::MultiVelocityContact<2>* contact = nullptr;
    for (const auto& module : sim->modules())
      if (auto* c = dynamic_cast<contact::MultiVelocityContact<2>*>(module.get())) contact = c;
    const double p0 = axial_momentum(sim->bodies()[0]);
    sim->run([&](const Simulation<2>& state) {
      double f = 0;
      for (const auto& pair : contact->last_forces())
        if (pair.body == 0 && pair.other == -1) f = pair.normal;  // on the ball from the plane
      time.push_back(state.time());
      force.push_back(f);
    });
    r.steps = sim->step();
    r.momentum_change = axial_momentum(sim->bodies()[0]) - p0;
    r.rebound = r.momentum_change / m - v0;
  } catch (const StabilityError& e) {
    r.failure = e.what();
  }
  r.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  // Window averages of the force (its impulse over each window / the window).
  std::vector<double> mean(static_cast<std::size_t>(std::ceil(1.3 * r.exact_duration / s.window)) + 1, 0.0);
  for (std::size_t k = 0; k < time.size(); ++k) {
    const double dt = time[k] - (k ? time[k - 1] : 0);
    r.impulse += force[k] * dt;
    mean[std::min(mean.size() - 1, static_cast<std::size_t>(time[k] / s.window))] += force[k] * dt / s.window;
  }
  r.peak = *std::max_element(mean.begin(), mean.end());
  std::size_t first = mean.size(), last = 0;
  for (std::size_t k = 0; k < mean.size(); ++k)
    if (mean[k] > 0.02 * r.peak) first = std::min(first, k), last = k;
  if (first <= last) r.duration = (last - first + 1) * s.window;
  return r;
}

}  // namespace mpm::verification
