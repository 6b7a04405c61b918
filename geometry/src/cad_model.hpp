#pragma once
// Internal to geometry/src: what the OpenCASCADE sources (occt/*.cpp, MPM_WITH_OCCT) give the rest of geometry, in
// plain types (no OpenCASCADE header here). They are a plugin loaded on first use (cad_backend.hpp, cad_plugin.cpp);
// without MPM_WITH_OCCT, or when the plugin cannot be loaded, these throw GeometryError saying why.
#include <array>
#include <string>
#include <vector>

#include "mpm/geometry/file_shapes.hpp"
#include "mpm/geometry/mass_properties.hpp"

namespace mpm::geometry::detail {

/// Why CAD files cannot be read ("" when they can): a build without OpenCASCADE, or a plugin that cannot be loaded
/// (the places looked at and the loader's message). Loads the plugin on first call.
const std::string& cad_unavailable();

/// A solid of a CAD file: the name of the part (product or label) it belongs to, "" when the file names none.
struct CadSolidInfo {
  std::string part;
  std::size_t index = 0;  ///< 0-based, in the order of the file's assembly tree
};

/// The file's solids (read once per process and kept). Throws GeometryError: unreadable, truncated or corrupt file,
/// a file with no solid (an IGES of surfaces only).
std::vector<CadSolidInfo> cad_solids(const std::string& file);

/// One solid tessellated: outward triangles in m after the file's unit, the shape's scale, rotation and translation.
struct CadTessellation {
  std::vector<std::array<double, 3>> points;
  std::vector<std::array<std::size_t, 3>> triangles;
  MassProperties exact;  ///< of the B-rep (BRepGProp), transformed like the points
  double tolerance = 0;  ///< the chordal deviation used, m
  std::string label;     ///< `FILE: solid 'part' (#index)` for messages
};

/// Solid `index` of shape.file. Throws GeometryError naming the file and the solid: an invalid B-rep (BRepCheck), an
/// open shell (its free edges), no volume, a face the mesher cannot triangulate.
CadTessellation tessellate_cad_solid(const CadShape& shape, std::size_t index);

}  // namespace mpm::geometry::detail
