// Shapes read from files: `mesh:` (a closed surface, STL/OBJ/OFF/PLY), `image:` (PNG/PGM in 2D, VTI in 3D) and
// `particles:` (a particle set, VTU or CSV).
// The files themselves are read by geometry/ when the body is filled; here only their names and keys.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <system_error>

#include "sections.hpp"
#include "shapes.hpp"

namespace mpm::sections {
namespace {

std::string lower_case(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return std::tolower(c); });
  return text;
}

/// A mesh or image file name: relative names are taken from the scene file's folder; the format (by
/// extension) must be one of `extensions` and the file must exist.
std::string read_file_name(const YamlReader& reader, const YamlValue& value, const std::string& scene_file,
                           const std::vector<std::string>& extensions, std::string_view what) {
  const std::string name = reader.name(value);
  std::filesystem::path path(name);
  if (path.is_relative()) path = std::filesystem::path(scene_file).parent_path() / path;
  const std::string extension = lower_case(path.extension().string());
  if (!contains(extensions, extension))
    reader.fail(value, fmt::format("unsupported {} format '{}' of '{}'; supported: {}", what, extension, name,
                                   fmt::join(extensions, ", ")));
  std::error_code error;
  if (!std::filesystem::exists(path, error))
    reader.fail(value, fmt::format("{} file '{}' not found (looked for {})", what, name, path.string()));
  return path.lexically_normal().string();
}

/// Exactly one of threshold, label and labels; `labels` values go to `labels` (one body per label).
void read_pixel_selection(const YamlReader& reader, const YamlMap& map, bool whole_shape, ShapeDescription& shape,
                          std::vector<double>* labels) {
  std::vector<YamlValue> selections;
  for (const char* key : {"threshold", "label", "labels"})
    if (const auto value = map.find(key)) selections.push_back(*value);
  if (selections.empty())
    reader.fail(map.self(),
                "an image body needs threshold (pixels with a value >= threshold), label (pixels with that value) "
                "or labels (one body per value)");
  if (selections.size() > 1) reader.fail(selections[1], "give one of threshold, label and labels");
  if (const auto threshold = map.find("threshold")) shape.threshold = reader.number(*threshold);
  if (const auto label = map.find("label")) shape.label = reader.number(*label);
  if (const auto list = map.find("labels")) {
    if (!labels || !whole_shape)
      reader.fail(*list,
                  "labels (one body per label) needs the image to be the whole shape of the body; use label here");
    const auto items = reader.list(*list, std::nullopt, "label values");
    if (items.empty()) reader.fail(*list, "expected at least one label value");
    for (const auto& item : items) {
      const double value = reader.number(item);
      if (std::find(labels->begin(), labels->end(), value) != labels->end())
        reader.fail(item, fmt::format("label {} is listed twice", value));
      labels->push_back(value);
    }
  }
}

}  // namespace

void read_mesh(const YamlReader& reader, const YamlMap& map, int dimension, const std::string& scene_file,
               ShapeDescription& shape) {
  const YamlValue file = *map.find("mesh");
  if (dimension == 1) reader.fail(file, "mesh bodies are available in 2D (a section of the mesh) and 3D");
  std::vector<std::string> keys{"mesh", "scale", "rotation", "translation"};
  if (dimension == 2) keys.push_back("section");
  map.allow(keys);
  shape.type = "mesh";
  shape.file = read_file_name(reader, file, scene_file, {".stl", ".obj", ".off", ".ply"}, "mesh");
  if (const auto scale = map.find("scale")) shape.scale = reader.number(*scale, Range::above(0), "");
  if (const auto rotation = map.find("rotation")) shape.rotation = reader.vector(*rotation, 3, Range::any(), "degrees");
  if (const auto translation = map.find("translation"))
    shape.translation = reader.vector(*translation, 3, Range::any(), "m");
  if (dimension == 2)
    shape.section = reader.number(
        map.required("section", "key", " (a 2D body is the section of the mesh by the plane z = section, m)"));
}

void read_image(const YamlReader& reader, const YamlMap& map, int dimension, const std::string& scene_file,
                bool whole_shape, ShapeDescription& shape, std::vector<double>* labels) {
  const YamlValue file = *map.find("image");
  if (dimension == 1) reader.fail(file, "image bodies are available in 2D (.png, .pgm) and 3D (.vti)");
  map.allow({"image", "pixel_size", "origin", "threshold", "label", "labels", "resolution"});
  shape.type = "image";
  const std::vector<std::string> formats =
      dimension == 2 ? std::vector<std::string>{".png", ".pgm"} : std::vector<std::string>{".vti"};
  shape.file = read_file_name(reader, file, scene_file, formats, fmt::format("{}D image", dimension));
  if (const auto size = map.find("pixel_size")) {
    const auto sizes = reader.per_axis(*size, dimension, "numbers");
    for (int d = 0; d < dimension; ++d) shape.pixel_size[d] = reader.number(sizes[d], Range::above(0), "m");
  } else if (dimension == 2) {
    map.required("pixel_size", "key", " (the size of a pixel, m)");
  }
  if (const auto origin = map.find("origin")) shape.image_origin = reader.vector(*origin, dimension, Range::any(), "m");
  read_pixel_selection(reader, map, whole_shape, shape, labels);
  if (const auto resolution = map.find("resolution")) {
    shape.pixel_particles = reader.choice(*resolution, {"grid", "pixel"}) == "pixel";
    if (shape.pixel_particles && !whole_shape)
      reader.fail(*resolution, "resolution: pixel needs the image to be the whole shape of the body");
  }
}

void read_particles(const YamlReader& reader, const YamlMap& map, const std::string& scene_file, bool whole_shape,
                    ShapeDescription& shape) {
  const YamlValue file = *map.find("particles");
  if (!whole_shape)
    reader.fail(file, "a particle file is the whole shape of a body, not part of a union, intersection or difference");
  map.allow({"particles", "body"});
  shape.type = "particles";
  shape.file = read_file_name(reader, file, scene_file, {".vtu", ".csv"}, "particle");
  if (const auto body = map.find("body")) shape.particle_body = reader.integer(*body, 0);
}

}  // namespace mpm::sections
