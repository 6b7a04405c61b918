// The module that projects the incompressible fluids' velocity (mpm/fluids/pressure_projection.hpp), prepared from
// the materials (`model: incompressible_fluid`; it has no scene section of its own).
#include "pressure_projection_module.hpp"

#include <fmt/format.h>

#include "mpm/fluids/field_keys.hpp"
#include "mpm/fluids/incompressible_fluid.hpp"
#include "mpm/fluids/pressure_projection.hpp"
#include "mpm/materials/material_registry.hpp"
#include "mpm/scene/scene_error.hpp"
#include "mpm/scene/scene_extension.hpp"
#include "mpm/schemes/scheme_registry.hpp"
#include "mpm/shape/shape_functions.hpp"

namespace mpm::fluids {
namespace {

/// The projection reads the shape function at the particle positions alone (eq. 21.1): the functions of a particle
/// domain (GIMP, CPDI) and the total-Lagrangian ones are not its kind.
template <class Shape, int Dim>
constexpr bool projects_with =
    shape_exists_in<Shape, Dim> && !shape_uses_domain<Shape> && !shape_corner_domain<Shape> && !shape_tlmpm_only<Shape>;

template <int Dim>
std::shared_ptr<Module<Dim>> prepare_projection(const SceneDescription& scene, std::vector<Body<Dim>>& bodies,
                                                const GridGeometry<Dim>& grid) {
  std::vector<int> fluid;
  Real tolerance = 1;
  int max_iterations = 0;
  const MaterialDescription* first = nullptr;
  for (auto& body : bodies) {
    const MaterialDescription& md = scene.materials.at(scene.bodies[static_cast<std::size_t>(body.index)].material);
    if (md.model != IncompressibleFluid::key) continue;
    if (!first) first = &md;
    fluid.push_back(body.index);
    body.particles.add_field(keys::projected_pressure, Real(0));
    tolerance = std::min<Real>(tolerance, material_parameter(md, "projection_tolerance"));
    max_iterations = std::max(max_iterations, static_cast<int>(material_parameter(md, "projection_iterations")));
  }
  if (fluid.empty()) return nullptr;
  const std::string key = "materials." + first->name + ".model";
  const auto refuse = [&](const std::string& why) { throw SceneError(first->where, key, why); };
  if constexpr (Dim == 1) {
    refuse("an incompressible fluid needs 2 or 3 dimensions: in 1D div v = 0 leaves it nothing but a rigid motion");
  } else {
    const SchemeTraits& traits = scheme_of(scene.solver).traits;
    if (traits.total_lagrangian || traits.unconditionally_stable)
      refuse(
          fmt::format("the pressure projection of an incompressible fluid runs after the momentum update of the "
                      "explicit updated-Lagrangian schemes (musl, usl, usf), not with scheme '{}'",
                      scene.solver.scheme));
    if (grid.coordinates != Coordinates::cartesian)
      refuse(
          "the pressure projection is written for Cartesian grids: the axisymmetric divergence (its hoop term "
          "v_r / r) is not in it yet");
    if (scene.extensions.count("contact"))
      refuse(
          "the pressure projection works on the shared velocity field of the grid, and the contact module gives "
          "each body its own: an incompressible fluid with contact is not written yet (without the `contact:` "
          "section the bodies share the grid and the pressure acts on them all)");
    const Vec<Dim> g = Eigen::Map<const Eigen::Vector3d>(scene.solver.gravity.data()).template head<Dim>();
    if (g.norm() == 0 && !scene.solver.dt && fluid.size() == bodies.size()) {
      bool at_rest = true;  // (prototype bodies, without particles, are not judged)
      Index particles = 0;
      for (const auto& body : bodies) {
        particles += body.particles.size();
        for (Index i = 0; i < body.particles.size(); ++i) at_rest = at_rest && Vec<Dim>(body.particles.v[i]).isZero();
      }
      if (at_rest && particles > 0)
        throw SceneError(scene.solver.dt_where, "solver.cfl",
                         "an incompressible fluid has no sound speed: at rest and without gravity nothing bounds its "
                         "time step (h / |v| with v = 0); give a fixed solver.dt, gravity or an initial velocity");
    }
    std::shared_ptr<Module<Dim>> module;
    const Vec<Dim> gravity = Eigen::Map<const Eigen::Vector3d>(scene.solver.gravity.data()).template head<Dim>();
    dispatch_shape(scene.solver.shape_function, [&]<class Shape>() {
      if constexpr (projects_with<Shape, Dim>)
        module = std::make_shared<PressureProjection<Dim, Shape>>(
            std::move(fluid), gravity, grid.h.minCoeff(), tolerance, max_iterations, "materials." + first->name);
    });
    if (!module)
      refuse(
          fmt::format("the pressure projection evaluates the shape function at points, without a particle domain; "
                      "shape_function '{}' is not one it takes (use one of: {})",
                      scene.solver.shape_function,
                      shape_function_names_where([]<class Shape>() { return projects_with<Shape, Dim>; })));
    return module;
  }
  return nullptr;
}

}  // namespace

void register_pressure_projection() {
  register_scene_extension({.key = "incompressible_fluid_projection",
                            .prepare_1d = &prepare_projection<1>,
                            .prepare_2d = &prepare_projection<2>,
                            .prepare_3d = &prepare_projection<3>});
}

}  // namespace mpm::fluids
