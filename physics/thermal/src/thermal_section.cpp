#include "thermal_section.hpp"

#include <fmt/format.h>

#include "mpm/scene/spec_map.hpp"
#include "mpm/thermal/thermal_description.hpp"

namespace mpm::thermal {
namespace {

using io::KeySpec;
using io::KeyType;
using io::SpecMap;
using io::YamlReader;
using io::YamlValue;

/// The keys of a face of `boundary:`.
std::vector<KeySpec> face_keys() {
  return {{.name = "temperature",
           .type = KeyType::expression,
           .unit = "K",
           .description = "the face nodes are held at it; an expression of t; not with `flux`"},
          {.name = "flux",
           .type = KeyType::expression,
           .unit = "W/m^2",
           .description = "prescribed heat flux q.n (outward normal; positive = heat leaving); an expression of t; "
                          "not with `temperature`"}};
}

/// The keys of one box of `fixed_temperature:`.
std::vector<KeySpec> region_keys() {
  return {{.name = "min",
           .type = KeyType::list,
           .unit = "m",
           .required = true,
           .description = "lower corner of the box",
           .type_text = "list of `dimension` numbers"},
          {.name = "max",
           .type = KeyType::list,
           .unit = "m",
           .required = true,
           .description = "upper corner of the box",
           .type_text = "list of `dimension` numbers",
           .allowed_text = "> `min` on every axis"},
          {.name = "temperature",
           .type = KeyType::expression,
           .unit = "K",
           .required = true,
           .description = "the temperature the particles inside the box at t = 0 are held at; an expression of t"}};
}

/// `boundary:` faces, each held at a temperature or given a heat flux.
void read_boundary(const YamlReader& reader, const YamlValue& value, int dimension, ThermalDescription& thermal) {
  const io::YamlMap faces = reader.map(value);
  const auto& names = GridDescription::face_names;
  faces.allow(std::vector<std::string>(names.begin(), names.begin() + 2 * dimension), "face",
              fmt::format(" in {}D", dimension));
  for (int f = 0; f < 2 * dimension; ++f) {
    const auto face = faces.find(names[f]);
    if (!face) continue;
    const SpecMap condition(reader, *face, io::find_key(thermal_keys(), "boundary")->keys);
    ThermalFace& thermal_face = thermal.boundary[f];
    thermal_face.where = reader.location(face->mark);
    const auto temperature = condition.find("temperature");
    const auto flux = condition.find("flux");
    if (temperature && flux) reader.fail(*flux, "give either temperature (K) or flux (W/m^2) on a face, not both");
    if (!temperature && !flux) reader.fail(*face, "expected temperature: ... (K) or flux: ... (W/m^2)");
    if (temperature) thermal_face.temperature = reader.expression(*temperature, {"t"}, "K");
    if (flux) thermal_face.flux = reader.expression(*flux, {"t"}, "W/m^2");
  }
}

/// `fixed_temperature:` boxes whose particles are held at a temperature.
std::vector<FixedTemperatureRegion> read_fixed_temperature(const YamlReader& reader, const YamlValue& value,
                                                           int dimension) {
  std::vector<FixedTemperatureRegion> regions;
  for (const auto& item : reader.list(value, std::nullopt, "boxes {min, max, temperature}")) {
    const SpecMap map(reader, item, io::find_key(thermal_keys(), "fixed_temperature")->keys);
    const YamlValue min = map.required("min"), max = map.required("max"), temperature = map.required("temperature");
    FixedTemperatureRegion region;
    region.where = reader.location(item.mark);
    region.min = reader.vector(min, dimension, io::Range::any(), "m");
    region.max = reader.vector(max, dimension, io::Range::any(), "m");
    for (int d = 0; d < dimension; ++d)
      if (!(region.max[d] > region.min[d])) reader.fail(max, "must exceed min on every axis");
    region.temperature = reader.expression(temperature, {"t"}, "K");
    regions.push_back(std::move(region));
  }
  return regions;
}

}  // namespace

const std::vector<KeySpec>& thermal_keys() {
  static const std::vector<KeySpec> keys{
      {.name = "initial_temperature",
       .type = KeyType::expression,
       .unit = "K",
       .absent = "each material's `room_temperature`",
       .description = "the temperature at t = 0",
       .type_text = "number or expression of x, y, z",
       .allowed_text = "finite"},
      {.name = "source",
       .type = KeyType::expression,
       .unit = "W/m^3",
       .default_value = std::string("0"),
       .description = "volumetric heat source gamma* (eq. 5.18), per current volume",
       .type_text = "number or expression of x, y, z, t"},
      {.name = "boundary",
       .type = KeyType::named_map,
       .absent = "none: insulated",
       .description = "conditions on the faces (`x_min`, ... as in `grid.boundary`, those of the scene's "
                      "dimension), each `{temperature: T}` or `{flux: q}` (keys below)",
       .type_text = "map of faces",
       .keys = face_keys()},
      {.name = "fixed_temperature",
       .type = KeyType::list,
       .description = "boxes `{min, max, temperature}`: the particles inside the box at t = 0 are held at "
                      "`temperature` (expression of t); `max` > `min` on every axis",
       .type_text = "list of `{min, max, temperature}`",
       .keys = region_keys()},
      {.name = "particle_relaxation",
       .type = KeyType::number,
       .unit = "-",
       .range = io::Range::at_least(0),
       .default_value = 0.5,
       .description = "the particles' relaxation time towards the grid temperature (eqs TP.1-TP.2), in cell diffusion "
                      "times h^2 rho c / k; 0: the FLIP-type update alone, which keeps an initial jump's offsets"},
      {.name = "projection_iterations",
       .type = KeyType::integer,
       .range = io::Range::closed(0, 20),
       .default_value = 3.0,
       .description = "Richardson steps of the relaxation target's projection (eq. TP.2); 0: T~ itself"},
  };
  return keys;
}

std::any parse_thermal_section(const YamlReader& reader, const YamlValue& section, const SceneDescription& scene) {
  ThermalDescription thermal;
  thermal.where = reader.location(section.mark);
  if (section.node.IsNull()) return thermal;  // `thermal:` alone: conduction with insulated boundaries
  const SpecMap map(reader, section, thermal_keys());
  if (const auto initial = map.find("initial_temperature"))
    thermal.initial_temperature = reader.expression(*initial, {"x", "y", "z"}, "K");
  thermal.source = map.expression("source", {"x", "y", "z", "t"});
  if (const auto boundary = map.find("boundary")) read_boundary(reader, *boundary, scene.dimension, thermal);
  thermal.particle_relaxation = map.number("particle_relaxation");
  thermal.projection_iterations = map.integer("projection_iterations");
  if (const auto fixed = map.find("fixed_temperature"))
    thermal.fixed_temperature = read_fixed_temperature(reader, *fixed, scene.dimension);
  return thermal;
}

}  // namespace mpm::thermal
