#pragma once
// The thermal analysis `solver.scheme: heat` (mpm/thermal/heat_only_scheme.hpp), registered by register_module().

namespace mpm::thermal {

/// Adds `heat` to the scheme registry (scheme_registry.hpp).
void register_heat_scheme();

}  // namespace mpm::thermal
