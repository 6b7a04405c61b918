// The scene file as a whole: the top-level keys, the sections in the order they depend on each other (each
// read by its own file in scene/), then the optional modules' sections (scene_extension.hpp).
#include "mpm/scene_loader.hpp"

#include <fmt/format.h>

#include <fstream>
#include <sstream>
#include <system_error>

#include "mpm/scene_extension.hpp"
#include "mpm/scheme_registry.hpp"
#include "scene/sections.hpp"

namespace mpm {

SceneDescription parse_scene(const std::string& yaml_text, const std::string& file_name_for_messages) {
  const io::YamlReader reader(file_name_for_messages);
  YAML::Node root;
  try {
    root = YAML::Load(yaml_text);
  } catch (const YAML::Exception& e) {
    reader.fail(e.mark, "", "YAML syntax error: " + e.msg);
  }
  const std::string top_keys = "dimension, grid, materials, bodies, solver, output";
  if (root.IsNull())
    throw SceneError({file_name_for_messages, 1, 1}, "",
                     "the scene is empty: expected a map with the keys " + top_keys);
  const io::YamlValue top_value{root, "", io::mark_of(root, YAML::Mark::null_mark())};
  if (!root.IsMap())
    reader.fail(top_value, fmt::format("expected a map with the keys {}, got {}", top_keys, io::describe(root)));
  const io::YamlMap top = reader.map(top_value);
  std::vector<std::string> top_allowed{"dimension", "grid", "materials", "bodies", "solver", "output"};
  for (const auto& key : scene_extension_keys()) top_allowed.push_back(key);
  top.allow(top_allowed);

  SceneDescription scene;
  scene.file = file_name_for_messages;
  scene.source = yaml_text;
  scene.dimension = sections::read_dimension(reader, top);
  scene.grid = sections::read_grid(reader, top.required("grid"), scene.dimension);
  scene.materials = sections::read_materials(reader, top.required("materials"));
  scene.bodies = sections::read_bodies(reader, top.required("bodies"), scene);
  scene.solver = sections::read_solver(reader, top.required("solver"), scene);
  if (const auto output = top.find("output")) scene.output = sections::read_output(reader, *output, scene);
  for (const auto& key : scene_extension_keys())  // module sections last: they may refer to bodies
    if (const auto section = top.find(key))
      scene.extensions[key] = find_scene_extension(key)->parse(reader, *section, scene);
  if (const auto check = scheme_of(scene.solver).check)  // the scheme checks the whole scene last
    check(reader, top, scene);
  return scene;
}

SceneDescription load_scene(const std::filesystem::path& file) {
  const std::string name = file.string();
  std::error_code error;
  if (!std::filesystem::exists(file, error)) throw SceneError({name, 0, 0}, "", "scene file not found");
  if (std::filesystem::is_directory(file, error))
    throw SceneError({name, 0, 0}, "", "is a directory, not a scene file");
  std::ifstream in(file, std::ios::binary);
  if (!in) throw SceneError({name, 0, 0}, "", "cannot open the scene file");
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw SceneError({name, 0, 0}, "", "cannot read the scene file");
  return parse_scene(text.str(), name);
}

}  // namespace mpm
