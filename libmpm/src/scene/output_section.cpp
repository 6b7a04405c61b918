// `output:` (docs/scene-reference.md, output): where and how often the frames are written, and which fields.
#include <fmt/format.h>

#include "mpm/output/output_writer.hpp"
#include "mpm/scene/scene_keys.hpp"
#include "mpm/scene/spec_map.hpp"
#include "sections.hpp"

namespace mpm {

namespace {

using io::KeySpec;
using io::KeyType;
using io::Range;

/// `output.checkpoint`'s keys.
const std::vector<KeySpec>& checkpoint_keys() {
  static const std::vector<KeySpec> keys{
      {.name = "interval",
       .type = KeyType::number,
       .unit = "s",
       .range = Range::above(0),
       .description = "simulated time between checkpoints (one after the first step that reaches each multiple)"},
      {.name = "wall_interval",
       .type = KeyType::number,
       .unit = "s",
       .range = Range::above(0),
       .description = "wall-clock time between checkpoints"},
      {.name = "keep",
       .type = KeyType::integer,
       .range = Range::at_least(1),
       .default_value = 2.0,
       .description = "the newest checkpoints kept, older ones are removed"},
      {.name = "directory",
       .type = KeyType::name,
       .absent = "`OUTPUT/checkpoints`",
       .description = "where they go (created; checked to be writable before the first step)"},
  };
  return keys;
}

}  // namespace

const std::vector<io::KeySpec>& output_keys() {
  static const std::vector<KeySpec> keys{
      {.name = "directory",
       .type = KeyType::name,
       .default_value = std::string("output"),
       .description = "where the files go; a relative path is relative to the working directory (`-o DIR` "
                      "overrides it)"},
      {.name = "prefix",
       .type = KeyType::name,
       .default_value = std::string("particles"),
       .description = "file-name prefix of the particle frames, without `/`"},
      {.name = "interval",
       .type = KeyType::number,
       .unit = "s",
       .range = Range::at_least(0),
       .default_value = 0.0,
       .description = "time between frames; 0 = first and last frame only"},
      {.name = "fields",
       .type = KeyType::list,
       .default_value = std::vector<std::string>{"velocity", "stress", "mass", "volume", "body"},
       .description = "the particle fields written in every frame; may be empty",
       .type_text = "list of strings",
       .allowed_text = "each once, from the [table below](#output-fields)"},
      {.name = "grid",
       .type = KeyType::boolean,
       .default_value = false,
       .description =
           "also write the grid at each frame (PREFIX_grid_NNNNNN.vti): nodal `mass`, `density` (m_I / V_I, "
           "V_I the volume a node stands for: a fluid's free surface is its contour at half the fluid's "
           "density, physics/fluids/README.md), `velocity`, `force` and the modules' nodal fields; the first "
           "frame's grid is empty (no step yet)"},
      {.name = "histories",
       .type = KeyType::list,
       .description = "probes, reactions, energies, extents: one CSV each, see [histories](#histories)",
       .keys = history_keys()},
      {.name = "checkpoint",
       .type = KeyType::map,
       .description = "when to write checkpoints, see [output.checkpoint](#outputcheckpoint)",
       .keys = checkpoint_keys()},
  };
  return keys;
}

namespace sections {
namespace {

/// `output.checkpoint: {interval, wall_interval, keep, directory}`.
CheckpointDescription read_checkpoint(const io::YamlReader& reader, const io::YamlValue& value) {
  const io::SpecMap map(reader, value, checkpoint_keys());
  CheckpointDescription checkpoint;
  checkpoint.enabled = true;
  checkpoint.where = reader.location(value.mark);
  checkpoint.interval = map.optional_number("interval");
  checkpoint.wall_interval = map.optional_number("wall_interval");
  checkpoint.keep = map.integer("keep");
  if (const auto directory = map.find("directory")) checkpoint.directory = reader.name(*directory);
  return checkpoint;
}

}  // namespace

OutputDescription read_output(const io::YamlReader& reader, const io::YamlValue& value, const SceneDescription& scene) {
  const io::SpecMap map(reader, value, output_keys());
  OutputDescription output;
  output.where = reader.location(value.mark);
  output.directory = map.name("directory");
  output.prefix = map.name("prefix");
  if (output.prefix.find_first_of("/\\") != std::string::npos)
    reader.fail(*map.find("prefix"), "must be a file name prefix, not a path (use directory for the folder)");
  output.interval = map.number("interval");
  output.fields = std::get<std::vector<std::string>>(map.spec("fields").default_value);
  if (const auto fields = map.find("fields")) {
    output.fields.clear();
    for (const auto& item : reader.list(*fields, std::nullopt, "field names")) {
      std::string field = reader.choice(item, output_field_names());
      if (contains(output.fields, field)) reader.fail(item, fmt::format("field '{}' is listed twice", field));
      output.fields.push_back(std::move(field));
    }
  }
  output.grid = map.boolean("grid");
  if (const auto histories = map.find("histories"))
    output.histories = read_histories(reader, *histories, scene, output.interval);
  if (const auto checkpoint = map.find("checkpoint")) output.checkpoint = read_checkpoint(reader, *checkpoint);
  return output;
}

}  // namespace sections
}  // namespace mpm
