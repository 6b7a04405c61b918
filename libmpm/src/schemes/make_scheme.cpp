// Explicit instantiation of every (dimension, scheme, shape function) combination, in one place.
#include <stdexcept>

#include "mpm/schemes/musl.hpp"
#include "mpm/schemes/usl.hpp"
#include "mpm/shape/cubic_bspline.hpp"
#include "mpm/shape/linear_hat.hpp"

namespace mpm {
namespace {

template <int Dim, class Shape>
std::unique_ptr<Scheme<Dim>> make_with_shape(const std::string& scheme) {
  if (scheme == "usl") return std::make_unique<Usl<Dim, Shape>>();
  if (scheme == "musl") return std::make_unique<Musl<Dim, Shape>>();
  throw std::invalid_argument("unknown scheme '" + scheme + "' (valid: usl, musl)");
}

}  // namespace

std::vector<std::string> scheme_names() { return {"musl", "usl"}; }
std::vector<std::string> shape_function_names() { return {LinearHat::name, CubicBSpline::name}; }

template <int Dim>
std::unique_ptr<Scheme<Dim>> make_scheme(const std::string& scheme, const std::string& shape) {
  if (shape == LinearHat::name) return make_with_shape<Dim, LinearHat>(scheme);
  if (shape == CubicBSpline::name) return make_with_shape<Dim, CubicBSpline>(scheme);
  throw std::invalid_argument("unknown shape function '" + shape + "' (valid: linear, cubic_bspline)");
}

template std::unique_ptr<Scheme<1>> make_scheme<1>(const std::string&, const std::string&);
template std::unique_ptr<Scheme<2>> make_scheme<2>(const std::string&, const std::string&);
template std::unique_ptr<Scheme<3>> make_scheme<3>(const std::string&, const std::string&);

}  // namespace mpm
