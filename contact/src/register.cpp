#include "mpm/contact/register.hpp"

#include <mutex>

#include "contact_section.hpp"
#include "mpm/contact/rigid_material.hpp"
#include "mpm/materials/material_registry.hpp"
#include "mpm/scene/scene_extension.hpp"

namespace mpm::contact {
namespace {

template <int Dim>
std::unique_ptr<Material<Dim>> make_rigid(const MaterialDescription& d) {
  return std::make_unique<RigidMaterial<Dim>>(d.parameters.at("density"));
}

MaterialModel rigid_model() {
  return {.key = "rigid",
          .description =
              "rigid body (review §4.2.4, Alg. 4): no stress; moves with the velocity given in "
              "contact.rigid_bodies (needs a contact section)",
          .parameters = {ParameterSpec::required(
              "density", "kg/m^3", io::Range::above(0),
              "density (only gives the rigid particles a mass, used to find contact nodes and normals)")},
          .make_1d = &make_rigid<1>,
          .make_2d = &make_rigid<2>,
          .make_3d = &make_rigid<3>,
          .phase = MaterialPhase::rigid};
}

}  // namespace

void register_module() {
  static std::once_flag once;
  std::call_once(once, [] {
    register_material_model(rigid_model());
    register_scene_extension({.key = "contact",
                              .parse = &parse_contact_section,
                              .complete = &complete_contact_defaults,
                              .build_1d = &build_contact<1>,
                              .build_2d = &build_contact<2>,
                              .build_3d = &build_contact<3>,
                              .keys = contact_keys(),
                              .description = "[Multi-body contact, rigid bodies, rigid planes](#contact) (module "
                                             "`contact`, CMake option `MPM_WITH_CONTACT`)"});
  });
}

}  // namespace mpm::contact
