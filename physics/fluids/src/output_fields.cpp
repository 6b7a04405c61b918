#include "mpm/fluids/output_fields.hpp"

#include "mpm/fluids/field_keys.hpp"
#include "mpm/output/output_fields.hpp"

namespace mpm::fluids {

void register_output_fields() {
  register_output_field(scalar_particle_output(
      keys::internal_energy, "J/kg", "specific internal energy e (J/kg) of `ideal_gas` bodies; 0 in other bodies"));
}

}  // namespace mpm::fluids
