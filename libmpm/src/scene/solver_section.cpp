// `solver:` (docs/scene-reference.md, solver): scheme, shape function (checked against the grid), velocity
// transfer, CPDI domain update, local damping, time step, the intervals of the guard and the sorting, and the energy
// sentinel.
#include <fmt/format.h>

#include "mpm/schemes/scheme.hpp"
#include "mpm/schemes/scheme_registry.hpp"
#include "sections.hpp"

namespace mpm::sections {
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
void read_cpdi_domain_update(const YamlReader& reader, const YamlMap& map, SolverDescription& solver) {
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

void read_velocity_transfer(const YamlReader& reader, const YamlMap& map, SolverDescription& solver) {
  solver.velocity_transfer_given = map.find("flip_fraction") || map.find("velocity_transfer");
  if (const auto flip = map.find("flip_fraction")) solver.flip_fraction = reader.number(*flip, Range::closed(0, 1), "");
  const auto transfer = map.find("velocity_transfer");
  if (!transfer) return;
  solver.velocity_transfer = reader.choice<VelocityTransfer>(*transfer);
  if (!carries_affine_velocity(solver.velocity_transfer)) return;
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
void read_damping(const YamlReader& reader, const YamlMap& map, SolverDescription& solver) {
  const auto damping = map.find("damping");
  if (!damping) return;
  solver.damping = reader.number(*damping, Range{0, true, 1, false}, "");
  if (const Support& local = scheme_of(solver).traits.local_damping; !local)
    reader.fail(*damping, fmt::format("damping is not available with {} ({})", solver.scheme_name(), local.why_not));
}

/// Exactly one of dt (fixed) and cfl (adaptive).
void read_time_step(const YamlReader& reader, const YamlMap& map, SolverDescription& solver) {
  const auto dt = map.find("dt");
  const auto cfl = map.find("cfl");
  if (dt && cfl) reader.fail(*cfl, "give either dt (fixed time step) or cfl (adaptive time step), not both");
  if (!dt && !cfl)
    reader.fail(map.self().mark, map.path_of("dt"),
                "one of dt (fixed time step, s) or cfl (adaptive time step) is required");
  if (dt) {
    solver.dt = reader.number(*dt, Range::above(0), "s");
    solver.dt_where = reader.location(dt->mark);
  } else {
    solver.cfl = reader.number(*cfl, Range::above_up_to(0, 1), "");
    solver.dt_where = reader.location(cfl->mark);
  }
}

/// `scheme`: a registered one (scheme_registry.hpp), the core's or a module's.
void read_scheme(const YamlReader& reader, const YamlMap& map, SolverDescription& solver) {
  if (const auto scheme = map.find("scheme")) solver.scheme = reader.choice(*scheme, scheme_names());
}

/// The keys of `solver:` a registered scheme owns are refused with any other scheme.
void check_scheme_keys(const YamlReader& reader, const YamlMap& map, const SolverDescription& solver) {
  for (const auto& [key, owner] : scheme_solver_keys())
    if (const auto value = map.find(key); value && solver.scheme != owner)
      reader.fail(*value,
                  fmt::format("{} applies to scheme: {} only; the scheme is {}", key, owner, solver.scheme_name()));
}

}  // namespace

SolverDescription read_solver(const YamlReader& reader, const YamlValue& value, const SceneDescription& scene) {
  const YamlMap map = reader.map(value);
  std::vector<std::string> allowed{
      "scheme",        "shape_function",     "velocity_transfer", "flip_fraction",   "dt",
      "cfl",           "end_time",           "mass_cutoff",       "gravity",         "snapshot_interval",
      "sort_interval", "cpdi_domain_update", "energy_tolerance",  "on_energy_drift", "damping"};
  for (const auto& [key, owner] : scheme_solver_keys()) allowed.push_back(key);
  map.allow(allowed);
  SolverDescription solver;
  read_scheme(reader, map, solver);
  check_scheme_keys(reader, map, solver);
  if (const auto shape_function = map.find("shape_function")) {
    solver.shape_function = reader.choice(*shape_function, shape_function_names());
    check_shape_function(reader, *shape_function, solver, scene);
  }
  read_cpdi_domain_update(reader, map, solver);
  read_velocity_transfer(reader, map, solver);
  read_damping(reader, map, solver);
  // before the time step: the scheme may refuse cfl with its own message
  if (const auto parse = scheme_of(solver).parse) solver.scheme_options = parse(reader, map, solver, scene);
  read_time_step(reader, map, solver);
  solver.end_time = reader.number(map.required("end_time"), Range::above(0), "s");
  if (const auto cutoff = map.find("mass_cutoff")) solver.mass_cutoff = reader.number(*cutoff, Range::at_least(0), "");
  if (const auto gravity = map.find("gravity"))
    solver.gravity = reader.vector(*gravity, scene.dimension, Range::any(), "m/s^2");
  if (const auto interval = map.find("snapshot_interval")) solver.snapshot_interval = reader.integer(*interval, 1);
  if (const auto interval = map.find("sort_interval")) solver.sort_interval = reader.integer(*interval, 1);
  // The energy sentinel (energy_sentinel.hpp): a fraction of the largest energy of the run so far.
  if (const auto tolerance = map.find("energy_tolerance"))
    solver.energy_tolerance = reader.number(*tolerance, Range::above(0), "");
  if (const auto action = map.find("on_energy_drift"))
    solver.on_energy_drift = reader.choice<EnergyDriftAction>(*action);
  return solver;
}

}  // namespace mpm::sections
