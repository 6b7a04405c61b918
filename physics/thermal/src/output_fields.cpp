#include "mpm/thermal/output_fields.hpp"

#include <string>

#include "mpm/field_keys.hpp"
#include "mpm/output_fields.hpp"
#include "mpm/thermal/field_keys.hpp"

namespace mpm::thermal {

void register_output_fields() {
  OutputField temperature = scalar_particle_output(
      mpm::keys::temperature, "K",
      "temperature (K) of every body with a `thermal:` section (and of materials with `specific_heat`); 0 in "
      "bodies that do not track it; an error if no body does");
  temperature.carrier = std::string(mpm::keys::temperature.name);
  temperature.absent = "no body tracks temperature";
  temperature.remedies = {"add a thermal: section"};
  register_output_field(std::move(temperature));

  OutputField flux;
  flux.name = "heat_flux";
  flux.components = 3;
  flux.unit = "W/m^2";
  flux.description =
      "heat flux q = -k grad T (W/m^2, 3 components) of the thermal module; an error without a "
      "`thermal:` section";
  flux.append_with([](const auto& body, std::vector<double>& out) {
    append_vector_field(body.particles, keys::heat_flux<body_dimension<decltype(body)>>, out);
  });
  flux.carrier = std::string(keys::heat_flux<3>.name);
  flux.absent = "no body conducts heat";
  flux.remedies = {"add a thermal: section (and thermal_conductivity to the materials)"};
  register_output_field(std::move(flux));
}

}  // namespace mpm::thermal
