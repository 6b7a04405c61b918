// geometry's registration (mpm/geometry/register.hpp): its body shape kinds.
#include "mpm/geometry/register.hpp"

#include "shape_kinds.hpp"

namespace mpm::geometry {

void register_module() {
  register_shape_kind(mesh_kind());
  register_shape_kind(image_kind());
  register_shape_kind(cad_kind());
  register_shape_kind(gmsh_kind());
}

}  // namespace mpm::geometry
