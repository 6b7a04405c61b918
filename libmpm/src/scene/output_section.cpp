// `output:` (docs/scene-reference.md, output): where and how often the frames are written, and which fields.
#include <fmt/format.h>

#include "mpm/output_writer.hpp"
#include "sections.hpp"

namespace mpm::sections {
namespace {

/// `output.checkpoint: {interval, wall_interval, keep, directory}`.
CheckpointDescription read_checkpoint(const io::YamlReader& reader, const io::YamlValue& value) {
  const io::YamlMap map = reader.map(value);
  map.allow({"interval", "wall_interval", "keep", "directory"});
  CheckpointDescription checkpoint;
  checkpoint.enabled = true;
  checkpoint.where = reader.location(value.mark);
  if (const auto interval = map.find("interval"))
    checkpoint.interval = reader.number(*interval, io::Range::above(0), "s");
  if (const auto wall = map.find("wall_interval"))
    checkpoint.wall_interval = reader.number(*wall, io::Range::above(0), "s");
  if (const auto keep = map.find("keep")) checkpoint.keep = reader.integer(*keep, 1);
  if (const auto directory = map.find("directory")) checkpoint.directory = reader.name(*directory);
  return checkpoint;
}

}  // namespace

OutputDescription read_output(const io::YamlReader& reader, const io::YamlValue& value, const SceneDescription& scene) {
  const io::YamlMap map = reader.map(value);
  map.allow({"directory", "prefix", "interval", "fields", "grid", "histories", "checkpoint"});
  OutputDescription output;
  output.where = reader.location(value.mark);
  if (const auto directory = map.find("directory")) output.directory = reader.name(*directory);
  if (const auto prefix = map.find("prefix")) {
    output.prefix = reader.name(*prefix);
    if (output.prefix.find_first_of("/\\") != std::string::npos)
      reader.fail(*prefix, "must be a file name prefix, not a path (use directory for the folder)");
  }
  if (const auto interval = map.find("interval"))
    output.interval = reader.number(*interval, io::Range::at_least(0), "s");
  if (const auto fields = map.find("fields")) {
    output.fields.clear();
    for (const auto& item : reader.list(*fields, std::nullopt, "field names")) {
      std::string field = reader.choice(item, output_field_names());
      if (contains(output.fields, field)) reader.fail(item, fmt::format("field '{}' is listed twice", field));
      output.fields.push_back(std::move(field));
    }
  }
  if (const auto grid = map.find("grid")) output.grid = reader.boolean(*grid);
  if (const auto histories = map.find("histories"))
    output.histories = read_histories(reader, *histories, scene, output.interval);
  if (const auto checkpoint = map.find("checkpoint")) output.checkpoint = read_checkpoint(reader, *checkpoint);
  return output;
}

}  // namespace mpm::sections
