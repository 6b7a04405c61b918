// `solver:` (docs/scene-reference.md, solver): scheme, shape function (checked against the grid), velocity
// transfer, CPDI domain update, local damping, time step, the intervals of the guard and the sorting, and the energy
// sentinel.
#include <fmt/format.h>

#include "mpm/core/enum_names.hpp"
#include "mpm/scene/scene_extension.hpp"
#include "mpm/scene/scene_keys.hpp"
#include "mpm/scene/spec_map.hpp"
#include "mpm/schemes/scheme.hpp"
#include "mpm/schemes/scheme_registry.hpp"
#include "sections.hpp"

namespace mpm {
namespace {

/// The registered schemes as the reference's Allowed column words them: "`musl` (description); ...".
std::string scheme_choices_text() {
  std::string text;
  for (const auto& name : scheme_names()) {
    if (!text.empty()) text += "; ";
    text += fmt::format("`{}` ({})", name, find_scheme(name)->description);
  }
  return text;
}

/// `solver.gravity_stage`'s keys (simulation/gravity_stage.hpp).
std::vector<io::KeySpec> gravity_stage_keys() {
  using io::KeyType;
  return {
      {.name = "damping",
       .type = KeyType::number,
       .unit = "-",
       .range = io::Range::open(0, 1),
       .default_value = 0.8,
       .description = "the local damping alpha of the stage (eq. 2.74; FLAC's default 0.8); the run afterwards has "
                      "`solver.damping`"},
      {.name = "tolerance",
       .type = KeyType::number,
       .unit = "-",
       .range = io::Range::above(0),
       .default_value = 1e-4,
       .description = "the stage ends once the unbalanced force ratio (docs/theory.md eq. 20.3: the norm of the "
                      "nodal forces out of balance over that of the nodal weights) stays below this for 10 steps in "
                      "a row"},
      {.name = "max_steps",
       .type = KeyType::integer,
       .range = io::Range::at_least(1),
       .default_value = 100000.0,
       .description = "the stage gives up after this many steps",
       .type_text = "integer (steps)"},
      {.name = "on_no_equilibrium",
       .type = KeyType::choice,
       .choices = enum_names<NoEquilibriumAction>(),
       .default_value = std::string("stop"),
       .description = "when the ratio is still above the tolerance after `max_steps`: `stop` ends the program with "
                      "the ratio reached, at this key (exit status 2; a slope that fails under its own weight never "
                      "settles), `warn` logs it and starts the run from the state reached"},
  };
}

/// The core's keys of `solver:`.
std::vector<io::KeySpec> core_solver_keys() {
  using io::KeyType;
  // why a fork may not change the keys that choose the scheme's kernels: the particles carry the fields those
  // kernels need (C_p, CPDI corners, the reference configuration of TLMPM) in the checkpoint's layout
  const std::string scheme_layout = "the state layout of the scheme: the particles' fields are the checkpoint's";
  return {
      {.name = "scheme",
       .type = KeyType::choice,
       .choices = scheme_names(),
       .default_value = std::string("musl"),
       .description = "the time integration; a module's scheme and its own keys are described with the module",
       .allowed_text = scheme_choices_text(),
       .fork_refusal = scheme_layout},
      {.name = "velocity_transfer",
       .type = KeyType::choice,
       .choices = enum_names<VelocityTransfer>(),
       .default_value = std::string("flip"),
       .absent = "`flip`; `apic` in a scene with a `contact:` section that gives neither this key nor "
                 "`flip_fraction` (with `contact.onset: particle_gap` it alone kept stacked blocks at rest and "
                 "gained nothing in impacts on rigid planes: contact/README.md, Defaults)",
       .description =
           "`flip`: PIC/FLIP blend with `flip_fraction` (eq. 2.53); `apic`: affine particle-in-cell (Jiang et al. "
           "2015, review eqs 5.37-5.38), which conserves angular momentum; the particle carries C_p (field allocated "
           "only then). Not with `tlmpm` (Remark 35); `flip_fraction` must not be given with `apic`. It dissipates "
           "the energy of grid-scale velocity modes: the review's dam break (MUSL or USF) loses about 5% by 1.7 s "
           "with hats or quadratic B-splines (FLIP gains 1.1%), and still 2.8-3.2% with 2-4 times finer cells: the "
           "loss of the wall impact falls with the cell, the per-step loss of the flow after it does not "
           "(physics/fluids/README.md, Limits); more particles per cell lose less (3 per axis at 140 cells: 1.76%, "
           "`examples/12_dam_break/apic.yaml`): give it at least 3 per axis; use `flip` when the energy matters. "
           "With `linear` hats a node lighter than 0.05 of a face layer of particles (0.1 particle masses in 2D "
           "with 2 per cell per axis, 0.2 in 3D) enters C_p without its velocity gradient, and one up to 10% "
           "heavier with part of it (docs/theory.md §2). `polypic`: PolyPIC (Fu et al. 2017), `linear` hats only "
           "(refused with other shape functions, whose 3^d or more nodes these modes do not span), 2D and 3D (in "
           "1D it is `apic`); the particle carries C_p and the multilinear modes of its cell (field "
           "`polypic_modes`: xy in 2D; xy, xz, yz, xyz in 3D), so the transfer loses nothing at nodes of full mass "
           "and conserves momentum and angular momentum as `apic`. The review's dam break (MUSL) at 35/70/140 "
           "cells: -5.61%/-1.75%/-1.14% by 1.7 s (`apic` -13.4%/-4.85%/-2.80%; sensitive to the step's last "
           "digits: -2.08% at 70 cells with dt = 0.1 h/c unrounded); like `flip` it keeps grid-scale noise: the "
           "FSI example with hats inverts a spray particle at 0.234 s at `cfl: 0.5`, and loses 25.3% by 0.5 s at "
           "`cfl: 0.25` (physics/fluids/README.md, Limits). Not with `tlmpm`, no `flip_fraction`",
       .fork_refusal = scheme_layout},
      {.name = "shape_function",
       .type = KeyType::choice,
       .choices = shape_function_names(),
       .default_value = std::string("linear"),
       .description = "the particle-grid weights",
       .allowed_text =
           "`linear` (hat), `cubic_bspline` (>= 4 cells per axis), `quadratic_bspline` (>= 2), `bernstein` "
           "(quadratic Bernstein; even number of cells: an element is two cells), `gimp` (uGIMP), `cpgimp` "
           "(cpGIMP), `lagrange_quadratic` (quadratic finite-element basis of the 000 paper, negative lobes: "
           "`tlmpm` only; even number of cells); CPDI (review §3.6, >= 3 cells per axis): `cpdi_l2` (1D segments), "
           "`cpdi_r4` (2D parallelograms convected with F, the original CPDI), `cpdi_q4` (2D quadrilaterals with "
           "tracked corners, \"CPDI2\"), `cpdi_t3` (2D triangles: each particle sub-cell is split into two), "
           "`cpdi_tet4` (3D tetrahedra: each sub-cell is split into six). A CPDI function exists in its dimension "
           "only",
       .fork_refusal = scheme_layout},
      {.name = "cpdi_domain_update",
       .type = KeyType::choice,
       .choices = enum_names<CpdiDomainUpdate>(),
       .absent = "`deformation_gradient` for `cpdi_l2`, `cpdi_r4` and with `tlmpm`; `corners` otherwise",
       .description = "CPDI only. `deformation_gradient`: corners x_p + F (X_c - X_p) (eq. 3.27); `corners`: every "
                      "corner moves with the grid velocity at the corner (eq. 3.38), so neighbouring domains stay "
                      "glued. `corners` is refused with `cpdi_r4` (use `cpdi_q4`) and with `tlmpm` (its weights "
                      "never change)",
       .fork_refusal = scheme_layout},
      {.name = "flip_fraction",
       .type = KeyType::number,
       .unit = "-",
       .range = io::Range::closed(0, 1),
       .default_value = 1.0,
       .description = "1 = pure FLIP, 0 = pure PIC (eq. 2.53); only with `velocity_transfer: flip`",
       .run_control = true},
      {.name = "damping",
       .type = KeyType::number,
       .unit = "-",
       .range = io::Range{0, true, 1, false},
       .default_value = 0.0,
       .description =
           "local non-viscous (Cundall) damping of the grid momentum update, to bring bodies to static equilibrium "
           "(a gravity stage): each component of a node's unbalanced force f is reduced by `damping` x |f| against "
           "the node's velocity (docs/theory.md eq. 2.74); it vanishes with the unbalanced force, so the state it "
           "settles to is the undamped static one (the elastic column under gravity of "
           "`examples/21_gravity_column`: settlement within 0.05% and stress within 0.02% of the static solution, "
           "docs/verification-notes.md). 0: off. Every explicit scheme, every transfer, 1D, 2D, axisymmetric and "
           "3D, and each body's own field under `contact:`; refused by a scheme without an explicit momentum "
           "update (`implicit`). The energy it removes is booked: `energy.csv` gains the column `damped_energy` "
           "(eq. 2.75; total_energy + damped_energy = E(0) + W) and the energy sentinel counts it as it counts "
           "eroded material",
       .fork_refusal = "its energy book (energy.csv's damped_energy column) is the checkpoint's"},
      {.name = "dt",
       .type = KeyType::number,
       .unit = "s",
       .range = io::Range::above(0),
       .absent = "none: give `dt` or `cfl`",
       .description = "a fixed time step; exactly one of `dt` and `cfl`",
       .run_control = true},
      {.name = "cfl",
       .type = KeyType::number,
       .unit = "-",
       .range = io::Range::above_up_to(0, 1),
       .absent = "none: give `dt` or `cfl`",
       .description = "an adaptive time step, this fraction of the critical step (eq. 2.73); exactly one of `dt` "
                      "and `cfl`",
       .run_control = true},
      {.name = "end_time",
       .type = KeyType::number,
       .unit = "s",
       .range = io::Range::above(0),
       .required = true,
       .description = "the run ends at this time",
       .run_control = true},
      {.name = "mass_cutoff",
       .type = KeyType::number,
       .unit = "-",
       .range = io::Range::at_least(0),
       .default_value = 1e-12,
       .description = "small-nodal-mass cut-off of eq. 2.63 as a fraction of the largest particle mass: nodes "
                      "lighter than that get zero velocity",
       .run_control = true},
      {.name = "gravity",
       .type = KeyType::list,
       .unit = "m/s^2",
       .absent = "zeros",
       .description = "the body force per unit mass",
       .type_text = "list of `dimension` numbers",
       .allowed_text = "any",
       .run_control = true},
      {.name = "snapshot_interval",
       .type = KeyType::integer,
       .range = io::Range::at_least(1),
       .default_value = 20.0,
       .description = "steps between in-memory snapshots used by the stability guard (on a failure the run is "
                      "rolled back to the snapshot and replayed to the last good step, so this only trades memory "
                      "traffic against replay time)",
       .type_text = "integer (steps)",
       .run_control = true},
      {.name = "sort_interval",
       .type = KeyType::integer,
       .range = io::Range::at_least(1),
       .default_value = 20.0,
       .description = "steps between particle reorderings by cell",
       .type_text = "integer (steps)",
       .run_control = true},
      {.name = "energy_tolerance",
       .type = KeyType::number,
       .unit = "-",
       .range = io::Range::above(0),
       .default_value = 0.05,
       .description =
           "the energy sentinel's tolerance, a fraction of the largest energy of the run so far: every 50 steps the "
           "balance E(t) - E(0) - W (kinetic + strain + gravity potential + plastic work, less the work of the face "
           "conditions, moving rigid bodies and planes and body forces; docs/theory.md §8) is compared with it. "
           "Dissipation the audit does not track only lowers the balance, so only a gain can exceed it",
       .run_control = true},
      {.name = "on_energy_drift",
       .type = KeyType::choice,
       .choices = enum_names<EnergyDriftAction>(),
       .default_value = std::string("warn"),
       .description = "`warn`: the first audited step (every 50th) whose balance exceeds the tolerance is logged "
                      "once (step, time, balance, which energy grew most, and the hint of docs/VERIFICATION.md's "
                      "table for the scheme, shape function and transfer); `stop`: the run also ends there through "
                      "the stability path (exit status 3, the state of that step written as the last frame). The "
                      "largest balance / tolerance of the run is printed at the end",
       .run_control = true},
      {.name = "gravity_stage",
       .type = KeyType::map,
       .absent = "none: the run starts from the scene's state",
       .description = "bring the bodies to rest under gravity before t = 0, see "
                      "[solver.gravity_stage](#solvergravity_stage)",
       .fork_refusal = "the gravity stage ran before t = 0: the checkpoint's state is after it",
       .keys = gravity_stage_keys()},
  };
}

}  // namespace

std::vector<io::KeySpec> solver_keys() {
  std::vector<io::KeySpec> keys = core_solver_keys();
  for (auto& [spec, scheme] : scheme_solver_keys()) {
    spec.description = fmt::format("`scheme: {}` only: {}", scheme, spec.description);
    keys.push_back(std::move(spec));
  }
  return keys;
}

namespace sections {
namespace {

/// Fails unless the shape function exists in this dimension, suits the scheme and fits the grid.
void check_shape_function(const YamlReader& reader, const YamlValue& key, const SolverDescription& solver,
                          const SceneDescription& scene) {
  const int dimension = scene.dimension;
  const ShapeFunctionInfo& info = *find_shape_function(solver.shape_function);
  if (info.dimension != 0 && info.dimension != dimension)
    reader.fail(key, fmt::format("{} is a {}D shape function; this scene is {}D (CPDI elements: cpdi_l2 in 1D, "
                                 "cpdi_r4, cpdi_q4 and cpdi_t3 in 2D, cpdi_tet4 in 3D)",
                                 info.name, info.dimension, dimension));
  if (scene.grid.coordinates == Coordinates::axisymmetric && !info.axisymmetric) {
    std::string valid;
    for (const auto& name : shape_function_names())
      if (find_shape_function(name)->axisymmetric) valid += (valid.empty() ? "" : ", ") + name;
    reader.fail(key, fmt::format("{} is not available in axisymmetric coordinates; the shape functions there are {}",
                                 info.name, valid));
  }
  if (info.tlmpm_only && !scheme_of(solver).traits.total_lagrangian)
    reader.fail(key,
                fmt::format("{} has negative weights and is only valid with scheme: {} (particles at "
                            "fixed reference positions); the scheme is {}",
                            info.name, scheme_names_where([](const SchemeTraits& t) { return t.total_lagrangian; }),
                            solver.scheme_name()));
  for (int d = 0; d < dimension; ++d) {
    if (scene.grid.cells[d] < info.min_cells)
      reader.fail(key, fmt::format("{} needs at least {} cells per axis; the grid has {} on axis {}", info.name,
                                   info.min_cells, scene.grid.cells[d], axis_names[d]));
    if (info.even_cells && scene.grid.cells[d] % 2 != 0)
      reader.fail(key, fmt::format("{} needs an even number of cells per axis (two per element); the "
                                   "grid has {} on axis {}",
                                   info.name, scene.grid.cells[d], axis_names[d]));
  }
}

// CPDI domain update (review §3.6): with F by default for cpdi_l2/cpdi_r4 and with the TLMPM (whose weights
// never change), with the tracked corners (CPDI2) for cpdi_q4, cpdi_t3 and cpdi_tet4.
void read_cpdi_domain_update(const io::SpecMap& map, SolverDescription& solver) {
  const YamlReader& reader = map.reader();
  const ShapeFunctionInfo& info = *find_shape_function(solver.shape_function);
  const auto key = map.find("cpdi_domain_update");
  if (info.domain_corners == 0) {
    if (key)
      reader.fail(*key, "cpdi_domain_update applies to the CPDI shape functions only, not " + solver.shape_function);
    return;
  }
  const bool total_lagrangian = scheme_of(solver).traits.total_lagrangian;
  solver.cpdi_domain_update =
      info.domain_follows_F || total_lagrangian ? CpdiDomainUpdate::deformation_gradient : CpdiDomainUpdate::corners;
  if (!key) return;
  solver.cpdi_domain_update = reader.choice<CpdiDomainUpdate>(*key);
  if (solver.cpdi_domain_update != CpdiDomainUpdate::corners) return;
  if (total_lagrangian)
    reader.fail(*key,
                "corners: the TLMPM keeps its reference weights, so its domains follow F; use deformation_gradient");
  if (!info.tracks_corners)
    reader.fail(*key, solver.shape_function +
                          " is the parallelogram domain convected with F (eq. 3.27); use cpdi_q4 to track the corners");
}

void read_velocity_transfer(const io::SpecMap& map, SolverDescription& solver) {
  const YamlReader& reader = map.reader();
  solver.velocity_transfer_given = map.find("flip_fraction") || map.find("velocity_transfer");
  solver.flip_fraction = map.number("flip_fraction");
  solver.velocity_transfer = *enum_from_name<VelocityTransfer>(map.choice("velocity_transfer"));
  const auto transfer = map.find("velocity_transfer");
  if (!transfer || !carries_affine_velocity(solver.velocity_transfer)) return;
  const std::string name(enum_name(solver.velocity_transfer));
  if (const Support& affine = scheme_of(solver).traits.affine_transfers; !affine)
    reader.fail(*transfer, fmt::format("{} is not available with {} ({})", name, solver.scheme_name(), affine.why_not));
  if (const auto flip = map.find("flip_fraction"))
    reader.fail(*flip, "flip_fraction applies to velocity_transfer: flip, not to " + name);
  // PolyPIC's modes are the 2^d multilinear functions of the hats' one cell (docs/theory.md §2, velocity transfers):
  // with them a particle keeps every velocity field its 2^d nodes can hold. Wider or domain-averaged functions reach
  // 3^d or more nodes with weights that are not multilinear, where these modes are neither complete nor orthogonal.
  if (solver.velocity_transfer == VelocityTransfer::polypic && !find_shape_function(solver.shape_function)->multilinear)
    reader.fail(*transfer,
                "polypic keeps the 2^d multilinear velocity modes of a linear hat's cell, which make its "
                "transfer lossless only with shape_function: linear (the shape function is " +
                    solver.shape_function + "); use apic with other shape functions");
}

/// `damping`: the local damping of the momentum update (eq. 2.74), alpha in [0, 1); refused by a scheme without an
/// explicit momentum update.
void read_damping(const io::SpecMap& map, SolverDescription& solver) {
  solver.damping = map.number("damping");
  const auto damping = map.find("damping");
  if (!damping) return;
  if (const Support& local = scheme_of(solver).traits.local_damping; !local)
    map.reader().fail(*damping,
                      fmt::format("damping is not available with {} ({})", solver.scheme_name(), local.why_not));
}

/// Exactly one of dt (fixed) and cfl (adaptive).
void read_time_step(const io::SpecMap& map, SolverDescription& solver) {
  const YamlReader& reader = map.reader();
  const auto dt = map.find("dt");
  const auto cfl = map.find("cfl");
  if (dt && cfl) reader.fail(*cfl, "give either dt (fixed time step) or cfl (adaptive time step), not both");
  if (!dt && !cfl)
    reader.fail(map.map().self().mark, map.map().path_of("dt"),
                "one of dt (fixed time step, s) or cfl (adaptive time step) is required");
  solver.dt = map.optional_number("dt");
  solver.cfl = map.optional_number("cfl");
  solver.dt_where = reader.location(dt ? dt->mark : cfl->mark);
}

/// `gravity_stage`: needs gravity and a scheme with the local damping (an explicit momentum update).
GravityStageDescription read_gravity_stage(const YamlReader& reader, const YamlValue& value,
                                           const SolverDescription& solver) {
  const std::vector<io::KeySpec> keys = gravity_stage_keys();  // the map refers to them
  const io::SpecMap map(reader, value, keys);
  if (const Support& local = scheme_of(solver).traits.local_damping; !local)
    reader.fail(value, fmt::format("the gravity stage settles the bodies with the local damping, which is not "
                                   "available with {} ({})",
                                   solver.scheme_name(), local.why_not));
  if (solver.gravity == std::array<double, 3>{0, 0, 0})
    reader.fail(value, "the gravity stage settles the bodies under gravity, and solver.gravity is zero (or absent)");
  GravityStageDescription stage;
  stage.damping = map.number("damping");
  stage.tolerance = map.number("tolerance");
  stage.max_steps = map.integer("max_steps");
  stage.on_no_equilibrium = *enum_from_name<NoEquilibriumAction>(map.choice("on_no_equilibrium"));
  stage.where = reader.location(value.mark);
  return stage;
}

/// The keys of `solver:` a registered scheme owns are refused with any other scheme.
void check_scheme_keys(const io::SpecMap& map, const SolverDescription& solver) {
  for (const auto& [spec, owner] : scheme_solver_keys())
    if (const auto value = map.find(spec.name); value && solver.scheme != owner)
      map.reader().fail(*value, fmt::format("{} applies to scheme: {} only; the scheme is {}", spec.name, owner,
                                            solver.scheme_name()));
}

}  // namespace

SolverDescription read_solver(const YamlReader& reader, const YamlValue& value, const SceneDescription& scene) {
  const std::vector<io::KeySpec> keys = solver_keys();
  const io::SpecMap map(reader, value, keys);
  SolverDescription solver;
  solver.scheme = map.choice("scheme");
  check_scheme_keys(map, solver);
  solver.shape_function = map.choice("shape_function");
  if (const auto shape_function = map.find("shape_function"))
    check_shape_function(reader, *shape_function, solver, scene);
  read_cpdi_domain_update(map, solver);
  read_velocity_transfer(map, solver);
  read_damping(map, solver);
  // before the time step: the scheme may refuse cfl with its own message
  if (const auto parse = scheme_of(solver).parse) solver.scheme_options = parse(reader, map.map(), solver, scene);
  read_time_step(map, solver);
  solver.end_time = map.number("end_time");
  solver.mass_cutoff = map.number("mass_cutoff");
  if (const auto gravity = map.find("gravity"))
    solver.gravity = reader.vector(*gravity, scene.dimension, map.spec("gravity").range, map.spec("gravity").unit);
  solver.snapshot_interval = map.integer("snapshot_interval");
  solver.sort_interval = map.integer("sort_interval");
  // The energy sentinel (energy_sentinel.hpp): a fraction of the largest energy of the run so far.
  solver.energy_tolerance = map.number("energy_tolerance");
  solver.on_energy_drift = *enum_from_name<EnergyDriftAction>(map.choice("on_energy_drift"));
  if (const auto stage = map.find("gravity_stage")) solver.gravity_stage = read_gravity_stage(reader, *stage, solver);
  return solver;
}

}  // namespace sections
}  // namespace mpm
