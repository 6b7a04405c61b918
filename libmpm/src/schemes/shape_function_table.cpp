// The shape-function table (names and grid requirements for the scene loader) and the scheme names.
// make_scheme<Dim> itself is instantiated per dimension in make_scheme_{1,2,3}d.cpp.

#include "mpm/scheme.hpp"
#include "mpm/shape/bernstein_quadratic.hpp"
#include "mpm/shape/cpdi.hpp"
#include "mpm/shape/cubic_bspline.hpp"
#include "mpm/shape/gimp.hpp"
#include "mpm/shape/lagrange_quadratic.hpp"
#include "mpm/shape/linear_hat.hpp"
#include "mpm/shape/quadratic_bspline.hpp"

namespace mpm {

namespace {
template <class Shape>
ShapeFunctionInfo info() {
  ShapeFunctionInfo i;
  i.name = Shape::name;
  i.min_cells = Shape::min_cells;
  if constexpr (requires { Shape::cell_multiple; }) i.even_cells = Shape::cell_multiple == 2;
  if constexpr (requires { Shape::uses_domain; }) i.particle_domain = Shape::uses_domain;
  if constexpr (requires { Shape::tlmpm_only; }) i.tlmpm_only = Shape::tlmpm_only;
  if constexpr (requires { Shape::corner_domain; }) {
    i.dimension = Shape::dimension;
    i.domain_corners = Shape::element::corners;
    i.domain_follows_F = Shape::follows_F_by_default;
  }
  return i;
}
// Every shape function, once: the scene loader's list of names and grid checks come from here.
const std::vector<ShapeFunctionInfo>& shape_functions() {
  static const std::vector<ShapeFunctionInfo> all = {info<LinearHat>(),
                                                     info<CubicBSpline>(),
                                                     info<UGimp>(),
                                                     info<CpGimp>(),
                                                     info<QuadraticBSpline>(),
                                                     info<BernsteinQuadratic>(),
                                                     info<LagrangeQuadratic>(),
                                                     info<CpdiL2>(),
                                                     info<CpdiR4>(),
                                                     info<CpdiQ4>(),
                                                     info<CpdiT3>(),
                                                     info<CpdiTet4>()};
  return all;
}
}  // namespace

std::vector<std::string> scheme_names() { return {"musl", "tlmpm", "usf", "usl"}; }
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
