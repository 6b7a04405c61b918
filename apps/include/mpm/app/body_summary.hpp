#pragma once
/// \file body_summary.hpp
/// One line per body of a built simulation: particles, volume and mass (what `mpm check` and `mpm particles --scene`
/// print), so that a fill's volume (`volume: lattice` or `exact`, docs/scene-reference.md, bodies) can be checked
/// before a run.

#include <string>

#include "mpm/simulation/simulation.hpp"

namespace mpm::app {

/// "  body 'NAME': N particles, volume V m^3, mass M kg" per body, each line ending in a newline. In 1D and 2D
/// (cartesian) the volume and mass are per unit area or length out of plane (m, m^2; kg/m^2, kg/m); axisymmetric:
/// the full revolution (m^3, kg).
template <int Dim>
std::string body_summary(const Simulation<Dim>& sim);

}  // namespace mpm::app
