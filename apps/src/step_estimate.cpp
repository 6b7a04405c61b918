#include "mpm/app/step_estimate.hpp"

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <limits>

#include "mpm/app/key_location.hpp"
#include "mpm/scene/scene_error.hpp"
#include "mpm/scene/scene_limits.hpp"

namespace mpm::app {
namespace {

/// A wave crossing the grid more often than this in one run means the end time, not the time step, is the typo...
constexpr double max_crossings = 1e4;
/// ...unless the governing speed is beyond any physical one (the fastest solids' waves are about 1.8e4 m/s, diamond;
/// hypervelocity impacts about 1e4 m/s): then the speed's key is named.
constexpr double max_plausible_speed = 1e5;

/// The body whose CFL bound (eq. 2.73) is the smallest, the axis of it, and the parts of its speed there.
template <int Dim>
struct GoverningBody {
  int body = -1;
  int axis = 0;
  Real dt = std::numeric_limits<Real>::infinity();
  Real speed = 0;     ///< c + |v|, m/s
  Real velocity = 0;  ///< |v|, m/s
};

template <int Dim>
GoverningBody<Dim> governing_body(const Simulation<Dim>& sim) {
  GoverningBody<Dim> g;
  const auto& h = sim.grid().geometry.h;
  for (std::size_t b = 0; b < sim.bodies().size(); ++b) {
    const auto& body = sim.bodies()[b];
    const auto bound = body.material->wave_speed_bound(body.particles);
    Vec<Dim> v = Vec<Dim>::Zero();
    for (const auto& vp : body.particles.v) v = v.cwiseMax(Vec<Dim>(vp.cwiseAbs()));
    for (int d = 0; d < Dim; ++d)
      if (bound.max_speed[d] > 0 && h[d] / bound.max_speed[d] < g.dt)
        g = {static_cast<int>(b), d, h[d] / bound.max_speed[d], bound.max_speed[d], v[d]};
  }
  return g;
}

}  // namespace

template <int Dim>
StepEstimate estimate_steps(const SceneDescription& scene, const Simulation<Dim>& sim) {
  StepEstimate e;
  e.dt = sim.next_time_step();
  e.steps = scene.solver.end_time / e.dt;
  e.wall_seconds = e.steps * static_cast<double>(sim.particle_count()) / assumed_particle_updates_per_second;
  const auto g = governing_body(sim);
  const std::string limiter = sim.time_step_limiter();
  const bool cfl_governs = std::isfinite(g.dt) && limiter.rfind("CFL", 0) == 0;
  // How often the fastest wave crosses the grid in the run: beyond max_crossings the end time is the typo.
  const double extent = cfl_governs ? scene.grid.extent[g.axis] : 0;
  const double passes = cfl_governs && extent > 0 ? scene.solver.end_time * g.speed / extent : 0;
  if (passes > max_crossings && g.speed <= max_plausible_speed) {
    e.key = "solver.end_time";
    e.where = locate_key(scene, {"solver", "end_time"});
    e.reason = fmt::format(
        "end_time = {:.6g} s is {:.3g} times the {:.3g} s a wave at {:.4g} m/s takes to cross the "
        "grid",
        scene.solver.end_time, passes, extent / g.speed, g.speed);
  } else if (scene.solver.dt) {
    e.key = "solver.dt";
    e.where = scene.solver.dt_where;
    e.reason = fmt::format("the fixed time step dt = {:.6g} s (stable bound {:.6g} s)", e.dt, sim.stable_time_step());
  } else if (!cfl_governs) {
    e.where = locate_key(scene, {"solver"});
    e.reason = fmt::format("the time step {:.6g} s is set by the {}", e.dt, limiter);
  } else {
    const auto& bd = scene.bodies[g.body];
    const char* axis = std::array{"x", "y", "z"}[g.axis];
    if (g.velocity > g.speed - g.velocity) {  // the body's speed, not its material's wave speed, governs
      e.key = fmt::format("bodies[{}].velocity", g.body);
      e.where = locate_body_key(scene, bd.where, "velocity");
      e.reason = fmt::format(
          "the CFL bound h / (c + |v|) (eq. 2.73) is governed by the velocity of body '{}': "
          "|v_{}| = {:.4g} m/s, c = {:.4g} m/s",
          bd.name, axis, g.velocity, g.speed - g.velocity);
    } else {
      const auto& material = scene.materials.at(bd.material);
      const auto density = material.parameters.find("density");
      e.key = fmt::format("materials.{}.density", bd.material);
      e.where = locate_key(scene, {"materials", bd.material, "density"});
      e.reason = fmt::format(
          "the CFL bound h / (c + |v|) (eq. 2.73) is governed by the wave speed of material '{}' "
          "of body '{}': c = {:.4g} m/s with density {:.6g} kg/m^3",
          bd.material, bd.name, g.speed - g.velocity, density != material.parameters.end() ? density->second : 0.0);
    }
  }
  return e;
}

std::string step_warning(const StepEstimate& e) {
  if (!(e.steps > step_count_warning) && !(e.wall_seconds > wall_time_warning)) return "";
  return SceneError::format(
      e.where, e.key,
      fmt::format("about {:.3g} steps of {:.4g} s and {:.3g} s of wall time at {:.0e} particle-updates/s ({}); a "
                  "scene is warned about above {:.0e} steps or {:.0e} s of wall time",
                  e.steps, e.dt, e.wall_seconds, assumed_particle_updates_per_second, e.reason, step_count_warning,
                  wall_time_warning));
}

void check_time_step(const StepEstimate& e, const SceneDescription& scene) {
  const double end = scene.solver.end_time;
  if (e.dt > 0 && std::isfinite(e.dt) && end + e.dt > end) return;
  const std::string what = !(e.dt > 0)            ? "is 0"
                           : !std::isfinite(e.dt) ? "is not finite"
                                                  : fmt::format(
                                                        "is too small to advance the time at end_time = {:.6g} s "
                                                        "(end_time + dt == end_time in double precision)",
                                                        end);
  throw SceneError(e.where, e.key, fmt::format("the time step dt = {:.6g} s {}: {}", e.dt, what, e.reason));
}

template StepEstimate estimate_steps<1>(const SceneDescription&, const Simulation<1>&);
template StepEstimate estimate_steps<2>(const SceneDescription&, const Simulation<2>&);
template StepEstimate estimate_steps<3>(const SceneDescription&, const Simulation<3>&);

}  // namespace mpm::app
