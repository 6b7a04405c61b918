#pragma once
/// \file field_key.hpp
/// The name and value type of an on-demand particle field, so that `p.field(keys::temperature)` is a
/// `std::vector<Real>&` without naming the type again and a misspelt name does not compile. Keys are
/// `inline constexpr` constants (variable templates for types that depend on the dimension); where each
/// one is declared is stated in libmpm/README.md ("Particle field keys").

#include <string_view>

namespace mpm {

template <class T>
struct FieldKey {
  using value_type = T;
  std::string_view name;  ///< the field's name in the particle set (and in messages)
};

}  // namespace mpm
