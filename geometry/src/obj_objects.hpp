#pragma once
// Internal to geometry/src: the named objects of an OBJ file (`o NAME` lines), which CGAL's reader skips, so that a
// file of several objects is said to be several and `object: NAME` (mesh_kind.cpp) can choose one.
#include <cstddef>
#include <limits>
#include <string>
#include <vector>

namespace mpm::geometry::detail {

struct ObjObjects {
  static constexpr std::size_t none = std::numeric_limits<std::size_t>::max();
  std::vector<std::string> names;    ///< in file order, each once (an object may be continued later in the file)
  std::vector<std::size_t> of_face;  ///< per `f` line, in file order: the index of its object in names, or none
};

/// The objects of the OBJ file `file` and the object of every face. Faces are the lines whose first word is `f`, as
/// CGAL's reader (CGAL/IO/OBJ.h) reads them: the k-th is the k-th polygon of read_polygon_soup. Groups (`g`) are not
/// objects (exporters use them for materials and smoothing).
ObjObjects read_obj_objects(const std::string& file);

}  // namespace mpm::geometry::detail
