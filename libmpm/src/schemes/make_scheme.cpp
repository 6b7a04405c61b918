// make_explicit_scheme<Dim>: the scene's shape function picked once from ShapeFunctions; the instantiations
// themselves (make_scheme_for<Dim, Shape>) sit in the units libmpm/CMakeLists.txt generates. make_scheme<Dim>: any
// registered scheme by name.
#include <stdexcept>

#include "make_scheme_for.hpp"
#include "mpm/schemes/scheme_registry.hpp"
#include "mpm/shape/shape_functions.hpp"

namespace mpm {
namespace detail {

template <int Dim>
std::unique_ptr<Scheme<Dim>> make_explicit_scheme(std::size_t scheme, const SceneDescription& scene) {
  const std::string& shape = scene.solver.shape_function;
  const ShapeFunctionInfo* info = find_shape_function(shape);
  if (!info)
    throw std::invalid_argument("unknown shape function '" + shape +
                                "' (valid: " + shape_function_names_where([]<class>() { return true; }) + ")");
  if (info->tlmpm_only && !scheme_of(scene.solver).traits.total_lagrangian)
    throw std::invalid_argument("shape function '" + shape + "' is only valid with scheme " +
                                scheme_names_where([](const SchemeTraits& t) { return t.total_lagrangian; }) +
                                ", not '" + scene.solver.scheme + "'");
  if (scene.grid.coordinates == Coordinates::axisymmetric) {
    if constexpr (Dim == 2) {
      if (auto made = make_axisymmetric_scheme_for(scheme, shape)) return made;
      throw std::invalid_argument("shape function '" + shape +
                                  "' is not available in axisymmetric coordinates (valid: " +
                                  shape_function_names_where([]<class S>() { return shape_axisymmetric<S>; }) + ")");
    } else {
      throw std::invalid_argument("axisymmetric coordinates exist in 2D only, not in " + std::to_string(Dim) + "D");
    }
  }
  std::unique_ptr<Scheme<Dim>> made;
  dispatch_shape(shape, [&]<class Shape>() {
    if constexpr (shape_exists_in<Shape, Dim>)
      made = make_scheme_for<Dim, Shape>(scheme);
    else  // CPDI elements exist in one dimension each: instantiated only there
      throw std::invalid_argument("shape function '" + shape + "' is defined in " +
                                  std::to_string(shape_dimension<Shape>) + "D only, not in " + std::to_string(Dim) +
                                  "D");
  });
  return made;
}

template std::unique_ptr<Scheme<1>> make_explicit_scheme<1>(std::size_t, const SceneDescription&);
template std::unique_ptr<Scheme<2>> make_explicit_scheme<2>(std::size_t, const SceneDescription&);
template std::unique_ptr<Scheme<3>> make_explicit_scheme<3>(std::size_t, const SceneDescription&);

}  // namespace detail

template <int Dim>
std::unique_ptr<Scheme<Dim>> make_scheme(const std::string& scheme, const std::string& shape, Coordinates coordinates) {
  SceneDescription scene;
  scene.dimension = Dim;
  scene.solver.scheme = scheme;
  scene.solver.shape_function = shape;
  scene.grid.coordinates = coordinates;
  return make_scene_scheme<Dim>(scene);
}

template std::unique_ptr<Scheme<1>> make_scheme<1>(const std::string&, const std::string&, Coordinates);
template std::unique_ptr<Scheme<2>> make_scheme<2>(const std::string&, const std::string&, Coordinates);
template std::unique_ptr<Scheme<3>> make_scheme<3>(const std::string&, const std::string&, Coordinates);

}  // namespace mpm
