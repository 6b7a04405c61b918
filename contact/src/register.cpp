#include "mpm/contact/register.hpp"

#include <mutex>

#include "contact_section.hpp"
#include "mpm/contact/rigid_material.hpp"
#include "mpm/material_registry.hpp"
#include "mpm/scene_extension.hpp"

namespace mpm::contact {
namespace {

template <int Dim>
std::unique_ptr<Material<Dim>> make_rigid(const MaterialDescription& d) {
  return std::make_unique<RigidMaterial<Dim>>(d.parameters.at("density"));
}

MaterialModel rigid_model() {
  MaterialModel model;
  model.key = "rigid";
  model.description =
      "rigid body (review §4.2.4, Alg. 4): no stress; moves with the velocity given in contact.rigid_bodies "
      "(needs a contact section)";
  model.parameters = {ParameterSpec::required(
      "density", "kg/m^3", io::Range::above(0),
      "density (only gives the rigid particles a mass, used to find contact nodes and normals)")};
  model.make_1d = &make_rigid<1>;
  model.make_2d = &make_rigid<2>;
  model.make_3d = &make_rigid<3>;
  return model;
}

}  // namespace

void register_module() {
  static std::once_flag once;
  std::call_once(once, [] {
    register_material_model(rigid_model());
    SceneExtension section;
    section.key = "contact";
    section.parse = &parse_contact_section;
    section.build_1d = &build_contact<1>;
    section.build_2d = &build_contact<2>;
    section.build_3d = &build_contact<3>;
    register_scene_extension(section);
  });
}

}  // namespace mpm::contact
