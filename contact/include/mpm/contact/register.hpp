#pragma once
/// \file register.hpp
/// Registration of the contact module (CMake option MPM_WITH_CONTACT): the material model `rigid` and the
/// scene section `contact:` (docs/scene-reference.md). Called by the generated mpm::app::register_modules().

namespace mpm::contact {

void register_module();

}  // namespace mpm::contact
