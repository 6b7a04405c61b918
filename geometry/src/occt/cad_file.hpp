#pragma once
// Internal to geometry/src/occt (OpenCASCADE): a CAD file's solids with the names of their parts, read once.
#include <TopoDS_Solid.hxx>

#include <string>
#include <vector>

namespace mpm::geometry::detail {

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

}  // namespace mpm::geometry::detail
