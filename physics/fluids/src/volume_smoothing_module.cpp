// The module that smooths the fluids' volume ratio (mpm/fluids/volume_smoothing.hpp), prepared from the materials'
// key `pressure_smoothing` (it has no scene section of its own).
#include "volume_smoothing_module.hpp"

#include <fmt/format.h>

#include "mpm/fluids/volume_smoothing.hpp"
#include "mpm/scene/scene_error.hpp"
#include "mpm/scene/scene_extension.hpp"
#include "mpm/schemes/scheme_registry.hpp"

namespace mpm::fluids {
namespace {

/// The bodies whose material asks for the nodal average (pressure_smoothing: 1; a key only newtonian_fluid has), or
/// nullptr when none does. The average runs between the explicit updated-Lagrangian schemes' transfer and stress
/// update; the TLMPM (weights at the reference positions) and the implicit scheme have no such phase: refused there.
template <int Dim>
std::shared_ptr<Module<Dim>> prepare(const SceneDescription& scene, std::vector<Body<Dim>>& bodies,
                                     const GridGeometry<Dim>&) {
  std::vector<int> smoothed;
  for (const auto& body : bodies) {
    const MaterialDescription& md = scene.materials.at(scene.bodies[static_cast<std::size_t>(body.index)].material);
    const auto it = md.parameters.find(smoothing_key);
    if (it == md.parameters.end() || it->second == 0) continue;
    const SchemeTraits& traits = scheme_of(scene.solver).traits;
    if (traits.total_lagrangian || traits.unconditionally_stable)
      throw SceneError(md.where, "materials." + md.name + "." + smoothing_key,
                       fmt::format("the nodal average of J (pressure_smoothing: 1) runs between the transfer and the "
                                   "stress update of the explicit updated-Lagrangian schemes (musl, usl, usf), not "
                                   "with scheme '{}': set pressure_smoothing: 0",
                                   scene.solver.scheme));
    smoothed.push_back(body.index);
  }
  if (smoothed.empty()) return nullptr;
  return std::make_shared<VolumeSmoothing<Dim>>(std::move(smoothed));
}

}  // namespace

void register_volume_smoothing() {
  register_scene_extension({.key = "newtonian_fluid_pressure_smoothing",
                            .prepare_1d = &prepare<1>,
                            .prepare_2d = &prepare<2>,
                            .prepare_3d = &prepare<3>});
}

}  // namespace mpm::fluids
