#pragma once
/// \file body_summary.hpp
/// One line per body of a built simulation: particles, volume and mass (what `mpm check` and `mpm particles --scene`
/// print), so that a fill's volume (`volume: lattice` or `exact`, docs/scene-reference.md, bodies) can be checked
/// before a run.

#include <string>

#include "mpm/scene/scene.hpp"
#include "mpm/simulation/simulation.hpp"

namespace mpm::app {

/// "  body 'NAME': N particles, volume V m^3, mass M kg" per body, each line ending in a newline. In 1D and 2D
/// (cartesian) the volume and mass are per unit area or length out of plane (m, m^2; kg/m^2, kg/m); axisymmetric:
/// the full revolution (m^3, kg).
template <int Dim>
std::string body_summary(const Simulation<Dim>& sim);

/// "  set 'NAME': N particles in BODY[, BODY], mass M kg" per particle set of the scene (`sets:`), and " (none: its
/// bodies, region and ids select no particle)" for an empty one: what `mpm check` and `mpm particles --scene` show so
/// that a region that misses its body is seen before the run.
template <int Dim>
std::string set_summary(const Simulation<Dim>& sim, const SceneDescription& scene);

/// The fidelity certificate (geometry/mass_properties.hpp) of every 3D body whose shape knows its source's exact
/// properties (a CAD file's B-rep, a surface mesh's or a Gmsh mesh's integrals): the particles' volume, centroid and
/// inertia as built (volume0; with `volume: exact` their volumes sum to the exact volume by construction) against
/// them, a few lines per body. "" in 1D and 2D and for other shapes.
template <int Dim>
std::string body_certificates(const Simulation<Dim>& sim, const SceneDescription& scene);

}  // namespace mpm::app
