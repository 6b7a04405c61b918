/// Tests of the key specs of the scene sections (io/key_spec.hpp, io/spec_map.hpp, scene_keys.hpp): a section
/// reads through its specs (allowed keys, ranges, units, defaults), the structs' defaults are the specs', every key
/// a section accepts is in the generated tables of docs/scene-reference.md, and that file is current
/// (scene_reference.hpp).

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "mpm/app/modules.hpp"
#include "mpm/app/scene_reference.hpp"
#include "mpm/scene/scene_error.hpp"
#include "mpm/scene/scene_extension.hpp"
#include "mpm/scene/scene_keys.hpp"
#include "mpm/scene/scene_loader.hpp"
#include "mpm/scene/spec_map.hpp"
#ifdef MPM_WITH_THERMAL
#include "mpm/thermal/thermal_description.hpp"
#endif
#ifdef MPM_WITH_CONTACT
#include "mpm/contact/contact_description.hpp"
#endif

namespace {

using mpm::io::KeySpec;
using mpm::io::KeyType;
using mpm::io::Range;

/// A section of one key of each kind the reader takes.
const std::vector<KeySpec>& sample_keys() {
  static const std::vector<KeySpec> keys{
      {.name = "length", .type = KeyType::number, .unit = "m", .range = Range::above(0), .default_value = 2.5},
      {.name = "count", .type = KeyType::integer, .range = Range::at_least(1), .default_value = 3.0},
      {.name = "axis", .type = KeyType::integer, .range = Range::closed(0, 2), .required = true},
      {.name = "mode", .type = KeyType::choice, .choices = {"fast", "exact"}, .default_value = std::string("fast")},
      {.name = "label", .type = KeyType::name, .default_value = std::string("none")},
      {.name = "on", .type = KeyType::boolean, .default_value = false},
      {.name = "walls",
       .type = KeyType::list,
       .keys = {{.name = "speed", .type = KeyType::expression, .run_control = true}}},
      {.name = "files", .type = KeyType::map, .run_control = true},
  };
  return keys;
}

/// The message of the SceneError reading `yaml` through sample_keys() throws, or "" when it reads.
std::string read_sample(const std::string& yaml) {
  const mpm::io::YamlReader reader("sample.yaml");
  const mpm::io::YamlValue value{YAML::Load(yaml), "section", YAML::Mark()};
  try {
    const mpm::io::SpecMap map(reader, value, sample_keys());
    map.number("length");
    map.integer("count");
    map.integer("axis");
    map.choice("mode");
  } catch (const mpm::SceneError& e) {
    return e.what();
  }
  return "";
}

TEST(KeySpec, ReadsValuesAndDefaultsThroughTheSpec) {
  const mpm::io::YamlReader reader("sample.yaml");
  const mpm::io::YamlValue value{YAML::Load("{axis: 1, length: 0.5, on: yes}"), "section", YAML::Mark()};
  const mpm::io::SpecMap map(reader, value, sample_keys());
  EXPECT_EQ(map.number("length"), 0.5);
  EXPECT_EQ(map.integer("count"), 3);  // the spec's default
  EXPECT_EQ(map.integer("axis"), 1);
  EXPECT_EQ(map.choice("mode"), "fast");
  EXPECT_EQ(map.name("label"), "none");
  EXPECT_TRUE(map.boolean("on"));
  EXPECT_FALSE(map.optional_number("length") == std::nullopt);
  EXPECT_THROW(map.number("no_such_key"), std::logic_error);  // a key without a spec is a programming error
  EXPECT_THROW(map.boolean("mode"), std::logic_error);        // read as another type than its default's
}

TEST(KeySpec, MessagesTakeRangeUnitAndKeysFromTheSpec) {
  EXPECT_EQ(read_sample("{axis: 0, length: -1}"),
            "sample.yaml:1:19: section.length: out of range: must be > 0 m, got -1 m");
  EXPECT_EQ(read_sample("{axis: 0, count: 0}"), "sample.yaml:1:18: section.count: out of range: must be >= 1, got 0");
  EXPECT_EQ(read_sample("{axis: 4}"), "sample.yaml:1:8: section.axis: must be 0, 1 or 2, got 4");
  EXPECT_EQ(read_sample("{length: 1}"), "sample.yaml:1:1: section.axis: missing required key 'axis'");
  EXPECT_EQ(read_sample("{axis: 0, mode: slow}"),
            "sample.yaml:1:17: section.mode: invalid value 'slow'; valid values: fast, exact");
  EXPECT_EQ(read_sample("{axis: 0, colour: red}"),
            "sample.yaml:1:11: section.colour: unknown key 'colour'; valid keys: length, count, axis, mode, label, "
            "on, walls, files");
}

TEST(KeySpec, RunControlPatternsComeFromTheSpecs) {
  EXPECT_EQ(mpm::io::run_control_patterns(sample_keys(), "top"),
            (std::vector<std::string>{"top.walls.*.speed", "top.files"}));
}

TEST(KeySpec, ForkRulesTakeTheMostSpecificDeclaration) {
  // A refused section with an allowed key inside, and a refused key inside an allowed one: the rule with the most
  // parts decides; a refusal wins a tie; a key no rule matches has none (the caller's general reason).
  using mpm::io::KeySpec;
  using mpm::io::KeyType;
  const std::vector<KeySpec> keys{
      {.name = "box",
       .type = KeyType::map,
       .fork_refusal = "the box is fixed",
       .keys = {{.name = "size"}, {.name = "faces", .type = KeyType::named_map, .run_control = true}}},
      {.name = "items",
       .type = KeyType::list,
       .keys = {{.name = "speed", .run_control = true}, {.name = "start", .fork_refusal = "acts at t = 0"}}},
      {.name = "colour", .type = KeyType::name},
  };
  auto rules = mpm::io::fork_rules(keys, "top");
  ASSERT_EQ(rules.size(), 4u);
  const auto decide = [&](const std::string& key) {
    const mpm::io::ForkRule* rule = mpm::io::fork_rule_for(rules, key);
    return !rule ? std::string("none") : rule->allowed ? std::string("allowed") : rule->reason;
  };
  EXPECT_EQ(decide("top.box.size"), "the box is fixed");
  EXPECT_EQ(decide("top.box.faces.x_min.velocity[1]"), "allowed");
  EXPECT_EQ(decide("top.box.faces"), "allowed");
  EXPECT_EQ(decide("top.items[2].speed"), "allowed");
  EXPECT_EQ(decide("top.items[0].start"), "acts at t = 0");
  EXPECT_EQ(decide("top.items"), "none");  // a list that grew: no rule declares it
  EXPECT_EQ(decide("top.colour"), "none");
  rules.push_back({"top.items.*.speed", false, "refused too"});  // a tie: the refusal decides
  EXPECT_EQ(decide("top.items[2].speed"), "refused too");
}

TEST(KeySpec, ReferenceCellsSayTypeDefaultAndAllowedValues) {
  const auto& keys = sample_keys();
  EXPECT_EQ(mpm::io::key_default_text(keys[0]), "2.5");
  EXPECT_EQ(mpm::io::key_allowed_text(keys[0]), "> 0");
  EXPECT_EQ(mpm::io::key_default_text(keys[2]), "required");
  EXPECT_EQ(mpm::io::key_allowed_text(keys[2]), "0, 1 or 2");
  EXPECT_EQ(mpm::io::key_allowed_text(keys[3]), "`fast`, `exact`");
  EXPECT_EQ(mpm::io::key_default_text(keys[5]), "`false`");
  EXPECT_EQ(mpm::io::key_type_text(keys[6]), "list of maps");
  const std::string table = mpm::key_table(keys);
  EXPECT_NE(table.find("| `length` | number | m | 2.5 | > 0 |  |\n"), std::string::npos) << table;
  EXPECT_NE(table.find("| `files` | map |  | none |  | ; a fork may change it and everything in it |"),
            std::string::npos)
      << table;
}

// The structs of scene.hpp (and of the modules' descriptions) start from the specs' defaults, so that code that
// builds a description without the loader gets what a scene without the key gets.
TEST(SceneKeys, StructDefaultsAreTheSpecs) {
  const auto& output = mpm::output_keys();
  const mpm::OutputDescription o;
  EXPECT_EQ(o.directory, mpm::io::find_key(output, "directory")->default_text());
  EXPECT_EQ(o.prefix, mpm::io::find_key(output, "prefix")->default_text());
  EXPECT_EQ(o.interval, mpm::io::find_key(output, "interval")->default_number());
  EXPECT_EQ(o.fields, std::get<std::vector<std::string>>(mpm::io::find_key(output, "fields")->default_value));
  EXPECT_EQ(o.grid, std::get<bool>(mpm::io::find_key(output, "grid")->default_value));
  EXPECT_EQ(mpm::CheckpointDescription{}.keep, mpm::io::find_key_path(output, "checkpoint.keep")->default_number());

  const auto& body = mpm::body_keys();
  const mpm::BodyDescription b;
  for (const int count : b.particles_per_cell)
    EXPECT_EQ(count, mpm::io::find_key(body, "particles_per_cell")->default_number());
  for (const auto& component : b.velocity) EXPECT_EQ(component, mpm::io::find_key(body, "velocity")->default_text());
  EXPECT_EQ(b.domains, mpm::io::find_key(body, "domains")->default_text());

  const std::vector<mpm::io::KeySpec> solver = mpm::solver_keys();
  const mpm::SolverDescription s;
  const auto solver_default = [&](const char* key) { return mpm::io::find_key(solver, key)->default_number(); };
  EXPECT_EQ(s.scheme, mpm::io::find_key(solver, "scheme")->default_text());
  EXPECT_EQ(s.shape_function, mpm::io::find_key(solver, "shape_function")->default_text());
  EXPECT_EQ(enum_name(s.velocity_transfer), mpm::io::find_key(solver, "velocity_transfer")->default_text());
  EXPECT_EQ(s.flip_fraction, solver_default("flip_fraction"));
  EXPECT_EQ(s.damping, solver_default("damping"));
  EXPECT_EQ(s.mass_cutoff, solver_default("mass_cutoff"));
  EXPECT_EQ(s.snapshot_interval, solver_default("snapshot_interval"));
  EXPECT_EQ(s.sort_interval, solver_default("sort_interval"));
  EXPECT_EQ(s.energy_tolerance, solver_default("energy_tolerance"));
  EXPECT_EQ(enum_name(s.on_energy_drift), mpm::io::find_key(solver, "on_energy_drift")->default_text());

  mpm::app::register_modules();
#ifdef MPM_WITH_THERMAL
  const auto& thermal = mpm::find_scene_extension("thermal")->keys;
  EXPECT_EQ(mpm::thermal::ThermalDescription{}.source, mpm::io::find_key(thermal, "source")->default_text());
#endif
#ifdef MPM_WITH_CONTACT
  const auto& contact = mpm::find_scene_extension("contact")->keys;
  const mpm::contact::ContactDescription c;
  EXPECT_EQ(c.friction, mpm::io::find_key(contact, "friction")->default_number());
  EXPECT_EQ(c.normals, mpm::io::find_key(contact, "normals")->default_text());
  EXPECT_EQ(c.onset, mpm::io::find_key(contact, "onset")->default_text());
  EXPECT_EQ(c.force_interval, mpm::io::find_key(contact, "force_interval")->default_number());
  EXPECT_EQ(mpm::contact::PlaneDescription{}.friction,
            mpm::io::find_key_path(contact, "planes.friction")->default_number());
#endif
}

/// docs/scene-reference.md as text.
std::string scene_reference_text() {
  std::ifstream in(std::filesystem::path(MPM_SOURCE_DIR) / "docs" / "scene-reference.md", std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// Every section that declares its keys has its generated table in docs/scene-reference.md, so every key a section
// accepts (its reader allows exactly its specs' names) is documented. (That the whole file is current is checked
// through the program, whose process registers only the modules' kinds: SceneReference.IsCurrent in
// tests/apps/test_reference_command.cpp; this process also holds the output fields other tests register.)
TEST(SceneReference, DocumentsEveryDeclaredKeyAndField) {
  mpm::app::register_modules();
  const std::string text = scene_reference_text();
  for (const auto& path : mpm::sections_with_keys()) {
    const std::string content = path.empty() ? "top-level keys" : "keys of " + path;
    const auto table = mpm::section_key_table(path);
    ASSERT_TRUE(table) << path;
    EXPECT_NE(text.find("<!-- generated by `mpm reference`: " + content + " -->\n" + *table), std::string::npos)
        << "docs/scene-reference.md has no current table of " << content;
  }
}

// A section's reader allows exactly the keys of its spec: an unknown key's message lists them.
TEST(SceneKeys, ReadersAllowExactlyTheirSpecs) {
  mpm::app::register_modules();
  const std::string scene = R"(dimension: 2
grid: {origin: [0, 0], extent: [1, 1], cell_size: 0.25}
materials: {steel: {model: linear_elastic, density: 7800, youngs_modulus: 2.0e11, poisson_ratio: 0.3}}
bodies: [{material: steel, shape: {type: box, min: [0.25, 0.25], max: [0.75, 0.75]}}]
solver: {end_time: 1.0e-3, cfl: 0.5}
output: {checkpoint: {}}
)";
  struct Case {
    std::string from, to, path;
  };
  const std::vector<Case> cases{
      {"dimension: 2", "dimension: 2\nunknown_section: 1", ""},
      {"{material: steel,", "{unknown: 1, material: steel,", "bodies"},
      {"output: {checkpoint: {}}", "output: {unknown: 1}", "output"},
      {"checkpoint: {}", "checkpoint: {unknown: 1}", "output.checkpoint"},
      {"solver: {end_time", "solver: {unknown: 1, end_time", "solver"},
  };
  const std::vector<mpm::io::KeySpec> top = mpm::scene_keys();
  for (const auto& c : cases) {
    std::string text = scene;
    text.replace(text.find(c.from), c.from.size(), c.to);
    try {
      mpm::parse_scene(text, "keys.yaml");
      ADD_FAILURE() << c.path << ": the unknown key was accepted";
    } catch (const mpm::SceneError& e) {
      const auto& keys = c.path.empty() ? top : mpm::io::find_key_path(top, c.path)->keys;
      std::string names;
      for (const auto& key : keys) names += (names.empty() ? "" : ", ") + key.name;
      EXPECT_NE(std::string(e.what()).find("valid keys: " + names), std::string::npos) << e.what();
    }
  }
}

}  // namespace
