// The entry of the CAD reader plugin (cad_backend.hpp): OpenCASCADE's reading and tessellation behind a table of
// functions that return their failure instead of throwing it across the library boundary.
#include "../cad_backend.hpp"
#include "cad_file.hpp"
#include "mpm/geometry/geometry_error.hpp"

namespace mpm::geometry::occt {
namespace {

/// Runs `f`; a GeometryError (or anything else) becomes `failure`.
template <class Result, class F>
Result guarded(const std::string& file, detail::CadFailure& failure, F&& f) {
  try {
    return f();
  } catch (const GeometryError& e) {
    failure = {e.file, e.problem};
  } catch (const std::exception& e) {
    failure = {file, e.what()};
  }
  return Result{};
}

std::vector<detail::CadSolidInfo> solids(const std::string& file, detail::CadFailure& failure) {
  return guarded<std::vector<detail::CadSolidInfo>>(file, failure, [&] { return cad_solids(file); });
}

detail::CadTessellation tessellate(const CadShape& shape, std::size_t index, detail::CadFailure& failure) {
  return guarded<detail::CadTessellation>(shape.file, failure, [&] { return tessellate_cad_solid(shape, index); });
}

}  // namespace
}  // namespace mpm::geometry::occt

extern "C" __attribute__((visibility("default"))) const mpm::geometry::detail::CadBackend* mpm_cad_backend() {
  static const mpm::geometry::detail::CadBackend backend{
      mpm::geometry::detail::cad_backend_version, &mpm::geometry::occt::solids, &mpm::geometry::occt::tessellate};
  return &backend;
}
