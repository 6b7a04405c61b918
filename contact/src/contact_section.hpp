#pragma once
// Reading and building the scene's `contact:` section (private to contact/).
#include <any>

#include "mpm/contact/contact_description.hpp"
#include "mpm/simulation.hpp"

namespace YAML {
class Node;
}

namespace mpm::contact {

/// Parses and checks the section; throws SceneError naming file, line and key.
std::any parse_contact_section(const YAML::Node& section, const SceneDescription& scene);

/// Adds the contact module to a simulation built from `scene` (which has a `contact` section).
template <int Dim>
void build_contact(const SceneDescription& scene, Simulation<Dim>& simulation);

}  // namespace mpm::contact
