// `materials.NAME.failure` (docs/scene-reference.md, materials): the failure criteria of a material and what its
// failed particles become (failure/failure_criteria.hpp), read through their key specs. A criterion that reads a
// measure the model does not keep (plastic strain, damage) is refused by asking the model's traits.
#include <fmt/format.h>

#include "mpm/materials/material_registry.hpp"
#include "mpm/scene/scene_keys.hpp"
#include "mpm/scene/spec_map.hpp"
#include "sections.hpp"

namespace mpm {

const std::vector<io::KeySpec>& failure_keys() {
  using io::KeyType;
  using io::Range;
  static const std::vector<io::KeySpec> keys{
      {.name = "damage",
       .type = KeyType::boolean,
       .default_value = false,
       .description = "fail when the Johnson-Cook damage reaches D = 1 (eq. B.16; a model with damage: damage_d1)"},
      {.name = "plastic_strain",
       .type = KeyType::number,
       .unit = "-",
       .range = Range::above(0),
       .absent = "not tested",
       .description = "fail when the equivalent plastic strain reaches this value (a model that keeps it)"},
      {.name = "principal_strain",
       .type = KeyType::number,
       .unit = "-",
       .range = Range::above(0),
       .absent = "not tested",
       .description = "fail when the largest principal logarithmic strain ln(lambda_max) of F (with the hoop "
                      "stretch when axisymmetric) reaches this value"},
      {.name = "principal_stress",
       .type = KeyType::number,
       .unit = "Pa",
       .range = Range::above(0),
       .absent = "not tested",
       .description = "fail when the largest principal Cauchy stress reaches this value (tension)"},
      {.name = "spall_pressure",
       .type = KeyType::number,
       .unit = "Pa",
       .range = Range::above(0),
       .absent = "not tested",
       .description = "spall strength: fail when the tensile mean stress tr(sigma)/3 reaches this value"},
      {.name = "min_volume_ratio",
       .type = KeyType::number,
       .unit = "-",
       .range = Range::open(0, 1),
       .absent = "not tested",
       .description = "fail when J = det F falls to this value"},
      {.name = "max_volume_ratio",
       .type = KeyType::number,
       .unit = "-",
       .range = Range::above(1),
       .absent = "not tested",
       .description = "fail when J = det F grows to this value"},
      {.name = "min_time_step",
       .type = KeyType::number,
       .unit = "s",
       .range = Range::above(0),
       .absent = "not tested",
       .description = "fail when the particle's own stable time step cfl min_d h_d / (c + |v_d|) (eq. 16.3) falls to "
                      "this value (LS-DYNA's erosion on DTMIN)"},
      {.name = "action",
       .type = KeyType::choice,
       .choices = {"erode", "fail"},
       .default_value = std::string("erode"),
       .description = "what a failed particle becomes: `erode` leaves the run, its mass, momentum and energies "
                      "booked in energy.csv's eroded_* columns (as LS-DYNA's erosion and Abaqus/Explicit's element "
                      "deletion); `fail` keeps its mass and carries only compressive pressure"},
  };
  return keys;
}

namespace sections {

FailureCriteria read_failure(const YamlReader& reader, const YamlValue& value, const MaterialDescription& material,
                             const MaterialModel& model) {
  const io::SpecMap map(reader, value, failure_keys());
  FailureCriteria c;
  c.damage = map.boolean("damage");
  c.plastic_strain = map.optional_number("plastic_strain");
  c.principal_strain = map.optional_number("principal_strain");
  c.principal_stress = map.optional_number("principal_stress");
  c.spall_pressure = map.optional_number("spall_pressure");
  c.min_volume_ratio = map.optional_number("min_volume_ratio");
  c.max_volume_ratio = map.optional_number("max_volume_ratio");
  c.min_time_step = map.optional_number("min_time_step");
  c.action = map.choice("action") == "fail" ? FailureAction::fail : FailureAction::erode;
  if (!c.damage && !c.plastic_strain && !c.principal_strain && !c.principal_stress && !c.spall_pressure &&
      !c.min_volume_ratio && !c.max_volume_ratio && !c.min_time_step)
    reader.fail(value,
                "no failure criterion: give at least one of damage: true, plastic_strain, principal_strain, "
                "principal_stress, spall_pressure, min_volume_ratio, max_volume_ratio, min_time_step");
  if (c.damage) {
    const std::string& enabler = model.damage_enabled_by;
    if (enabler.empty())
      reader.fail(
          *map.find("damage"),
          fmt::format("model {} has no damage; the models with Johnson-Cook damage are {}", material.model,
                      material_model_names_where([](const MaterialModel& m) { return !m.damage_enabled_by.empty(); })));
    if (!material.parameters.count(enabler))
      reader.fail(*map.find("damage"), fmt::format("material '{}' has no damage: model {} tracks it only with {}; "
                                                   "give {} (and its constants) or another criterion",
                                                   material.name, material.model, enabler, enabler));
  }
  if (c.plastic_strain && !model.tracks_plastic_strain)
    reader.fail(
        *map.find("plastic_strain"),
        fmt::format("model {} keeps no plastic strain; the models that do are {}", material.model,
                    material_model_names_where([](const MaterialModel& m) { return m.tracks_plastic_strain; })));
  return c;
}

}  // namespace sections
}  // namespace mpm
