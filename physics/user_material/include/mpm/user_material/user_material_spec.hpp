#pragma once
/// \file user_material_spec.hpp
/// What a scene says about a `model: user` material besides its numbers (MaterialDescription::model_keys): the
/// shared library, its interface and entry point, the PROPS, the state variables (their number, initial values and
/// output names) and the CMNAME.

#include <string>
#include <vector>

namespace mpm::user_material {

/// The calling convention of the library's entry point (README.md, "Interfaces").
enum class Interface {
  vumat,  ///< Abaqus/Explicit VUMAT: blocks of points, corotational frame (symbol vumat_)
  umat,   ///< Abaqus/Standard UMAT: one point per call, stress rotated by the increment (symbol umat_)
  c,      ///< this program's C interface, mpm_user_material.h (symbol mpm_user_material_update)
};

/// "vumat", "umat" or "c".
const char* interface_name(Interface interface);
/// The entry point's symbol when the scene gives no `symbol:` (gfortran's mangling of VUMAT and UMAT).
const char* default_symbol(Interface interface);

struct UserMaterialSpec {
  std::string library;  ///< absolute path of the .so (the scene's `library`, relative to the scene file)
  Interface interface = Interface::vumat;
  std::string symbol;                    ///< entry point looked up with dlsym
  std::vector<double> properties;        ///< PROPS, in the scene's order
  std::vector<double> initial_state;     ///< NSTATEV initial values (0 when the scene gives a count)
  std::vector<std::string> state_names;  ///< the output field of each state variable (sdv1, ... or the scene's)
  std::string name;                      ///< CMNAME: the scene's `name:` or the material's name
  std::string material;                  ///< the material's name in the scene (for messages)
};

/// The particle field of state variable k (0-based): "sdv1", "sdv2", ... whatever its output name (checkpoint
/// datasets bodies/NAME/sdvK).
std::string state_field_name(std::size_t k);

}  // namespace mpm::user_material
