#include "mpm/app/key_location.hpp"

#include <yaml-cpp/yaml.h>

namespace mpm::app {
namespace {

SourceLocation at(const SceneDescription& scene, const YAML::Node& node) {
  return {scene.file, node.Mark().line + 1, node.Mark().column + 1};
}

}  // namespace

SourceLocation locate_key(const SceneDescription& scene, const std::vector<std::string>& path) {
  SourceLocation where{scene.file, 0, 0};
  try {
    YAML::Node node = YAML::Load(scene.source);
    for (const auto& key : path) {
      if (!node.IsMap() || !node[key]) break;
      node = node[key];
      if (!node.Mark().is_null()) where = at(scene, node);
    }
  } catch (const YAML::Exception&) {  // the text was read once already: keep what was found
  }
  return where;
}

SourceLocation locate_body_key(const SceneDescription& scene, const SourceLocation& body, const std::string& key) {
  SourceLocation where = body;
  try {
    const YAML::Node root = YAML::Load(scene.source);
    for (const auto& item : root["bodies"])
      if (item.Mark().line + 1 == body.line && item.Mark().column + 1 == body.column && item.IsMap() && item[key] &&
          !item[key].Mark().is_null())
        where = at(scene, item[key]);
  } catch (const YAML::Exception&) {
  }
  return where;
}

}  // namespace mpm::app
