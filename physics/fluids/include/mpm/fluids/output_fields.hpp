#pragma once
/// \file output_fields.hpp
/// The output field of the fluids module, `internal_energy`, in the output table of mpm/output_fields.hpp.

namespace mpm::fluids {

/// Registers it (called by register_module()).
void register_output_fields();

}  // namespace mpm::fluids
