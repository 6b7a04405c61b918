// The axisymmetric schemes (axisymmetric.hpp): the explicit schemes in 2D on the shape functions that have
// shape_axisymmetric (linear, the B-splines, cpGIMP), instantiated here once, apart from the Cartesian units.
#include "make_scheme_for_impl.hpp"

namespace mpm::detail {

std::unique_ptr<Scheme<2>> make_axisymmetric_scheme_for(std::size_t scheme, const std::string& shape) {
  std::unique_ptr<Scheme<2>> made;
  dispatch_shape(shape, [&]<class Shape>() {
    if constexpr (shape_axisymmetric<Shape>) made = make_scheme_for<2, Shape, AxisymmetricCoordinates>(scheme);
  });
  return made;
}

}  // namespace mpm::detail
