#pragma once
/// \file convergence.hpp
/// Helpers shared by the convergence tests: observed rates and compact number lists for `[ measured ]`.

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace mpm::verification {

/// Least-squares slope of log e against log h over the points [first, last) (all by default).
inline double observed_rate(const std::vector<double>& h, const std::vector<double>& e, std::size_t first = 0,
                            std::size_t last = static_cast<std::size_t>(-1)) {
  last = std::min(last, h.size());
  const double n = static_cast<double>(last - first);
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (std::size_t i = first; i < last; ++i) {
    const double x = std::log(h[i]), y = std::log(e[i]);
    sx += x, sy += y, sxx += x * x, sxy += x * y;
  }
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

/// The values printed with `format`, separated by spaces.
inline std::string join(const std::vector<double>& v, const char* format) {
  std::string s;
  char buf[32];
  for (double x : v) {
    std::snprintf(buf, sizeof buf, format, x);
    if (!s.empty()) s += ' ';
    s += buf;
  }
  return s;
}

}  // namespace mpm::verification
