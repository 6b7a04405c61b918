#pragma once
// The core's schemes (USL, MUSL, USF, TLMPM) as registry entries, read by the scheme registry when it is first used
// (scheme_registry.cpp).
#include <vector>

#include "mpm/schemes/scheme_registry.hpp"

namespace mpm {

/// The core's schemes, in the order `solver.scheme` lists them.
std::vector<SchemeSpec> core_schemes();

}  // namespace mpm
