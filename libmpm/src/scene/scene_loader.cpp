// The scene file as a whole: the top-level keys, the sections in the order they depend on each other (each
// read by its own file in scene/), then the optional modules' sections (scene_extension.hpp).
#include "mpm/scene/scene_loader.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <fstream>
#include <sstream>
#include <system_error>

#include "mpm/core/units.hpp"
#include "mpm/scene/scene_extension.hpp"
#include "mpm/scene/scene_keys.hpp"
#include "mpm/scene/spec_map.hpp"
#include "mpm/schemes/scheme_registry.hpp"
#include "sections.hpp"

namespace mpm {
namespace {

std::vector<std::string> unit_system_names() {
  std::vector<std::string> names;
  for (const auto& system : units::unit_systems()) names.emplace_back(system.name);
  return names;
}

/// The core's sections.
const std::vector<io::KeySpec>& core_keys() {
  using io::KeyType;
  static const std::vector<io::KeySpec> keys{
      {.name = "dimension",
       .type = KeyType::integer,
       .range = io::Range::closed(1, 3),
       .required = true,
       .description = "1D is uniaxial strain, 2D is plane strain (or axisymmetric, `grid.coordinates`)",
       .fork_refusal = "the state layout: the checkpoint's particles and grid are of its dimension"},
      {.name = "units",
       .type = KeyType::choice,
       .choices = unit_system_names(),
       .default_value = std::string("m-s-kg"),
       .description = "[Units](#units): the unit system of the scene's bare numbers (`mm-ms-g`: lengths in mm, times "
                      "in ms, masses in g, so forces in N, stresses in MPa, densities in g/mm^3); a number with its "
                      "unit (`210 GPa`) is that value in any system. The program computes and writes in SI"},
      {.name = "grid",
       .type = KeyType::map,
       .required = true,
       .description = "[Background grid](#grid)",
       .fork_refusal = "the grid is the checkpoint's",
       .keys = grid_keys()},
      {.name = "materials",
       .type = KeyType::named_map,
       .required = true,
       .description = "[Materials](#materials), at least one",
       .type_text = "map from names to materials",
       .fork_refusal = "a material's model and state come from the checkpoint (a fork may change its parameters)",
       .keys = material_keys()},
      {.name = "bodies",
       .type = KeyType::list,
       .required = true,
       .description = "[Bodies](#bodies), at least one",
       .fork_refusal = "the bodies' particles come from the checkpoint",
       .keys = body_keys()},
      {.name = "sets",
       .type = KeyType::named_map,
       .absent = "none",
       .description = "[Particle sets](#sets): named sets of particles, chosen by body, initial region and id",
       .type_text = "map from names to sets",
       .keys = set_keys()},
      {.name = "conditions",
       .type = KeyType::list,
       .absent = "none",
       .description = "[Conditions on particle sets](#conditions): held velocities, forces, initial velocities",
       .fork_refusal = "a fork may change a condition's set, velocity and force, not add or remove conditions",
       .keys = condition_keys()},
      {.name = "solver", .type = KeyType::map, .required = true, .description = "[Solver settings](#solver)"},
      {.name = "output",
       .type = KeyType::map,
       .absent = "every key's default",
       .description = "[Output](#output)",
       .run_control = true,
       .keys = output_keys()},
  };
  return keys;
}

}  // namespace

std::vector<io::KeySpec> scene_keys() {
  std::vector<io::KeySpec> keys = core_keys();
  // the solver's keys name the registered schemes and shape functions: built now, not cached with the others
  for (auto& key : keys)
    if (key.name == "solver") key.keys = solver_keys();
  for (const auto& name : scene_extension_keys()) {
    const SceneExtension& extension = *find_scene_extension(name);
    if (!extension.parse) continue;  // a module without a section (prepared from the materials' keys)
    keys.push_back({.name = name,
                    .type = io::KeyType::map,
                    .description = extension.description,
                    .type_text = "map, or nothing",
                    .keys = extension.keys});
  }
  return keys;
}

SceneDescription parse_scene(const std::string& yaml_text, const std::string& file_name_for_messages) {
  io::YamlReader reader(file_name_for_messages);
  YAML::Node root;
  try {
    root = YAML::Load(yaml_text);
  } catch (const YAML::Exception& e) {
    reader.fail(e.mark, "", "YAML syntax error: " + e.msg);
  }
  const std::vector<io::KeySpec> keys = scene_keys();
  const std::string top_keys = fmt::format("{}", fmt::join(key_names(core_keys()), ", "));
  if (root.IsNull())
    throw SceneError({file_name_for_messages, 1, 1}, "",
                     "the scene is empty: expected a map with the keys " + top_keys);
  const io::YamlValue top_value{root, "", io::mark_of(root, YAML::Mark::null_mark())};
  if (!root.IsMap())
    reader.fail(top_value, fmt::format("expected a map with the keys {}, got {}", top_keys, io::describe(root)));
  const io::SpecMap top(reader, top_value, keys);

  SceneDescription scene;
  scene.file = file_name_for_messages;
  scene.source = yaml_text;
  scene.dimension = top.integer("dimension");
  scene.units = top.choice("units");  // before any other number is read: they are in its units
  reader.set_unit_system(*units::find_unit_system(scene.units));
  scene.grid = sections::read_grid(reader, top.required("grid"), scene.dimension);
  scene.materials = sections::read_materials(reader, top.required("materials"));
  scene.bodies = sections::read_bodies(reader, top.required("bodies"), scene);
  if (const auto sets = top.find("sets")) scene.sets = sections::read_sets(reader, *sets, scene);
  if (const auto conditions = top.find("conditions"))
    scene.conditions = sections::read_conditions(reader, *conditions, scene);
  scene.solver = sections::read_solver(reader, top.required("solver"), scene);
  if (const auto output = top.find("output")) scene.output = sections::read_output(reader, *output, scene);
  for (const auto& key : scene_extension_keys())  // module sections last: they may refer to bodies
    if (const auto section = find_scene_extension(key)->parse ? top.find(key) : std::nullopt)
      scene.extensions[key] = find_scene_extension(key)->parse(reader, *section, scene);
  for (const auto& key : scene_extension_keys())  // then the defaults a present section implies for the others
    if (const auto complete = find_scene_extension(key)->complete; complete && scene.extensions.count(key))
      complete(scene);
  if (const auto check = scheme_of(scene.solver).check)  // the scheme checks the whole scene last
    check(reader, top.map(), scene);
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
