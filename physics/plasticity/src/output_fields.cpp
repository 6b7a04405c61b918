#include "mpm/plasticity/output_fields.hpp"

#include <string>

#include "mpm/output/output_fields.hpp"
#include "mpm/particles/field_keys.hpp"

namespace mpm::plasticity {

void register_output_fields() {
  for (const auto& o : plastic_outputs<3>) {
    // the body's material writes it (PlasticBatch::append_output); any other body has no plastic flow
    OutputField field = output_field(o.name, 1, o.unit, o.description,
                                     [name = std::string(o.name)](const auto& body, std::vector<double>& out) {
                                       if (!body.material->append_output(name, body.particles, out))
                                         out.insert(out.end(), static_cast<std::size_t>(body.particles.size()), 0.0);
                                     });
    field.material_output = true;
    register_output_field(std::move(field));
  }
  register_output_field(carried_scalar_output(
      mpm::keys::temperature, "K",
      "temperature (K) of materials with `specific_heat` (and of every body with a `thermal:` section); 0 in "
      "bodies that do not track it; an error if no body does",
      "no body tracks temperature", "give a material specific_heat (johnson_cook, j2_plasticity)"));
}

}  // namespace mpm::plasticity
