#include "axisymmetric_cases.hpp"

#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "mpm/app/modules.hpp"
#include "mpm/app/scene_builder.hpp"
#include "mpm/core/stability_error.hpp"
#include "mpm/scene/scene_loader.hpp"

namespace mpm::verification {

double radial_mode_root(double nu) {
  // f(x) = x J0(x) - q J1(x) falls from x J0 ~ x (1 - q/2) ... through 0 before the first zero of J0 (2.405):
  // bisection on [0.5, 2.4048] (f > 0 near 0.5 for q < 1, f < 0 at J0's zero where J1 > 0).
  const double q = (1 - 2 * nu) / (1 - nu);
  auto f = [&](double x) { return x * std::cyl_bessel_j(0.0, x) - q * std::cyl_bessel_j(1.0, x); };
  double lo = 0.5, hi = 2.404825557695773;
  for (int k = 0; k < 200; ++k) {
    const double mid = 0.5 * (lo + hi);
    (f(mid) > 0 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

double cylinder_cooling_centre(double tau) {
  // beta_n: the zeros of J0, by Newton from McMahon's estimate (n - 1/4) pi; J0(0) = 1 at the centre.
  double sum = 0;
  for (int n = 1; n <= 60; ++n) {
    double b = (n - 0.25) * std::numbers::pi;
    for (int k = 0; k < 20; ++k) b += std::cyl_bessel_j(0.0, b) / std::cyl_bessel_j(1.0, b);  // J0' = -J1
    sum += 2 / (b * std::cyl_bessel_j(1.0, b)) * std::exp(-b * b * tau);
  }
  return sum;
}

namespace {

/// Cells beyond the body on the free side: the B-splines and GIMP reach further than the hats.
int margin_cells(const std::string& shape) { return shape == "linear" ? 2 : 4; }

/// Builds and runs a simulation step by step: `observe(sim, result, first)` is called before the first step
/// (first = true) and after every step, and returns false to stop; the guard's message ends the run too.
template <class Build, class Observe>
AxisymmetricResult timed(double h, Build&& build, Observe&& observe) {
  AxisymmetricResult r;
  r.h = h;
  const auto start = std::chrono::steady_clock::now();
  try {
    app::register_modules();
    auto sim = build();
    r.particles = sim->particle_count();
    observe(*sim, r, true);
    while (observe(*sim, r, false) && !sim->finished()) sim->advance(sim->next_time_step());
    r.steps = sim->step();
  } catch (const StabilityError& e) {
    r.failure = e.what();
  }
  r.error = r.failure.empty() ? std::abs(r.value - r.exact) / r.exact : std::numeric_limits<double>::infinity();
  r.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

}  // namespace

AxisymmetricResult run_radial_vibration(const AxisymmetricSpec& s) {
  const double R = 1, E = 100, nu = 0.3, rho = 1;
  const double h = R / s.cells, height = 4 * h;
  const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
  const double c_L = std::sqrt((lambda + 2 * mu) / rho), kappa = radial_mode_root(nu) / R;
  const double period = 2 * std::numbers::pi / (kappa * c_L);
  const std::string yaml = fmt::format(
      "dimension: 2\n"
      "grid: {{coordinates: axisymmetric, extent: [{0:.17g}, {1:.17g}], cell_size: {2:.17g},\n"
      "       boundary: {{y_min: slip, y_max: slip}}}}\n"
      "materials: {{m: {{model: linear_elastic, density: {3}, youngs_modulus: {4}, poisson_ratio: {5}}}}}\n"
      "bodies: [{{material: m, shape: {{type: box, min: [0, 0], max: [{6:.17g}, {1:.17g}]}}, particles_per_cell: "
      "{7}}}]\n"
      "solver: {{scheme: {8}, shape_function: {9}, cfl: {10}, end_time: {11:.17g}}}\n",
      (s.cells + margin_cells(s.shape_function)) * h, height, h, rho, E, nu, R, s.particles_per_cell, s.scheme,
      s.shape_function, s.cfl, 1.6 * period);
  // The period from the zero crossings of sum m v_r, which starts at its maximum (cos): t1 = T/4, t3 = 5T/4.
  std::vector<double> crossings;
  double last_time = 0, last_value = 0;
  return timed(
      h, [&] { return app::build_simulation<2>(parse_scene(yaml, "radial_vibration.yaml")); },
      [&](Simulation<2>& sim, AxisymmetricResult& r, bool first) {
        auto& p = sim.bodies()[0].particles;
        if (first) {  // the mode shape (muparser has no Bessel functions)
          for (Index i = 0; i < p.size(); ++i)
            p.v[i] = Vec<2>(1e-3 * c_L * std::cyl_bessel_j(1.0, kappa * p.x[i][0]), 0);
          r.exact = period;
        }
        double value = 0;
        for (Index i = 0; i < p.size(); ++i) value += p.mass[i] * p.v[i][0];
        if (!first && (value < 0) != (last_value < 0))
          crossings.push_back(last_time + (sim.time() - last_time) * last_value / (last_value - value));
        last_time = sim.time();
        last_value = value;
        if (crossings.size() < 3) return true;
        r.value = crossings[2] - crossings[0];
        return false;
      });
}

AxisymmetricResult run_cylinder_cooling(const AxisymmetricSpec& s) {
  const double R = 1, tau = 0.2, h = R / s.cells;
  const std::string yaml = fmt::format(
      "dimension: 2\n"
      "grid: {{coordinates: axisymmetric, extent: [1, {0:.17g}], cell_size: {1:.17g}}}\n"
      "materials: {{m: {{model: linear_elastic, density: 1, youngs_modulus: 1.0e-9, poisson_ratio: 0,\n"
      "                 specific_heat: 1, thermal_conductivity: 1}}}}\n"
      "bodies: [{{material: m, shape: {{type: box, min: [0, 0], max: [1, {0:.17g}]}}, particles_per_cell: {2}}}]\n"
      "solver: {{scheme: {3}, shape_function: {4}, cfl: {5}, end_time: {6}}}\n"
      "thermal: {{initial_temperature: 1, boundary: {{x_max: {{temperature: 0}}}}}}\n",
      4 * h, h, s.particles_per_cell, s.scheme, s.shape_function, s.cfl, tau * R * R);
  return timed(
      h, [&] { return app::build_simulation<2>(parse_scene(yaml, "cylinder_cooling.yaml")); },
      [&](Simulation<2>& sim, AxisymmetricResult& r, bool first) {
        if (first) r.exact = cylinder_cooling_centre(tau);
        if (!sim.finished()) return true;
        r.value = sim.grid().node_fields.at("temperature")[0];  // the node r = 0, z = 0 (insulated ends: 1D in r)
        return false;
      });
}

namespace {

CaseRun case_run(const AxisymmetricResult& r) {
  CaseRun run;
  run.error = r.error;
  run.failure = r.failure;
  run.wall_seconds = r.wall_seconds;
  run.steps = r.steps;
  run.particles = r.particles;
  run.h = r.h;
  return run;
}

}  // namespace

void add_axisymmetric_cases(std::vector<VerificationCase>& list, bool quick, int refinements) {
  std::vector<int> ladder{8, 16, 32};
  if (quick) ladder.resize(1);
  for (int r = 0; !quick && r < refinements; ++r) ladder.push_back(2 * ladder.back());
  for (const std::string scheme : {"usl", "musl", "usf", "tlmpm"})
    for (const std::string shape : {"linear", "quadratic_bspline", "cubic_bspline", "cpgimp"})
      add_case(list, "radial_vibration_axisym", 2,
               "first root of x J0(x)/J1(x) = (1 - 2 nu)/(1 - nu), period 2 pi R / (x c_L) (Graff 1975, §8.2)",
               "|period - exact| / exact (-)", scheme, shape, ladder, [scheme, shape](int n) {
                 AxisymmetricSpec s;
                 s.scheme = scheme;
                 s.shape_function = shape;
                 s.cells = n;
                 return case_run(run_radial_vibration(s));
               });
#ifdef MPM_WITH_THERMAL
  for (const std::string shape : {"linear", "cubic_bspline", "cpgimp"})
    add_case(list, "cylinder_cooling_axisym", 2, "Bessel series, Carslaw & Jaeger 1959 §7.4 (alpha t / R^2 = 0.2)",
             "|T_centre - exact| / exact (-)", "musl", shape, ladder, [shape](int n) {
               AxisymmetricSpec s;
               s.shape_function = shape;
               s.cells = n;
               s.cfl = 0.8;
               return case_run(run_cylinder_cooling(s));
             });
#endif
}

}  // namespace mpm::verification
