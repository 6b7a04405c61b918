#pragma once
/// \file plausibility.hpp
/// Warnings (never errors) about a scene whose numbers are valid but implausible: the slips of units a range check
/// cannot see (a density in g/cm^3, a modulus in MPa, bodies placed into each other, an end time in the wrong unit).
/// `mpm check` prints them and `mpm run` logs them before the first step (make_run, run_scene.hpp); each is
/// `FILE:LINE:COLUMN: KEY: message` at the key to look at, and names the likely slip where there is one. One function
/// per rule, each with the numbers it rests on (docs/scene-reference.md, "Plausibility"):
///
///   1. check_density: a density outside what the model's matter has (solids: above 25,000 kg/m^3, or below
///      500 kg/m^3 with waves faster than any solid's; liquids: 500-25,000 kg/m^3; gases: 0.01-100 kg/m^3);
///   2. check_yield_stress: a yield stress above the Young's modulus, or an elastic-plastic Young's modulus below
///      1e6 Pa beside a solid's density;
///   3. check_overlap: particles of two bodies closer than half a particle spacing at t = 0;
///   4. check_wave_transit: an end time before any wave crosses a cell or 1% of a body, or after 1e5 crossings of
///      every body.
///
/// A scene written in consistent non-SI units (all of density, moduli and lengths scaled: examples 03, 10, 13, 18)
/// stays silent: the rules look for numbers that disagree with each other, not for numbers far from SI alone.

#include <string>
#include <vector>

#include "mpm/scene/scene.hpp"
#include "mpm/simulation/simulation.hpp"

namespace mpm::app {

/// Rule 1: each material's density against its phase's range (MaterialModel::phase). A solid below 500 kg/m^3 is
/// warned about only when its dilatational wave speed at rest exceeds 2e4 m/s (no solid's does: diamond's is about
/// 1.8e4 m/s), so that foams, snow and consistently scaled scenes stay silent while 7.83 (g/cm^3) beside 2e11 Pa
/// warns. Names the density's likely unit: `g/cm^3? (7830 kg/m^3)`, `t/mm^3? (7830 kg/m^3)`.
template <int Dim>
void check_density(const SceneDescription& scene, const Simulation<Dim>& sim, std::vector<std::string>& warnings);

/// Rule 2: a material with a yield stress (the elastic-plastic models: J2, Johnson-Cook A, Hencky J2) whose yield
/// stress is at or above its Young's modulus (a yield strain of 100 %: it never yields; metals yield at 0.1-2 %), or
/// whose Young's modulus is below 1e6 Pa (soft clays are about 1e6 Pa, metals 1e10-4e11 Pa) while its density is a
/// solid's (>= 500 kg/m^3: the stresses, not the whole scene, are scaled). Names the modulus' likely unit (MPa, GPa).
void check_yield_stress(const SceneDescription& scene, std::vector<std::string>& warnings);

/// Rule 3: two bodies whose particles lie closer than half a particle spacing (h / particles_per_cell, the smaller of
/// the two bodies') at t = 0, for at least max(10, 1% of the smaller body's particles) of them (bodies that touch
/// keep a spacing between their particles; a few at a tangency do not count). Cost O(N log N): only the particles in
/// the overlap of the two bodies' boxes are binned (cells of half a spacing, sorted) and looked up.
template <int Dim>
void check_overlap(const SceneDescription& scene, const Simulation<Dim>& sim, std::vector<std::string>& warnings);

/// Rule 4: the end time against the time a dilatational wave takes to cross each body (its largest extent / its
/// wave speed at rest), when waves set the time step (the CFL bound governs): too short when no wave crosses a cell
/// nor 1 % of any body in the run (fewer steps than 1/CFL: a time unit slipped, ns for us); too long when every
/// body is crossed more than 1e5 times (at a few cells per body and CFL 0.5, millions of steps: ms or us written as
/// s).
template <int Dim>
void check_wave_transit(const SceneDescription& scene, const Simulation<Dim>& sim, std::vector<std::string>& warnings);

/// Every rule's warnings, in the order above.
template <int Dim>
std::vector<std::string> plausibility_warnings(const SceneDescription& scene, const Simulation<Dim>& sim);

}  // namespace mpm::app
