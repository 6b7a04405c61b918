// A build without OpenCASCADE (MPM_WITH_OCCT=OFF): the CAD reader refuses every file, naming the option.
#include "../cad_model.hpp"
#include "mpm/geometry/geometry_error.hpp"

namespace mpm::geometry::detail {

namespace {

[[noreturn]] void refuse(const std::string& file) {
  throw GeometryError(file,
                      "STEP, IGES and BREP files need a build with OpenCASCADE (CMake option MPM_WITH_OCCT=ON, "
                      "Debian packages libocct-data-exchange-dev, libocct-modeling-algorithms-dev, libocct-ocaf-dev)");
}

}  // namespace

bool cad_available() { return false; }
std::vector<CadSolidInfo> cad_solids(const std::string& file) { refuse(file); }
CadTessellation tessellate_cad_solid(const CadShape& shape, std::size_t) { refuse(shape.file); }

}  // namespace mpm::geometry::detail
