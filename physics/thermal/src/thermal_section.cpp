#include "thermal_section.hpp"

#include "mpm/thermal/thermal_description.hpp"

namespace mpm::thermal {
namespace {

using io::YamlMap;
using io::YamlReader;
using io::YamlValue;

/// `boundary:` faces, each held at a temperature or given a heat flux.
void read_boundary(const YamlReader& reader, const YamlValue& value, int dimension, ThermalDescription& thermal) {
  const YamlMap faces = reader.map(value);
  const auto& names = GridDescription::face_names;
  faces.allow(std::vector<std::string>(names.begin(), names.begin() + 2 * dimension));
  for (int f = 0; f < 2 * dimension; ++f) {
    const auto face = faces.find(names[f]);
    if (!face) continue;
    const YamlMap condition = reader.map(*face);
    condition.allow({"temperature", "flux"});
    ThermalFace& thermal_face = thermal.boundary[f];
    thermal_face.where = reader.location(face->mark);
    const auto temperature = condition.find("temperature");
    const auto flux = condition.find("flux");
    if (temperature && flux) reader.fail(*flux, "give either temperature (K) or flux (W/m^2) on a face, not both");
    if (!temperature && !flux) reader.fail(*face, "expected temperature: ... (K) or flux: ... (W/m^2)");
    if (temperature) thermal_face.temperature = reader.expression(*temperature, {"t"});
    if (flux) thermal_face.flux = reader.expression(*flux, {"t"});
  }
}

/// `fixed_temperature:` boxes whose particles are held at a temperature.
std::vector<FixedTemperatureRegion> read_fixed_temperature(const YamlReader& reader, const YamlValue& value,
                                                           int dimension) {
  std::vector<FixedTemperatureRegion> regions;
  for (const auto& item : reader.list(value, std::nullopt, "boxes {min, max, temperature}")) {
    const YamlMap map = reader.map(item);
    map.allow({"min", "max", "temperature"});
    const YamlValue min = map.required("min"), max = map.required("max"), temperature = map.required("temperature");
    FixedTemperatureRegion region;
    region.where = reader.location(item.mark);
    region.min = reader.vector(min, dimension, io::Range::any(), "m");
    region.max = reader.vector(max, dimension, io::Range::any(), "m");
    for (int d = 0; d < dimension; ++d)
      if (!(region.max[d] > region.min[d])) reader.fail(max, "must exceed min on every axis");
    region.temperature = reader.expression(temperature, {"t"});
    regions.push_back(std::move(region));
  }
  return regions;
}

}  // namespace

std::any parse_thermal_section(const YamlReader& reader, const YamlValue& section, const SceneDescription& scene) {
  ThermalDescription thermal;
  thermal.where = reader.location(section.mark);
  if (section.node.IsNull()) return thermal;  // `thermal:` alone: conduction with insulated boundaries
  const YamlMap map = reader.map(section);
  map.allow({"initial_temperature", "source", "boundary", "fixed_temperature"});
  if (const auto initial = map.find("initial_temperature"))
    thermal.initial_temperature = reader.expression(*initial, {"x", "y", "z"});
  if (const auto source = map.find("source")) thermal.source = reader.expression(*source, {"x", "y", "z", "t"});
  if (const auto boundary = map.find("boundary")) read_boundary(reader, *boundary, scene.dimension, thermal);
  if (const auto fixed = map.find("fixed_temperature"))
    thermal.fixed_temperature = read_fixed_temperature(reader, *fixed, scene.dimension);
  return thermal;
}

}  // namespace mpm::thermal
