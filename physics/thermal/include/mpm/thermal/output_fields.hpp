#pragma once
/// \file output_fields.hpp
/// The output fields of the thermal module: `heat_flux`, and the shared `temperature` (with its remedy: a
/// thermal: section), in the output table of mpm/output_fields.hpp.

namespace mpm::thermal {

/// Registers them (called by register_module()).
void register_output_fields();

}  // namespace mpm::thermal
