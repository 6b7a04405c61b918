#include "mpm/core/range.hpp"

#include <fmt/format.h>

#include <cmath>

namespace mpm::io {

std::string unit_suffix(std::string_view unit) {
  // Built by append: GCC 12 reports a false -Wrestrict on `" " + std::string(unit)` at -O3 (GCC bug 105329).
  std::string suffix;
  if (unit.empty() || unit == "-") return suffix;
  suffix.reserve(unit.size() + 1);
  suffix += ' ';
  suffix += unit;
  return suffix;
}

std::string Range::describe(std::string_view unit) const {
  const bool has_lower = std::isfinite(lower), has_upper = std::isfinite(upper);
  if (has_lower && has_upper)
    return fmt::format("in {}{}, {}{}{}", lower_inclusive ? '[' : '(', lower, upper, upper_inclusive ? ']' : ')',
                       unit_suffix(unit));
  if (has_lower) return fmt::format("{} {}{}", lower_inclusive ? ">=" : ">", lower, unit_suffix(unit));
  if (has_upper) return fmt::format("{} {}{}", upper_inclusive ? "<=" : "<", upper, unit_suffix(unit));
  return "any";
}

}  // namespace mpm::io
