// The shape-function table (names, grid requirements and traits for the scene loader and the modules), derived
// from ShapeFunctions.

#include "mpm/schemes/scheme.hpp"
#include "mpm/shape/shape_functions.hpp"

namespace mpm {

namespace {
template <class Shape>
ShapeFunctionInfo info() {
  ShapeFunctionInfo i;
  i.name = Shape::name;
  i.min_cells = Shape::min_cells;
  i.even_cells = shape_cell_multiple<Shape> == 2;
  i.particle_domain = shape_uses_domain<Shape>;
  i.tlmpm_only = shape_tlmpm_only<Shape>;
  i.dimension = shape_dimension<Shape>;
  i.axisymmetric = shape_axisymmetric<Shape>;
  i.multilinear = shape_multilinear<Shape>;
  if constexpr (shape_corner_domain<Shape>) {
    i.domain_corners = Shape::element::corners;
    i.domain_follows_F = Shape::follows_F_by_default;
    i.tracks_corners = Shape::tracks_corners;
  }
  if constexpr (requires { Shape::stretched_domain; }) i.stretched_domain = Shape::stretched_domain;
  return i;
}
// Every shape function, once, in the order of ShapeFunctions.
const std::vector<ShapeFunctionInfo>& shape_functions() {
  static const std::vector<ShapeFunctionInfo> all = [] {
    std::vector<ShapeFunctionInfo> v;
    for_each_shape([&]<class Shape>() { v.push_back(info<Shape>()); });
    return v;
  }();
  return all;
}
}  // namespace

std::vector<std::string> shape_function_names() {
  std::vector<std::string> names;
  for (const auto& s : shape_functions()) names.push_back(s.name);
  return names;
}
const ShapeFunctionInfo* find_shape_function(const std::string& name) {
  for (const auto& s : shape_functions())
    if (s.name == name) return &s;
  return nullptr;
}

}  // namespace mpm
