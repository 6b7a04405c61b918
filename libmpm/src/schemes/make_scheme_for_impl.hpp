#pragma once
// Definition of make_scheme_for<Dim, Shape> (make_scheme_for.hpp), included only by the generated units.
#include <stdexcept>

#include "explicit_schemes.hpp"
#include "make_scheme_for.hpp"
#include "mpm/shape/shape_functions.hpp"

namespace mpm::detail {

template <class List>
struct ExplicitSchemeMaker;
template <class... Schemes>
struct ExplicitSchemeMaker<ExplicitSchemeList<Schemes...>> {
  /// The `index`-th scheme of the list on (Dim, Shape, Coords): each listed scheme is instantiated once here.
  template <int Dim, class Shape, class Coords>
  static std::unique_ptr<Scheme<Dim>> make(std::size_t index) {
    std::unique_ptr<Scheme<Dim>> made;
    std::size_t position = 0;
    (
        [&] {
          // negative weights (shape_tlmpm_only): only at fixed reference positions
          if constexpr (Schemes::total_lagrangian || !shape_tlmpm_only<Shape>)
            if (position == index) made = std::make_unique<typename Schemes::template type<Dim, Shape, Coords>>();
          ++position;
        }(),
        ...);
    return made;
  }
};

template <int Dim, class Shape, class Coords>
std::unique_ptr<Scheme<Dim>> make_scheme_for(std::size_t scheme) {
  if constexpr (!shape_exists_in<Shape, Dim>) {  // never called (make_explicit_scheme refuses first)
    throw std::logic_error("make_scheme_for: '" + std::string(Shape::name) + "' does not exist in this dimension");
  } else {
    if (auto made = ExplicitSchemeMaker<ExplicitSchemes>::template make<Dim, Shape, Coords>(scheme)) return made;
    throw std::logic_error("make_scheme_for: scheme " + std::to_string(scheme) + " is not listed or refuses '" +
                           std::string(Shape::name) + "'");
  }
}

}  // namespace mpm::detail
