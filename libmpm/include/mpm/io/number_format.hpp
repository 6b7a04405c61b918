#pragma once
/// \file number_format.hpp
/// Numbers as text for the output files: shortest exact form, locale-independent.

#include <charconv>
#include <string>

namespace mpm::io {

/// %.17g (reads back to the same double) in the C locale, whatever the global locale.
inline std::string format_double(double v) {
  char buffer[32];
  const auto end = std::to_chars(buffer, buffer + sizeof buffer, v, std::chars_format::general, 17).ptr;
  return std::string(buffer, end);
}

}  // namespace mpm::io
