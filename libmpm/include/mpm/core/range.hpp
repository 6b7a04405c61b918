#pragma once
/// \file range.hpp
/// An admissible interval of a number: what the YAML reader checks a value against (yaml_reader.hpp), what a
/// material parameter declares (material_registry.hpp) and what the scene reference prints as "Allowed values".

#include <limits>
#include <string>
#include <string_view>

namespace mpm::io {

/// The interval [lower, upper], each end open or closed; infinite ends mean unbounded.
struct Range {
  double lower = -std::numeric_limits<double>::infinity();
  bool lower_inclusive = true;
  double upper = std::numeric_limits<double>::infinity();
  bool upper_inclusive = true;

  /// Every finite number.
  static constexpr Range any() { return {}; }
  /// > `bound`.
  static constexpr Range above(double bound) { return {bound, false}; }
  /// >= `bound`.
  static constexpr Range at_least(double bound) { return {bound, true}; }
  /// [lower, upper].
  static constexpr Range closed(double lower, double upper) { return {lower, true, upper, true}; }
  /// (lower, upper).
  static constexpr Range open(double lower, double upper) { return {lower, false, upper, false}; }
  /// (lower, upper].
  static constexpr Range above_up_to(double lower, double upper) { return {lower, false, upper, true}; }

  constexpr bool contains(double v) const {
    return (v > lower || (lower_inclusive && v == lower)) && (v < upper || (upper_inclusive && v == upper));
  }
  /// "> 0 Pa", ">= 0", "in (0, 1]", ...; "any" when unbounded. `unit` follows the bound (none for "" or "-").
  std::string describe(std::string_view unit = "") const;

  bool operator==(const Range&) const = default;
};

/// " unit" for messages; nothing for dimensionless quantities ("-" or "").
std::string unit_suffix(std::string_view unit);

}  // namespace mpm::io
