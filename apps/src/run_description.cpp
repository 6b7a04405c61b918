#include "mpm/app/run_description.hpp"

#include <tbb/global_control.h>

#include <algorithm>
#include <limits>

#include "mpm/app/commit_id.hpp"
#include "mpm/output/output_fields.hpp"

namespace mpm::app {

io::FieldData run_field_data(const SceneDescription& scene, const std::vector<std::string>& overrides) {
  io::FieldData data;
  std::string changes;
  for (const auto& line : overrides) changes += line + "\n";
  data.text = {{"scene", scene.source},
               {"scene_file", scene.file},
               {"overrides", changes},
               {"program", std::string("mpm ") + MPM_VERSION},
               {"commit", commit_id()}};
  data.numbers = {
      {"threads", static_cast<double>(tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism))},
      {"ranks", 1.0}};
  return data;
}

io::ViewScript view_script_for(const SceneDescription& scene) {
  io::ViewScript view;
  view.particles_pvd = scene.output.prefix + ".pvd";
  view.dimension = scene.dimension;
  const auto& fields = scene.output.fields;
  std::string colour = "id";  // always written
  if (std::find(fields.begin(), fields.end(), "von_mises_stress") != fields.end()) {
    colour = "von_mises_stress";
  } else {
    for (const auto& f : fields)
      if (const OutputField* field = find_output_field(f); field && field->components > 0) {
        colour = f;
        break;
      }
  }
  view.colour_by = colour;
  view.colour_components = find_output_field(colour)->components;
  double spacing = std::numeric_limits<double>::infinity();
  for (const auto& body : scene.bodies)
    for (int d = 0; d < scene.dimension; ++d)
      spacing = std::min(spacing, scene.grid.cell_size[d] / body.particles_per_cell[d]);
  view.particle_radius = std::isfinite(spacing) ? 0.5 * spacing : 0;
  return view;
}

}  // namespace mpm::app
