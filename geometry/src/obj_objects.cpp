#include "obj_objects.hpp"

#include <algorithm>
#include <fstream>
#include <sstream>

namespace mpm::geometry::detail {

ObjObjects read_obj_objects(const std::string& file) {
  ObjObjects objects;
  std::ifstream in(file);
  std::string line, word;
  std::size_t current = ObjObjects::none;
  while (std::getline(in, line)) {
    std::istringstream words(line);
    if (!(words >> word)) continue;
    if (word == "f") {
      objects.of_face.push_back(current);
    } else if (word == "o") {
      std::string name;
      std::getline(words >> std::ws, name);
      while (!name.empty() && (name.back() == '\r' || name.back() == ' ' || name.back() == '\t')) name.pop_back();
      const auto found = std::find(objects.names.begin(), objects.names.end(), name);
      current = static_cast<std::size_t>(found - objects.names.begin());
      if (found == objects.names.end()) objects.names.push_back(name);
    }
  }
  return objects;
}

}  // namespace mpm::geometry::detail
