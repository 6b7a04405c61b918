#pragma once
// The core's explicit schemes as class templates on (dimension, shape function, coordinates), listed once
// (private to libmpm). The units CMake generates instantiate every listed scheme on every shape function
// (make_scheme_for_impl.hpp); core_schemes.cpp registers each with its name and traits. Adding a scheme: its
// header in include/mpm/schemes/, its entry here, its SchemeSpec in core_schemes.cpp.
#include <cstddef>
#include <type_traits>

#include "mpm/schemes/musl.hpp"
#include "mpm/schemes/tlmpm.hpp"
#include "mpm/schemes/usf.hpp"
#include "mpm/schemes/usl.hpp"

namespace mpm::detail {

/// One scheme template, and whether it is total-Lagrangian (only such a scheme is instantiated on the shape
/// functions with negative weights, shape_tlmpm_only); core_schemes.cpp takes SchemeTraits::total_lagrangian from
/// here.
template <template <int, class, class> class Template, bool TotalLagrangian = false>
struct ExplicitScheme {
  template <int Dim, class Shape, class Coords>
  using type = Template<Dim, Shape, Coords>;
  static constexpr bool total_lagrangian = TotalLagrangian;
};

template <class... Schemes>
struct ExplicitSchemeList {
  static constexpr std::size_t size = sizeof...(Schemes);
};

/// The core's explicit schemes.
using ExplicitSchemes =
    ExplicitSchemeList<ExplicitScheme<Musl>, ExplicitScheme<Tlmpm, true>, ExplicitScheme<Usf>, ExplicitScheme<Usl>>;

/// The position of `Scheme` in ExplicitSchemes: how a registered maker names the template to the units.
template <class Scheme, class List = ExplicitSchemes>
inline constexpr std::size_t explicit_scheme_index = 0;
template <class Scheme, class First, class... Rest>
inline constexpr std::size_t explicit_scheme_index<Scheme, ExplicitSchemeList<First, Rest...>> =
    std::is_same_v<Scheme, First> ? 0 : 1 + explicit_scheme_index<Scheme, ExplicitSchemeList<Rest...>>;

}  // namespace mpm::detail
