#include "obj_objects.hpp"

#include <algorithm>
#include <fstream>

namespace mpm::geometry::detail {

ObjObjects read_obj_objects(const std::string& file) {
  ObjObjects objects;
  std::ifstream in(file);
  std::string line;
  std::size_t current = ObjObjects::none;
  // The first word of a line, as CGAL's `iss >> s` reads it; no stream per line (a large OBJ has millions).
  const auto is_space = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; };
  while (std::getline(in, line)) {
    std::size_t begin = 0;
    while (begin < line.size() && is_space(line[begin])) ++begin;
    std::size_t end = begin;
    while (end < line.size() && !is_space(line[end])) ++end;
    if (end != begin + 1) continue;  // `f` and `o` are one letter
    if (line[begin] == 'f') {
      objects.of_face.push_back(current);
    } else if (line[begin] == 'o') {
      while (end < line.size() && is_space(line[end])) ++end;
      std::string name = line.substr(end);
      while (!name.empty() && is_space(name.back())) name.pop_back();
      const auto found = std::find(objects.names.begin(), objects.names.end(), name);
      current = static_cast<std::size_t>(found - objects.names.begin());
      if (found == objects.names.end()) objects.names.push_back(name);
    }
  }
  return objects;
}

}  // namespace mpm::geometry::detail
