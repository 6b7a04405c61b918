#pragma once
// Reading a body's `shape:` (docs/scene-reference.md, bodies[].shape): the primitives and set operations
// (shape_reader.cpp), polygons (polygon_shape.cpp), mesh and image files (file_shapes.cpp), and the bounding
// box the body section checks against the grid (shape_bounds.cpp).

#include <array>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "mpm/scene/scene.hpp"
#include "mpm/scene/yaml_reader.hpp"

namespace mpm::sections {

/// Reads the shape at `value`. `scene_file` locates relative file names; `whole_shape` is false inside a union,
/// intersection or difference; `labels` (may be null) receives the values of an image's `labels:` list (one
/// body per label).
ShapeDescription read_shape(const io::YamlReader& reader, const io::YamlValue& value, int dimension,
                            const std::string& scene_file, bool whole_shape, std::vector<double>* labels);

/// `type: polygon`: corners from `vertices` or a `file`, checked to be simple with a non-zero area.
void read_polygon(const io::YamlReader& reader, const io::YamlMap& map, const std::string& scene_file,
                  ShapeDescription& shape);
/// `mesh: FILE` with its transformation (and the 2D section).
void read_mesh(const io::YamlReader& reader, const io::YamlMap& map, int dimension, const std::string& scene_file,
               ShapeDescription& shape);
/// `image: FILE` with its pixel size, origin and pixel selection.
void read_image(const io::YamlReader& reader, const io::YamlMap& map, int dimension, const std::string& scene_file,
                bool whole_shape, ShapeDescription& shape, std::vector<double>* labels);

/// `particles: FILE` (.vtu or .csv) with an optional `body` (the rows of that body of this program's output).
void read_particles(const io::YamlReader& reader, const io::YamlMap& map, const std::string& scene_file,
                    bool whole_shape, ShapeDescription& shape);

/// Lower and upper corners (first `dimension` axes meaningful), m.
using Bounds = std::pair<std::array<double, 3>, std::array<double, 3>>;
/// Axis-aligned bounding box of a shape, or nothing when only the mesh or image file knows it (the scene
/// builder checks those).
std::optional<Bounds> bounding_box(const ShapeDescription& shape, int dimension);

}  // namespace mpm::sections
