// The one table of documented instabilities (energy_hints.hpp). A row is added here with the measurement it
// rests on, and that measurement is documented where the row says (docs/VERIFICATION.md or a README).
#include "mpm/diagnostics/energy_hints.hpp"

#include <fmt/format.h>

#include <array>

#include "mpm/schemes/scheme.hpp"

namespace mpm {
namespace {

/// The shape function's entry of the table; an unknown name (a hand-made context) has none of its traits.
const ShapeFunctionInfo& shape_of(const HintContext& c) {
  static const ShapeFunctionInfo none;
  const ShapeFunctionInfo* info = find_shape_function(c.shape_function);
  return info ? *info : none;
}
bool is_linear(const HintContext& c) { return shape_of(c).multilinear; }
/// An explicit updated-Lagrangian scheme (USL, MUSL, USF): what the stability measurements of these rows ran.
bool is_explicit_updated_lagrangian(const HintContext& c) {
  return !c.scheme.total_lagrangian && !c.scheme.unconditionally_stable;
}

constexpr std::array<EnergyHint, 12> rows{{
    {"a particle left the grid through a face that does not let material out", trigger_left_grid,
     [](const HintContext&) { return true; },
     "the face the guard names holds material in (`stop`, the default of a face not listed, or `free`): give it "
     "`outflow` (grid.boundary), so that what crosses it leaves the run with its mass, momentum and energy booked in "
     "energy.csv, or enlarge the grid (`grid.extent`) if the material should stay",
     "the axisymmetric sphere through a plate (examples/19_plate_perforation, hats, 0.25 mm cells): with the faces "
     "below and above the plate `stop` (the default) a plate particle leaving through y_min stopped the run at 30.4 "
     "us; with them `outflow` it runs to 40 us, 1,624 particles (2.75 g) booked as they left (docs/theory.md §16)"},
    {"APIC with linear hats", trigger_energy | trigger_guard,
     [](const HintContext& c) { return c.transfer == VelocityTransfer::apic && is_linear(c); },
     "APIC with linear hats runs on free surfaces with MUSL and USF (the re-map takes C_p from the trial velocities, a "
     "nearly empty node enters C_p without its gradient); with USL a particle next to a nearly empty node inverts F as "
     "with FLIP: use `scheme: musl` or `usf`. APIC itself loses energy (the non-affine modes, at every transfer), it "
     "does not gain it; with 2 particles per cell per axis it loses more: use 3 or more",
     "the dam break (examples/12) with APIC and hats, to 1.7 s: energy change -4.85% (MUSL), -5.02% (USF), never above "
     "E0; at 35/140/280 cells instead of 70 (MUSL): -13.4%/-2.80%/-3.23%, density warnings only at the wall impact; "
     "with 3/6/8 particles per cell per axis instead of 2: -3.86%/-3.08%/-2.84%, and -1.76% at 140 cells with 3 "
     "(examples/12_dam_break/apic.yaml); USL inverts a particle at 0.065 s, "
     "FLIP with USL at 0.066 s; before the fix MUSL inverted at 0.093 s, USF at 0.068 s (physics/fluids/README.md, "
     "Limits)"},
    {"PolyPIC with linear hats", trigger_energy | trigger_guard,
     [](const HintContext& c) { return c.transfer == VelocityTransfer::polypic; },
     "PolyPIC's transfer returns a node of full mass its velocity unchanged, so it keeps grid-scale velocity noise as "
     "FLIP does: where a splash breaks into spray it can gain energy and invert a particle: give the water "
     "`cavitation_pressure: 0` (no tension) and `volumetric_deformation: 1`, halve `cfl`, or use "
     "`velocity_transfer: apic` (both lose energy instead); MUSL or USF, not USL; 3 particles per cell per axis, not 2 "
     "(with 2 it loses energy in a surge)",
     "the dam break (examples/12) with PolyPIC and hats, MUSL, to 1.7 s: -5.61%/-1.75%/-1.14% at 35/70/140 cells, "
     "never above E0 (APIC -13.4%/-4.85%/-2.80%), -0.63% at 70 cells with 3 particles per cell per axis; the FSI "
     "example (examples/14) with hats: a spray particle inverts at 0.227 s (cfl 0.5), at cfl 0.25 -25.3% (APIC "
     "-46.1%); its contact set-up (contact.yaml: slip floor, cavitation_pressure 0, volumetric_deformation 1, 3 "
     "particles per cell per axis) runs to 0.5 s, no inverted particle, -14.5% (APIC -17.7%) at 40 cells: the water "
     "alone in that tank loses -1.9% (APIC -4.7%; with 2 per axis -5.7% and -10.9%), a rigid obstacle adds what a grid "
     "wall at its place costs, the elastic one inelastic contact corrections where water and obstacle approach, not "
     "the normals (examples/14 README, \"Where the rest goes\"), and 10 of the 13.3 points follow the jet's strike on "
     "the far wall, whose spray (4.6% of E0, up to 14 m/s) loses its energy where it strikes next: a particle alone in "
     "its cell keeps none of it (examples/14 README, \"The spray of the far wall\"); USL inverts at 0.091 s "
     "(physics/fluids/README.md, Limits)"},
    {"USL (any shape function)", trigger_energy | trigger_guard,
     [](const HintContext& c) { return c.scheme.stress_update_without_remap; },
     "USL is the least stable explicit scheme here: use `scheme: musl` (or usf), or a smaller `cfl`",
     "largest stable CFL factor on the two disks: USL 0.200 (linear) to 1.300 (cubic B-spline), MUSL 1.200 to >= 2; "
     "USL linear at 0.225 inverts a particle (docs/VERIFICATION.md, Largest stable CFL factor)"},
    {"contact with the FLIP transfer", trigger_energy,
     [](const HintContext& c) { return c.contact && c.transfer == VelocityTransfer::flip && c.flip_fraction > 0.96; },
     "bodies resting on each other and impacts on a rigid plane or body gain energy with FLIP; without "
     "`velocity_transfer` and `flip_fraction` a scene with contact takes `apic` (or give `flip_fraction: 0.95`), and "
     "keep the default `contact.onset: particle_gap` (`grid` pushes bodies before they touch a plane)",
     "contact/README.md, Defaults (MUSL, 2D, onset particle_gap): two rubber blocks stacked under gravity to 1 s, "
     "between slip walls: FLIP +4.1% (hats) to +12.7% (cpgimp), flip_fraction 0.99 +0.68% / +1.4%, 0.95 and apic "
     "at most +0.02%; a steel block at 50 m/s on a rigid plane: FLIP +0.9% to +3.9% (largest), 0.95 and apic never "
     "above E0"},
    {"FLIP (flip_fraction 1) with linear hats", trigger_energy | trigger_guard,
     [](const HintContext& c) {
       return c.transfer == VelocityTransfer::flip && c.flip_fraction > 0.999 && is_linear(c) &&
              is_explicit_updated_lagrangian(c);
     },
     "pure FLIP with linear hats gains energy from the cell-crossing error at fine resolution; add a PIC fraction "
     "(`flip_fraction: 0.99`), or use `shape_function: quadratic_bspline` or `cpgimp`",
     "the two disks of examples/02 at 200 cells per side, dt = 0.002 s, MUSL: total energy +37.3% at 3.5 s with FLIP "
     "and hats; flip_fraction 0.99: -19.6% (never above E0 by 1e-5), quadratic_bspline: +1.1% (largest +1.4%), cpgimp: "
     "+2.0% (largest +2.1%) (docs/VERIFICATION.md, Energy sentinel); the axisymmetric sphere through a plate with "
     "erosion (docs/theory.md §16), with contact: +7.3% with FLIP and hats, +4.0% with flip_fraction 0.99, -4.2% "
     "with quadratic_bspline, +8.6% with contact.onset particle_gap"},
    {"a fluid keeping its full F (volumetric_deformation: 0)", trigger_energy,
     [](const HintContext& c) { return c.fluid_full_deformation; },
     "the fluid's F keeps the shear of the flow (its cpGIMP domains follow it): in a long splash the spray particles' "
     "distorted F and domains gain energy; give the water `volumetric_deformation: 1` (F keeps its volume only), which "
     "costs energy in a collapsing column with cpGIMP instead",
     "the open-tank dam break (examples/20_open_tank, cpGIMP, FLIP, 40 cells, to 1.5 s): full F +58.4% (warning at "
     "0.48 s), volume only -1.93%; the Martin & Moyce column (examples/12_dam_break/martin_moyce.yaml, cpGIMP): full F "
     "-0.013%, volume only +5.2%; examples/14_fsi_obstacle/scene.yaml to 0.5 s: full F +2.7%, volume only +12.8% "
     "(physics/fluids/README.md)"},
    {"contact module (multi-velocity contact)", trigger_energy, [](const HintContext& c) { return c.contact; },
     "with the defaults (`onset: particle_gap`, `apic`) contact was measured never above E0 by more than 0.05% "
     "(collisions, resting, stacking, rigid planes and bodies, with and without friction); `contact.onset: grid` "
     "pushes bodies a shape function's reach before they touch a plane or rigid body and gains energy there: remove "
     "it",
     "contact/README.md, Defaults (MUSL, energy read every step): a steel block at 50 m/s on a rigid plane or rigid "
     "body, 1 and 0.5 mm cells, hats, quadratic and cubic B-splines, cpGIMP: apic and particle_gap never above E0 "
     "(vibration energy dissipated: -8% to -36% at the end), onset grid +20% to +217%; the same in 3D (a 10 mm cube, "
     "hats and cubic) never above E0; stacked rubber blocks to 1 s: apic -0.001% to -0.045%; friction (hats and "
     "cubic): the block striking the plane obliquely at (20, -50) m/s with mu 0.3, a rubber block sliding at 2 m/s "
     "on a rigid plane (mu 0.2, decelerating at mu g within 0.3%) and on a rubber slab, never above E0; Love & "
     "Sulsky's colliding cylinders never above E0 with either onset (docs/theory.md §11, \"Energy\")"},
    {"Bernstein functions with an explicit scheme", trigger_energy | trigger_guard,
     // two-cell elements with an explicit scheme: Bernstein (Lagrange's are total-Lagrangian only)
     [](const HintContext& c) { return shape_of(c).even_cells && is_explicit_updated_lagrangian(c); },
     "quadratic Bernstein functions tolerate a smaller time step than the others with MUSL; use `cfl: 0.5` or less",
     "largest stable CFL factor on the bar: MUSL with bernstein 0.600 against 1.500 to >= 2 for the other functions "
     "(docs/VERIFICATION.md, Largest stable CFL factor)"},
    {"TLMPM", trigger_energy, [](const HintContext& c) { return c.scheme.total_lagrangian; },
     "the total-Lagrangian scheme gains energy over long runs, the more the larger the step: use `cfl: 0.5` or less (a "
     "PIC fraction, `flip_fraction: 0.99`, removes the gain but damps strongly)",
     "a 2D elastic block (256 particles, linear hats, FLIP), 1e5 steps: +42.5% at cfl 1, +12.9% at 0.7, +2.3% at 0.5; "
     "flip_fraction 0.99 at cfl 1: -87% (docs/verification-notes.md, Stiff and extreme cases, extended)"},
    {"fixed time step (solver.dt)", trigger_energy | trigger_guard,
     [](const HintContext& c) { return c.fixed_dt && !c.scheme.unconditionally_stable; },
     "a fixed dt is checked against the CFL bound of the initial state only; faster or compressed material lowers the "
     "bound during the run: use `cfl: 0.5` (adaptive) instead of `dt`",
     "beyond the largest stable CFL factor the energy grows before the guard trips: two disks, MUSL linear at 1.225 x "
     "the bound: +12.2% at 3.469 s (docs/VERIFICATION.md, Largest stable CFL factor)"},
    {"any other method", trigger_energy | trigger_guard, [](const HintContext&) { return true; },
     "no documented cause for this method: halve the time step (`cfl`), refine the grid, and compare with the measured "
     "stability limits",
     "the largest stable CFL factor of every scheme and shape function on the bar and the two disks "
     "(docs/VERIFICATION.md, Largest stable CFL factor)"},
}};

}  // namespace

std::span<const EnergyHint> energy_hints() { return rows; }

const EnergyHint& find_energy_hint(const HintContext& context, HintTrigger trigger) {
  for (const auto& row : rows)
    if ((row.triggers & trigger) != 0 && row.applies(context)) return row;
  return rows.back();
}

std::string energy_hint_table() {
  std::string table = "| condition | energy / guard | hint | measurement |\n|---|---|---|---|\n";
  for (const auto& row : rows)
    table += fmt::format("| {} | {} | {} | {} |\n", row.condition,
                         (row.triggers & trigger_energy) != 0 && (row.triggers & trigger_guard) != 0 ? "both"
                         : (row.triggers & trigger_energy) != 0                                      ? "energy"
                         : (row.triggers & trigger_left_grid) != 0 ? "guard (left the grid)"
                                                                   : "guard",
                         row.hint, row.measurement);
  return table;
}

}  // namespace mpm
