// `output:` (docs/scene-reference.md, output): where and how often the frames are written, and which fields.
#include <fmt/format.h>

#include "mpm/output_writer.hpp"
#include "sections.hpp"

namespace mpm::sections {

OutputDescription read_output(const io::YamlReader& reader, const io::YamlValue& value, const SceneDescription& scene) {
  const io::YamlMap map = reader.map(value);
  map.allow({"directory", "prefix", "interval", "fields", "grid", "histories"});
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
  return output;
}

}  // namespace mpm::sections
