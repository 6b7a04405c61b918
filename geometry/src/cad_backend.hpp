#pragma once
// Internal to geometry/src: the table the CAD reader plugin (libmpm_cad_occt.so, built from occt/*.cpp with
// OpenCASCADE) hands to the program (cad_plugin.cpp). OpenCASCADE is some 60 shared libraries whose loading took
// 97 ms of the 150 ms of every `mpm` start (measured, issue 45 note); as a plugin it is loaded by the first scene
// with a `cad:` body only. Plain C++ types of the same compiler and library on both sides; no exception crosses:
// a failure comes back as a CadFailure and is thrown as GeometryError by the program.
#include <cstddef>
#include <string>
#include <vector>

#include "cad_model.hpp"

namespace mpm::geometry::detail {

/// Raised when the table's layout changes: a plugin of another version is refused by name rather than called.
inline constexpr int cad_backend_version = 1;

struct CadFailure {
  std::string file, problem;  ///< GeometryError's parts; problem empty: no failure
};

struct CadBackend {
  int version = cad_backend_version;
  std::vector<CadSolidInfo> (*solids)(const std::string& file, CadFailure& failure) = nullptr;
  CadTessellation (*tessellate)(const CadShape& shape, std::size_t index, CadFailure& failure) = nullptr;
};

}  // namespace mpm::geometry::detail

/// The plugin's one exported symbol.
extern "C" const mpm::geometry::detail::CadBackend* mpm_cad_backend();
#define MPM_CAD_BACKEND_SYMBOL "mpm_cad_backend"
