// make_scheme<Dim>: the scene's shape function picked once from ShapeFunctions; the instantiations
// themselves (make_scheme_for<Dim, Shape>) sit in the units libmpm/CMakeLists.txt generates.
#include <stdexcept>

#include "make_scheme_for.hpp"
#include "mpm/shape/shape_functions.hpp"

namespace mpm {

template <int Dim>
std::unique_ptr<Scheme<Dim>> make_scheme(const std::string& scheme, const std::string& shape, Coordinates coordinates) {
  if (coordinates == Coordinates::axisymmetric) {
    if constexpr (Dim == 2) {
      if (auto made = detail::make_axisymmetric_scheme_for(scheme, shape)) return made;
      throw std::invalid_argument("shape function '" + shape +
                                  "' is not available in axisymmetric coordinates (valid: " +
                                  shape_function_names_where([]<class S>() { return shape_axisymmetric<S>; }) + ")");
    } else {
      throw std::invalid_argument("axisymmetric coordinates exist in 2D only, not in " + std::to_string(Dim) + "D");
    }
  }
  std::unique_ptr<Scheme<Dim>> made;
  const bool listed = dispatch_shape(shape, [&]<class Shape>() {
    if constexpr (shape_exists_in<Shape, Dim>)
      made = detail::make_scheme_for<Dim, Shape>(scheme);
    else  // CPDI elements exist in one dimension each: instantiated only there
      throw std::invalid_argument("shape function '" + shape + "' is defined in " +
                                  std::to_string(shape_dimension<Shape>) + "D only, not in " + std::to_string(Dim) +
                                  "D");
  });
  if (!listed)
    throw std::invalid_argument("unknown shape function '" + shape +
                                "' (valid: " + shape_function_names_where([]<class>() { return true; }) + ")");
  return made;
}

template std::unique_ptr<Scheme<1>> make_scheme<1>(const std::string&, const std::string&, Coordinates);
template std::unique_ptr<Scheme<2>> make_scheme<2>(const std::string&, const std::string&, Coordinates);
template std::unique_ptr<Scheme<3>> make_scheme<3>(const std::string&, const std::string&, Coordinates);

}  // namespace mpm
