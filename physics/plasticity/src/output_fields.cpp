#include "mpm/plasticity/output_fields.hpp"

#include <string>

#include "mpm/field_keys.hpp"
#include "mpm/output_fields.hpp"

namespace mpm::plasticity {

void register_output_fields() {
  for (const auto& o : plastic_outputs<3>) {
    OutputField f;
    f.name = o.name;
    f.unit = o.unit;
    f.description = o.description;
    // the body's material writes it (PlasticBatch::append_output); any other body has no plastic flow
    f.append_with([name = std::string(o.name)](const auto& body, std::vector<double>& out) {
      if (!body.material->append_output(name, body.particles, out))
        out.insert(out.end(), static_cast<std::size_t>(body.particles.size()), 0.0);
    });
    register_output_field(std::move(f));
  }
  OutputField temperature = scalar_particle_output(
      mpm::keys::temperature, "K",
      "temperature (K) of materials with `specific_heat` (and of every body with a `thermal:` section); 0 in "
      "bodies that do not track it; an error if no body does");
  temperature.carrier = std::string(mpm::keys::temperature.name);
  temperature.absent = "no body tracks temperature";
  temperature.remedies = {"give a material specific_heat (johnson_cook, j2_plasticity)"};
  register_output_field(std::move(temperature));
}

}  // namespace mpm::plasticity
