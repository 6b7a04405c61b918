#pragma once
// Reading and building the scene's `contact:` section (private to contact/).
#include <any>
#include <vector>

#include "mpm/contact/contact_description.hpp"
#include "mpm/scene/key_spec.hpp"
#include "mpm/scene/yaml_reader.hpp"
#include "mpm/simulation/simulation.hpp"

namespace mpm::contact {

/// The section's keys (contact_keys.cpp; docs/scene-reference.md, contact), which parse_contact_section reads
/// through.
const std::vector<io::KeySpec>& contact_keys();

/// Parses and checks the section (the value of `contact:`) through the scene's reader; returns a
/// ContactDescription. Throws SceneError naming file, line and key.
std::any parse_contact_section(const io::YamlReader& reader, const io::YamlValue& section,
                               const SceneDescription& scene);

/// What a scene with contact gets by default for the solver keys it does not give: `velocity_transfer: apic` where
/// the scheme takes it (contact/README.md, "Defaults": with `onset: particle_gap` APIC alone kept stacked blocks
/// and a block on a rigid plane at rest and gained no energy in impacts on rigid planes and bodies, with every
/// shape function; pure FLIP gained up to 13%, a PIC fraction of 5% bounced the block on the plane).
void complete_contact_defaults(SceneDescription& scene);

/// Adds the contact module to a simulation built from `scene` (which has a `contact` section).
template <int Dim>
void build_contact(const SceneDescription& scene, Simulation<Dim>& simulation);

}  // namespace mpm::contact
