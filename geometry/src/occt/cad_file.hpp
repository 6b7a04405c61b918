#pragma once
// Internal to geometry/src/occt, the CAD reader plugin (libmpm_cad_occt.so, cad_plugin_entry.cpp): a CAD file's
// solids with the names of their parts, read once, and one solid tessellated. They throw GeometryError; the plugin's
// entry turns it into a CadFailure for the program (cad_backend.hpp).
#include <TopoDS_Solid.hxx>

#include <string>
#include <vector>

#include "../cad_model.hpp"

namespace mpm::geometry::occt {

struct CadModel {
  struct Solid {
    std::string part;    ///< the product (or instance) name, "" when none
    TopoDS_Solid solid;  ///< in `unit`, placed by the assembly's locations
  };
  std::vector<Solid> solids;
  double unit = 1;  ///< metres per model unit (the file's unit is converted to it when read)
};

/// The model of a .step/.stp, .iges/.igs or .brep file, in `unit` (STEP and IGES carry their unit; a .brep has none
/// and is taken as metres). Read on first use and kept for the process. Throws GeometryError.
const CadModel& cad_model(const std::string& file);

/// detail::cad_solids and detail::tessellate_cad_solid (cad_model.hpp) with OpenCASCADE.
std::vector<detail::CadSolidInfo> cad_solids(const std::string& file);
detail::CadTessellation tessellate_cad_solid(const CadShape& shape, std::size_t index);

}  // namespace mpm::geometry::occt
