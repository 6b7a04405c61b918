#include "mpm/implicit/register.hpp"

#include <mutex>

#include "implicit_section.hpp"
#include "mpm/implicit/implicit_scheme.hpp"
#include "mpm/scene/scene_extension.hpp"
#include "mpm/schemes/scheme_registry.hpp"

namespace mpm::implicit {
namespace {

template <int Dim>
std::unique_ptr<Scheme<Dim>> make_implicit(const SceneDescription& scene) {
  return std::make_unique<ImplicitScheme<Dim>>(std::any_cast<const ImplicitOptions&>(scene.solver.scheme_options));
}

}  // namespace

void register_module() {
  static std::once_flag once;
  std::call_once(once, [] {
    register_scheme(
        {.name = "implicit",
         .description = "Energy-consistent implicit MPM (Love & Sulsky, ref. 003): consistent mass, midpoint rule, "
                        "Newton-Krylov; stable for any dt",
         .parse = &parse_implicit_solver,
         .check = &check_implicit_scene,
         .make_1d = &make_implicit<1>,
         .make_2d = &make_implicit<2>,
         .make_3d = &make_implicit<3>,
         .traits = {
             .affine_transfers = Support::no("it updates particle velocities by the grid increment: eq. 92, FLIP"),
             .contact = Support::no("the implicit scheme does not support contact yet"),
             .local_damping =
                 Support::no("its midpoint Newton step has no explicit momentum update to damp, and damping "
                             "would void its energy proof (Prop. 3.1); to reach a static state use an explicit "
                             "scheme (musl, usl, usf, tlmpm) with damping"),
             .contact_releases_separating_nodes = false,
             .unconditionally_stable = true,
             .runs_distributed = false}});
    register_scheme_solver_keys("implicit", implicit_keys());
  });
}

}  // namespace mpm::implicit
