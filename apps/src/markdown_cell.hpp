#pragma once
// Internal to apps/src: the text of a Markdown table cell (the generated references, material_reference.cpp and
// scene_reference.cpp).
#include <string>

namespace mpm {

/// `text` with every '|' escaped: a bare one would end the cell.
inline std::string markdown_cell(const std::string& text) {
  std::string escaped;
  for (const char c : text) {
    if (c == '|') escaped += '\\';
    escaped += c;
  }
  return escaped;
}

}  // namespace mpm
