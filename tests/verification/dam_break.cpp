#include "dam_break.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <fmt/format.h>

#include "mpm/app/modules.hpp"
#include "mpm/app/scene_builder.hpp"
#include "mpm/core/stability_error.hpp"
#include "mpm/scene/scene_loader.hpp"

namespace mpm::verification {
namespace {

constexpr double g = 9.81;
constexpr double rho0 = 1000, tait_gamma = 7;

double interpolate(const std::vector<double>& xs, const std::vector<double>& ys, double x) {
  if (xs.empty()) return std::nan("");
  if (x <= xs.front()) return ys.front();
  if (x >= xs.back()) return ys.back();
  const auto it = std::upper_bound(xs.begin(), xs.end(), x);
  const std::size_t i = static_cast<std::size_t>(it - xs.begin());
  const double w = (x - xs[i - 1]) / (xs[i] - xs[i - 1]);
  return (1 - w) * ys[i - 1] + w * ys[i];
}

double time_scale(const DamBreakSpec& s) { return std::sqrt(2 * g / s.width); }  // T = t * time_scale

}  // namespace

double DamBreakResult::front_at(double t) const { return interpolate(T, Z, t); }
double MartinMoyce::front_at(double t) const { return interpolate(T, Z, t); }

std::string dam_break_scene(const DamBreakSpec& s) {
  const double a = s.width, h = a / s.cells_per_width;
  const double U = 2 * std::sqrt(g * s.height_ratio * a), c0 = U / s.mach;
  const double bulk_modulus = rho0 * c0 * c0 / tait_gamma;
  return fmt::format(
      "# Martin & Moyce dam break: column {a} m wide, {n2} times as high; c0 = {c0:.4g} m/s (Mach {mach} at the\n"
      "# shallow-water front speed {U:.4g} m/s), K = rho0 c0^2 / 7.\n"
      "dimension: 2\n"
      "grid:\n"
      "  origin: [0, 0]\n"
      "  extent: [{Lx}, {Ly}]\n"
      "  cell_size: {h}\n"
      "  boundary: {{x_min: slip, x_max: slip, y_min: slip, y_max: slip}}\n"
      "materials:\n"
      "  water: {water}\n"
      "bodies:\n"
      "  - name: column\n"
      "    material: water\n"
      "    shape: {{type: box, min: [0, 0], max: [{a}, {H}]}}\n"
      "    particles_per_cell: {ppc}\n"
      "solver: {{scheme: {scheme}, shape_function: {shape}, flip_fraction: 1, cfl: {cfl}, gravity: [0, -{g}], "
      "end_time: {end:.6g}}}\n"
      "output: {{interval: {interval}, fields: [velocity, pressure, density]}}\n",
      fmt::arg("a", a), fmt::arg("n2", s.height_ratio), fmt::arg("c0", c0), fmt::arg("mach", s.mach), fmt::arg("U", U),
      fmt::arg("Lx", s.tank_length * a), fmt::arg("Ly", s.tank_height * a), fmt::arg("h", h), fmt::arg("rho0", rho0),
      fmt::arg("K", bulk_modulus), fmt::arg("mu", s.viscosity), fmt::arg("H", s.height_ratio * a),
      fmt::arg("ppc", s.particles_per_cell), fmt::arg("scheme", s.scheme), fmt::arg("shape", s.shape_function),
      fmt::arg("cfl", s.cfl), fmt::arg("g", g), fmt::arg("end", s.end_T / time_scale(s)),
      fmt::arg("interval", s.output_interval),
      fmt::arg("water",
               s.incompressible
                   ? fmt::format("{{model: incompressible_fluid, density: {}, viscosity: {}}}", rho0, s.viscosity)
                   : fmt::format("{{model: newtonian_fluid, density: {}, bulk_modulus: {:.6g}, eos_exponent: "
                                 "7, viscosity: {}}}",
                                 rho0, bulk_modulus, s.viscosity)));
}

DamBreakResult run_dam_break(const DamBreakSpec& s) {
  const auto start = std::chrono::steady_clock::now();
  app::register_modules();
  auto sim = app::build_simulation<2>(parse_scene(dam_break_scene(s), "dam_break.yaml"));
  DamBreakResult r;
  const double a = s.width, half_spacing = 0.5 * a / (s.cells_per_width * s.particles_per_cell);
  const double Lx = s.tank_length * a, Ly = s.tank_height * a;
  auto record = [&](const Simulation<2>& sim_now) {
    double front = 0;
    for (const auto& b : sim_now.bodies()) {
      const auto& p = b.particles;
      for (Index i = 0; i < p.size(); ++i) {
        const double x = p.x[i][0], y = p.x[i][1];
        front = std::max(front, x);
        r.inside_tank = r.inside_tank && x >= 0 && x <= Lx && y >= 0 && y <= Ly;
        r.max_density_deviation = std::max(r.max_density_deviation, std::abs(1 / p.F[i].determinant() - 1));
      }
    }
    r.T.push_back(sim_now.time() * time_scale(s));
    r.Z.push_back((front + half_spacing) / a);
  };
  record(*sim);
  try {
    sim->run(record);
  } catch (const StabilityError& e) {
    r.failure = e.what();
  }
  r.steps = sim->step();
  r.particles = sim->particle_count();
  r.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

double largest_front_deviation(const DamBreakResult& run, const MartinMoyce& experiment, double last_T) {
  double worst = 0;
  for (std::size_t i = 0; i < experiment.T.size(); ++i)
    if (experiment.T[i] <= last_T)
      worst = std::max(worst, std::abs(run.front_at(experiment.T[i]) / experiment.Z[i] - 1));
  return worst;
}

MartinMoyce martin_moyce(const std::string& csv_path, double width_inch) {
  std::ifstream in(csv_path);
  if (!in) throw std::runtime_error(csv_path + ": cannot open the Martin & Moyce data");
  MartinMoyce m;
  std::string line;
  bool header = true;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    if (header) {  // a_inch,T,Z
      header = false;
      continue;
    }
    std::replace(line.begin(), line.end(), ',', ' ');
    std::istringstream fields(line);
    double size = 0, T = 0, Z = 0;
    if (!(fields >> size >> T >> Z)) throw std::runtime_error(csv_path + ": bad line '" + line + "'");
    if (std::abs(size - width_inch) < 1e-9) {
      m.T.push_back(T);
      m.Z.push_back(Z);
    }
  }
  return m;
}

}  // namespace mpm::verification
