// Explicit instantiation of every (dimension, scheme, shape function) combination, in one place.
#include <stdexcept>

#include "mpm/schemes/musl.hpp"
#include "mpm/schemes/tlmpm.hpp"
#include "mpm/schemes/usf.hpp"
#include "mpm/schemes/usl.hpp"
#include "mpm/shape/bernstein_quadratic.hpp"
#include "mpm/shape/cubic_bspline.hpp"
#include "mpm/shape/gimp.hpp"
#include "mpm/shape/lagrange_quadratic.hpp"
#include "mpm/shape/linear_hat.hpp"
#include "mpm/shape/quadratic_bspline.hpp"

namespace mpm {
namespace {

template <int Dim, class Shape>
std::unique_ptr<Scheme<Dim>> make_with_shape(const std::string& scheme) {
  if (scheme == "usl") return std::make_unique<Usl<Dim, Shape>>();
  if (scheme == "musl") return std::make_unique<Musl<Dim, Shape>>();
  if (scheme == "usf") return std::make_unique<Usf<Dim, Shape>>();
  if (scheme == "tlmpm") return std::make_unique<Tlmpm<Dim, Shape>>();
  throw std::invalid_argument("unknown scheme '" + scheme + "' (valid: musl, tlmpm, usf, usl)");
}

}  // namespace

namespace {
template <class Shape>
ShapeFunctionInfo info() {
  ShapeFunctionInfo i;
  i.name = Shape::name;
  i.min_cells = Shape::min_cells;
  if constexpr (requires { Shape::cell_multiple; }) i.even_cells = Shape::cell_multiple == 2;
  if constexpr (requires { Shape::uses_domain; }) i.particle_domain = Shape::uses_domain;
  if constexpr (requires { Shape::tlmpm_only; }) i.tlmpm_only = Shape::tlmpm_only;
  return i;
}
// Every shape function, once: the scene loader's list of names and grid checks come from here.
const std::vector<ShapeFunctionInfo>& shape_functions() {
  static const std::vector<ShapeFunctionInfo> all = {
      info<LinearHat>(),          info<CubicBSpline>(),     info<UGimp>(), info<CpGimp>(), info<QuadraticBSpline>(),
      info<BernsteinQuadratic>(), info<LagrangeQuadratic>()};
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

template <int Dim>
std::unique_ptr<Scheme<Dim>> make_scheme(const std::string& scheme, const std::string& shape) {
  if (shape == LinearHat::name) return make_with_shape<Dim, LinearHat>(scheme);
  if (shape == CubicBSpline::name) return make_with_shape<Dim, CubicBSpline>(scheme);
  if (shape == UGimp::name) return make_with_shape<Dim, UGimp>(scheme);
  if (shape == QuadraticBSpline::name) return make_with_shape<Dim, QuadraticBSpline>(scheme);
  if (shape == BernsteinQuadratic::name) return make_with_shape<Dim, BernsteinQuadratic>(scheme);
  if (shape == CpGimp::name) return make_with_shape<Dim, CpGimp>(scheme);
  if (shape == LagrangeQuadratic::name) {  // negative lobes: total-Lagrangian only (tlmpm_only)
    if (scheme == "tlmpm") return std::make_unique<Tlmpm<Dim, LagrangeQuadratic>>();
    throw std::invalid_argument("shape function 'lagrange_quadratic' is only valid with scheme 'tlmpm', not '" +
                                scheme + "'");
  }
  throw std::invalid_argument("unknown shape function '" + shape + "'");
}

template std::unique_ptr<Scheme<1>> make_scheme<1>(const std::string&, const std::string&);
template std::unique_ptr<Scheme<2>> make_scheme<2>(const std::string&, const std::string&);
template std::unique_ptr<Scheme<3>> make_scheme<3>(const std::string&, const std::string&);

}  // namespace mpm
