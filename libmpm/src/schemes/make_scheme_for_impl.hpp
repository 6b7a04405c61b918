#pragma once
// Definition of make_scheme_for<Dim, Shape> (make_scheme_for.hpp), included only by the generated units.
#include <stdexcept>

#include "make_scheme_for.hpp"
#include "mpm/schemes/musl.hpp"
#include "mpm/schemes/tlmpm.hpp"
#include "mpm/schemes/usf.hpp"
#include "mpm/schemes/usl.hpp"
#include "mpm/shape/shape_functions.hpp"

namespace mpm::detail {

template <int Dim, class Shape, class Coords>
std::unique_ptr<Scheme<Dim>> make_scheme_for(const std::string& scheme) {
  if constexpr (!shape_exists_in<Shape, Dim>) {  // never called (make_scheme refuses first): nothing to build
    throw std::logic_error("make_scheme_for: '" + std::string(Shape::name) + "' does not exist in this dimension");
  } else if constexpr (shape_tlmpm_only<Shape>) {  // negative weights: only at fixed reference positions
    if (scheme == "tlmpm") return std::make_unique<Tlmpm<Dim, Shape, Coords>>();
    throw std::invalid_argument("shape function '" + std::string(Shape::name) +
                                "' is only valid with scheme 'tlmpm', not '" + scheme + "'");
  } else {
    if (scheme == "tlmpm") return std::make_unique<Tlmpm<Dim, Shape, Coords>>();
    if (scheme == "usl") return std::make_unique<Usl<Dim, Shape, Coords>>();
    if (scheme == "musl") return std::make_unique<Musl<Dim, Shape, Coords>>();
    if (scheme == "usf") return std::make_unique<Usf<Dim, Shape, Coords>>();
  }
  throw std::invalid_argument("unknown scheme '" + scheme + "' (valid: musl, tlmpm, usf, usl)");
}

}  // namespace mpm::detail
