#include "mpm/implicit/register.hpp"

#include <mutex>

#include "implicit_section.hpp"
#include "mpm/implicit/implicit_scheme.hpp"
#include "mpm/scheme_extension.hpp"

namespace mpm::implicit {
namespace {

template <int Dim>
std::unique_ptr<Scheme<Dim>> make_implicit(const SceneDescription& scene) {
  return std::make_unique<ImplicitScheme<Dim>>(std::any_cast<const ImplicitOptions&>(scene.solver.extension_options));
}

}  // namespace

void register_module() {
  static std::once_flag once;
  std::call_once(once, [] {
    register_scheme_extension({.name = "implicit",
                               .solver_keys = {"implicit"},
                               .parse = &parse_implicit_solver,
                               .check = &check_implicit_scene,
                               .make_1d = &make_implicit<1>,
                               .make_2d = &make_implicit<2>,
                               .make_3d = &make_implicit<3>,
                               .unconditionally_stable = true});
  });
}

}  // namespace mpm::implicit
