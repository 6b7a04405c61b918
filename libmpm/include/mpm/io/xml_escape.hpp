#pragma once
/// \file xml_escape.hpp
/// Text as an XML attribute value or element content (the hand-written .pvd and .pvtu files).

#include <string>

namespace mpm::io {

/// `s` with & < > " ' replaced by their entities.
inline std::string xml_escape(const std::string& s) {
  std::string out;
  out.reserve(s.size());
  for (const char c : s) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&apos;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

}  // namespace mpm::io
