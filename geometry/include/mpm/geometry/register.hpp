#pragma once
/// \file register.hpp
/// Registers geometry's body shape kinds, `mesh` and `image` (body_shape/shape_kind.hpp). Called by the generated
/// mpm::app::register_modules(), like the physics modules'.

namespace mpm::geometry {

void register_module();

}  // namespace mpm::geometry
