#pragma once
/// \file scene_number.hpp
/// A number written into the text of a generated scene: 17 significant digits, so that the scene reader gets the
/// same double back (the verification cases build their scenes as YAML text, as a user would write them).

#include <cstdio>
#include <string>

namespace mpm::verification {

inline std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

}  // namespace mpm::verification
