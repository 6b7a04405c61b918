#pragma once
/// \file cad_region.hpp
/// Bodies from CAD files (STEP, IGES, BREP; `cad: FILE`, file_shapes.hpp) read with OpenCASCADE (MPM_WITH_OCCT): each
/// chosen solid is checked (a valid, closed B-rep), placed, tessellated to the shape's tolerance and made a closed
/// CGAL mesh (surface_mesh_io), whose inside test the lattice fill asks; a body of several solids is their union.
/// Its exact volume, centroid and inertia are the B-rep's (BRepGProp), for `volume: exact` and the certificate
/// (mass_properties.hpp).

#include <memory>
#include <string>
#include <vector>

#include "mpm/geometry/file_shapes.hpp"
#include "mpm/geometry/region.hpp"

namespace mpm::geometry {

/// What was read (for reports and tests).
struct CadSummary {
  std::vector<std::size_t> solids;  ///< indices of the solids in the body
  std::size_t triangles = 0;        ///< of their tessellations
  Real tolerance = 0;               ///< the largest chordal deviation used, m
};

/// The indices of the solids `shape` chooses (its parts' and its solid indices; all when it names none). Throws
/// GeometryError for a part name the file does not carry (listing those it does) or an index past its solids.
std::vector<std::size_t> chosen_cad_solids(const CadShape& shape);

/// The names of the parts of a CAD file, each once, in file order ("" for solids without one).
std::vector<std::string> cad_part_names(const std::string& file);

/// Every solid of a CAD file as `#index 'part'` (`#index` when it has no name), for `mpm particles`.
std::vector<std::string> cad_solid_labels(const std::string& file);

/// The region of the chosen solids. Throws GeometryError naming the file, the solid and the problem.
std::unique_ptr<Region<3>> make_cad_region(const CadShape& shape, std::vector<std::string>* warnings,
                                           CadSummary* summary = nullptr);

}  // namespace mpm::geometry
