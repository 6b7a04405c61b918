// `image: FILE` (2D: .png, .pgm; 3D: .vti; docs/scene-reference.md, bodies[].shape): the pixels selected by a
// threshold or a label form the body (image_region.cpp), filled on the lattice or one particle per pixel
// (`resolution: pixel`); `labels` makes one body per label. Its volume is the selected pixels', and `volume`
// defaults to it.
#include <fmt/format.h>

#include <algorithm>

#include "mpm/geometry/image_region.hpp"
#include "mpm/scene/yaml_reader.hpp"
#include "shape_kinds.hpp"

namespace mpm::geometry {
namespace {
namespace image {  // named: the library compiles in unity batches (cmake/unity_libraries.cmake)

const std::vector<io::KeySpec>& keys() {
  using io::KeyType;
  static const std::vector<io::KeySpec> k{
      {.name = "image",
       .type = KeyType::name,
       .required = true,
       .description = "a picture `.png` or `.pgm` (binary P5) in 2D, a VTK image `.vti` in 3D, relative to the scene "
                      "file's folder"},
      {.name = "pixel_size",
       .type = KeyType::list,
       .unit = "m",
       .range = io::Range::above(0),
       .absent = "required in 2D; the `.vti` file's spacing in 3D",
       .description = "the size of a pixel or voxel",
       .type_text = "number, or list of `dimension` numbers"},
      {.name = "origin",
       .type = KeyType::list,
       .unit = "m",
       .absent = "0; the `.vti` file's",
       .description = "the lower corner of the image (a `.vti` file's gives the voxel centres, minus half a voxel)",
       .type_text = "list of `dimension` numbers"},
      {.name = "threshold",
       .type = KeyType::number,
       .absent = "one of threshold, label, labels",
       .description = "the pixels with a value >= threshold form the body"},
      {.name = "label",
       .type = KeyType::number,
       .absent = "one of threshold, label, labels",
       .description = "the pixels with exactly this value form the body"},
      {.name = "labels",
       .type = KeyType::list,
       .absent = "one of threshold, label, labels",
       .description = "one body per value, named `<name>_<label>`, with the body's other keys (whole shape only)",
       .type_text = "list of numbers"},
      {.name = "resolution",
       .type = KeyType::choice,
       .choices = {"grid", "pixel"},
       .default_value = std::string("grid"),
       .description = "`grid`: the lattice fill; `pixel`: one particle at the centre of every selected pixel, with "
                      "its area or volume (whole shape only)"},
  };
  return k;
}

/// Exactly one of threshold, label and labels; each value of `labels` makes a body of its own (context.bodies).
void read_pixel_selection(const io::YamlReader& reader, const io::YamlMap& map, const ShapeContext& context,
                          ImageShape& image) {
  std::vector<io::YamlValue> selections;
  for (const char* key : {"threshold", "label", "labels"})
    if (const auto value = map.find(key)) selections.push_back(*value);
  if (selections.empty())
    reader.fail(map.self(),
                "an image body needs threshold (pixels with a value >= threshold), label (pixels with that value) "
                "or labels (one body per value)");
  if (selections.size() > 1) reader.fail(selections[1], "give one of threshold, label and labels");
  if (const auto threshold = map.find("threshold")) image.threshold = reader.number(*threshold);
  if (const auto label = map.find("label")) image.label = reader.number(*label);
  if (const auto list = map.find("labels")) {
    if (!context.bodies || !context.whole_shape)
      reader.fail(*list,
                  "labels (one body per label) needs the image to be the whole shape of the body; use label here");
    const auto items = reader.list(*list, std::nullopt, "label values");
    if (items.empty()) reader.fail(*list, "expected at least one label value");
    std::vector<double> labels;
    for (const auto& item : items) {
      const double value = reader.number(item);
      if (std::find(labels.begin(), labels.end(), value) != labels.end())
        reader.fail(item, fmt::format("label {} is listed twice", value));
      labels.push_back(value);
    }
    for (const double value : labels) {
      ImageShape one = image;
      one.label = value;
      context.bodies->emplace_back(fmt::format("{}", value), one);
    }
  }
}

std::any parse(const io::YamlReader& reader, const io::YamlMap& map, const ShapeContext& context) {
  const io::YamlValue file = *map.find("image");
  const int dimension = context.dimension;
  if (dimension == 1) reader.fail(file, "image bodies are available in 2D (.png, .pgm) and 3D (.vti)");
  map.allow({"image", "pixel_size", "origin", "threshold", "label", "labels", "resolution"});
  ImageShape image;
  const std::vector<std::string> formats =
      dimension == 2 ? std::vector<std::string>{".png", ".pgm"} : std::vector<std::string>{".vti"};
  image.file = read_shape_file(reader, file, context.scene_file, formats, fmt::format("{}D image", dimension));
  if (const auto size = map.find("pixel_size")) {
    const auto sizes = reader.per_axis(*size, dimension, "numbers");
    for (int d = 0; d < dimension; ++d) image.pixel_size[d] = reader.number(sizes[d], io::Range::above(0), "m");
  } else if (dimension == 2) {
    map.required("pixel_size", "key", " (the size of a pixel, m)");
  }
  if (const auto origin = map.find("origin")) image.origin = reader.vector(*origin, dimension, io::Range::any(), "m");
  const std::size_t bodies_before = context.bodies ? context.bodies->size() : 0;
  read_pixel_selection(reader, map, context, image);
  if (const auto resolution = map.find("resolution")) {
    image.pixel_particles = reader.choice(*resolution, {"grid", "pixel"}) == "pixel";
    if (image.pixel_particles && !context.whole_shape)
      reader.fail(*resolution, "resolution: pixel needs the image to be the whole shape of the body");
    if (context.bodies)  // the bodies of `labels` take the resolution too
      for (std::size_t b = bodies_before; b < context.bodies->size(); ++b)
        std::any_cast<ImageShape&>((*context.bodies)[b].second).pixel_particles = image.pixel_particles;
  }
  return image;
}

std::string file_of(const std::any& spec) { return std::any_cast<const ImageShape&>(spec).file; }

template <int Dim>
std::unique_ptr<Region<Dim>> region(const std::any& spec, std::vector<std::string>*) {
  return make_image_region<Dim>(std::any_cast<const ImageShape&>(spec));
}

/// `resolution: pixel`: one particle per selected pixel; otherwise the lattice fill.
template <int Dim>
std::optional<ParticleSeeds<Dim>> fill(const std::any& spec, const GridGeometry<Dim>&) {
  const auto& image = std::any_cast<const ImageShape&>(spec);
  if (!image.pixel_particles) return std::nullopt;
  return fill_image_pixels<Dim>(image);
}

/// `resolution: pixel`: the selected pixels (their area over a pixel's).
std::optional<OwnParticleCount> own_count(const std::any& spec, int dimension) {
  const auto& image = std::any_cast<const ImageShape&>(spec);
  if (!image.pixel_particles) return std::nullopt;
  std::optional<Real> area;
  if (dimension == 2) area = make_image_region<2>(image)->exact_volume();
  if (dimension == 3) area = make_image_region<3>(image)->exact_volume();
  Real pixel = 1;
  for (int d = 0; d < dimension; ++d) pixel *= image.pixel_size[d];
  return OwnParticleCount{pixel > 0 ? area.value_or(0) / pixel : 0, true};
}

}  // namespace image
}  // namespace

ShapeKind image_kind() {
  using namespace image;
  ShapeKind k;
  k.name = "image";
  k.noun = "an image";
  k.description = "the pixels of a picture (2D) or voxels of a VTK image (3D) selected by a threshold or a label";
  k.keyed = true;
  k.keys = keys();
  k.traits.dimensions = {false, true, true};
  k.traits.exact_volume = true;
  k.traits.exact_by_default = true;
  k.parse = parse;
  k.file = file_of;
  k.region_2d = region<2>;
  k.region_3d = region<3>;
  k.fill_2d = fill<2>;
  k.fill_3d = fill<3>;
  k.own_count = own_count;
  return k;
}

}  // namespace mpm::geometry
