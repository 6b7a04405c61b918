#include "mpm/thermal/output_fields.hpp"

#include <string>

#include "mpm/output/output_fields.hpp"
#include "mpm/particles/field_keys.hpp"
#include "mpm/thermal/field_keys.hpp"

namespace mpm::thermal {

void register_output_fields() {
  register_output_field(carried_scalar_output(
      mpm::keys::temperature, "K",
      "temperature (K) of every body with a `thermal:` section (and of materials with `specific_heat`); 0 in "
      "bodies that do not track it; an error if no body does",
      "no body tracks temperature", "add a thermal: section"));

  OutputField flux = output_field("heat_flux", 3, "W/m^2",
                                  "heat flux q = -k grad T (W/m^2, 3 components) of the thermal module; an error "
                                  "without a `thermal:` section",
                                  [](const auto& body, std::vector<double>& out) {
                                    constexpr int Dim = body_dimension<decltype(body)>;
                                    append_vector_field(body.particles, keys::heat_flux<Dim>, out);
                                  });
  flux.carrier = std::string(keys::heat_flux<3>.name);
  flux.absent = "no body conducts heat";
  flux.remedies = {"add a thermal: section (and thermal_conductivity to the materials)"};
  register_output_field(std::move(flux));
}

}  // namespace mpm::thermal
