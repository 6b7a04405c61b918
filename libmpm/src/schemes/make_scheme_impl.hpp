#pragma once
// Definition of make_scheme<Dim>: included by make_scheme_{1,2,3}d.cpp, which instantiate one dimension
// each, so that the 4 schemes x 7 shape functions compile in parallel (private to libmpm).
#include <stdexcept>

#include "mpm/schemes/musl.hpp"
#include "mpm/schemes/tlmpm.hpp"
#include "mpm/schemes/usf.hpp"
#include "mpm/schemes/usl.hpp"
#include "mpm/shape/bernstein_quadratic.hpp"
#include "mpm/shape/cpdi.hpp"
#include "mpm/shape/cubic_bspline.hpp"
#include "mpm/shape/gimp.hpp"
#include "mpm/shape/lagrange_quadratic.hpp"
#include "mpm/shape/linear_hat.hpp"
#include "mpm/shape/quadratic_bspline.hpp"

namespace mpm {
namespace detail {

template <int Dim, class Shape>
std::unique_ptr<Scheme<Dim>> make_with_shape(const std::string& scheme) {
  if (scheme == "usl") return std::make_unique<Usl<Dim, Shape>>();
  if (scheme == "musl") return std::make_unique<Musl<Dim, Shape>>();
  if (scheme == "usf") return std::make_unique<Usf<Dim, Shape>>();
  if (scheme == "tlmpm") return std::make_unique<Tlmpm<Dim, Shape>>();
  throw std::invalid_argument("unknown scheme '" + scheme + "' (valid: musl, tlmpm, usf, usl)");
}

/// The scheme on the CPDI shape named `shape`, or nullptr if no listed shape has that name; throws
/// if the shape exists only in another dimension.
template <int Dim, class... Shapes>
std::unique_ptr<Scheme<Dim>> make_cpdi(const std::string& scheme, const std::string& shape) {
  std::unique_ptr<Scheme<Dim>> made;
  auto try_one = [&]<class Shape>() {
    if (made || shape != Shape::name) return;
    if constexpr (Shape::dimension == Dim)
      made = make_with_shape<Dim, Shape>(scheme);
    else
      throw std::invalid_argument("shape function '" + shape + "' is defined in " + std::to_string(Shape::dimension) +
                                  "D only, not in " + std::to_string(Dim) + "D");
  };
  (try_one.template operator()<Shapes>(), ...);
  return made;
}

}  // namespace detail

template <int Dim>
std::unique_ptr<Scheme<Dim>> make_scheme(const std::string& scheme, const std::string& shape) {
  if (shape == LinearHat::name) return detail::make_with_shape<Dim, LinearHat>(scheme);
  if (shape == CubicBSpline::name) return detail::make_with_shape<Dim, CubicBSpline>(scheme);
  if (shape == UGimp::name) return detail::make_with_shape<Dim, UGimp>(scheme);
  if (shape == QuadraticBSpline::name) return detail::make_with_shape<Dim, QuadraticBSpline>(scheme);
  if (shape == BernsteinQuadratic::name) return detail::make_with_shape<Dim, BernsteinQuadratic>(scheme);
  if (shape == CpGimp::name) return detail::make_with_shape<Dim, CpGimp>(scheme);
  if (shape == LagrangeQuadratic::name) {  // negative lobes: total-Lagrangian only (tlmpm_only)
    if (scheme == "tlmpm") return std::make_unique<Tlmpm<Dim, LagrangeQuadratic>>();
    throw std::invalid_argument("shape function 'lagrange_quadratic' is only valid with scheme 'tlmpm', not '" +
                                scheme + "'");
  }
  // CPDI elements exist in one dimension each: instantiated only there.
  if (auto cpdi = detail::make_cpdi<Dim, CpdiL2, CpdiR4, CpdiQ4, CpdiT3, CpdiTet4>(scheme, shape)) return cpdi;
  throw std::invalid_argument("unknown shape function '" + shape + "'");
}

}  // namespace mpm
