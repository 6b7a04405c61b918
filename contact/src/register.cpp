#include "mpm/contact/register.hpp"

#include <limits>
#include <mutex>

#include "contact_section.hpp"
#include "mpm/contact/rigid_material.hpp"
#include "mpm/material_catalog.hpp"
#include "mpm/material_factory.hpp"
#include "mpm/scene_extension.hpp"

namespace mpm::contact {
namespace {

MaterialModelSpec rigid_spec() {
  MaterialModelSpec s;
  s.model = "rigid";
  s.description =
      "rigid body (review §4.2.4, Alg. 4): no stress; moves with the velocity given in contact.rigid_bodies "
      "(needs a contact section)";
  ParameterSpec density;
  density.name = "density";
  density.unit = "kg/m^3";
  density.description = "density (only gives the rigid particles a mass, used to find contact nodes and normals)";
  density.lower = 0;
  density.lower_inclusive = false;
  s.parameters = {density};
  return s;
}

template <int Dim>
std::unique_ptr<Material<Dim>> make_rigid(const MaterialDescription& d) {
  return std::make_unique<RigidMaterial<Dim>>(d.parameters.at("density"));
}

}  // namespace

void register_module() {
  static std::once_flag once;
  std::call_once(once, [] {
    register_material_model(rigid_spec());
    register_material_factory("rigid", &make_rigid<1>, &make_rigid<2>, &make_rigid<3>);
    SceneExtension e;
    e.key = "contact";
    e.parse = &parse_contact_section;
    e.build_1d = &build_contact<1>;
    e.build_2d = &build_contact<2>;
    e.build_3d = &build_contact<3>;
    register_scene_extension(e);
  });
}

}  // namespace mpm::contact
