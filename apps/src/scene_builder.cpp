#include "mpm/app/scene_builder.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <iostream>

#include "mpm/app/key_location.hpp"
#include "mpm/app/memory_budget.hpp"
#include "mpm/app/memory_estimate.hpp"
#include "mpm/app/step_estimate.hpp"
#include "mpm/body_shape/shape_kind.hpp"
#include "mpm/boundary/face_condition_kind.hpp"
#include "mpm/boundary/face_names.hpp"
#include "mpm/core/expression.hpp"
#include "mpm/diagnostics/energy_sentinel.hpp"
#include "mpm/failure/failing_material.hpp"
#include "mpm/failure/failure_module.hpp"
#include "mpm/geometry/conforming_domains.hpp"
#include "mpm/geometry/cpdi_domains.hpp"
#include "mpm/history/history_kind.hpp"
#include "mpm/materials/material_registry.hpp"
#include "mpm/output/output_fields.hpp"
#include "mpm/particles/field_keys.hpp"
#include "mpm/scene/scene_error.hpp"
#include "mpm/scene/scene_extension.hpp"
#include "mpm/schemes/axisymmetric.hpp"
#include "mpm/schemes/cpdi_corner_tracking.hpp"
#include "mpm/schemes/scheme_registry.hpp"
#include "mpm/sets/geostatic_stress.hpp"
#include "mpm/sets/particle_sets.hpp"
#include "mpm/simulation/local_damping_book.hpp"
#include "mpm/simulation/reaction_provider.hpp"
#include "particle_file_body.hpp"

namespace mpm::app {
namespace {

std::string body_key(int index, const char* key) { return "bodies[" + std::to_string(index) + "]." + key; }

bool wants_output(const SceneDescription& scene, const char* field) {
  const auto& fields = scene.output.fields;
  return std::find(fields.begin(), fields.end(), field) != fields.end();
}

template <int Dim>
GridGeometry<Dim> grid_geometry(const GridDescription& gd) {
  Vec<Dim> origin, h;
  std::array<int, Dim> cells{};
  for (int d = 0; d < Dim; ++d) {
    origin[d] = gd.origin[d];
    h[d] = gd.cell_size[d];
    cells[d] = gd.cells[d];
  }
  return GridGeometry<Dim>(origin, h, cells, gd.coordinates);
}

/// The output fields that only shape functions with particle domains define (checked before any body is built).
void check_output_against_shape_function(const SceneDescription& scene, const ShapeFunctionInfo& shape) {
  if (wants_output(scene, "domains") && !shape.particle_domain && shape.domain_corners == 0)
    throw SceneError(scene.output.where, "output.fields",
                     "domains are only defined for shape functions with particle domains (gimp, cpgimp, cpdi_*), "
                     "not " +
                         scene.solver.shape_function);
  if (wants_output(scene, "domain_size") && !shape.particle_domain)
    throw SceneError(scene.output.where, "output.fields",
                     "domain_size is only defined for shape functions with particle domains (gimp, cpgimp), not " +
                         scene.solver.shape_function);
}

/// The particles of one body's shape (body_shape/shape_kind.hpp): its kind's own, or the lattice fill of its region
/// with the body's `volume`. Refuses a kind whose particles have no domains with a CPDI shape function, before it
/// reads anything.
template <int Dim>
ParticleSeeds<Dim> shape_particles(const SceneDescription& scene, const BodyDescription& bd, int index,
                                   const GridGeometry<Dim>& geometry, const ShapeFunctionInfo& shape,
                                   std::vector<std::string>& warnings) {
  const std::string shape_key = body_key(index, "shape");
  const ShapeTraits& traits = shape_kind(bd.shape).traits;
  if (!traits.not_cpdi.empty() && shape.domain_corners > 0)
    throw SceneError(bd.shape.where, shape_key,
                     traits.not_cpdi + ", which " + scene.solver.shape_function +
                         " needs: use a shape function without them (not cpdi_*)");
  ParticleSeeds<Dim> seeds;
  try {
    seeds = fill_shape<Dim>(bd.shape, geometry, bd.particles_per_cell, &warnings, bd.exact_volume);
  } catch (const ShapeError& e) {
    throw SceneError(bd.shape.where, e.key.empty() ? shape_key : shape_key + "." + e.key,
                     "body '" + bd.name + "': " + e.what());
  }
  if (seeds.positions.empty())
    throw SceneError(bd.where, shape_key,
                     "body '" + bd.name + "' contains no particle: the shape is smaller than a particle spacing");
  return seeds;
}

/// The particles of one body as elements (position, volume; CPDI: corner offsets): a kind's own particles as they
/// are, the lattice's split into CPDI elements or meshed conformingly when the shape function asks for it.
template <int Dim>
geometry::CpdiParticles<Dim> particle_elements(const SceneDescription& scene, const BodyDescription& bd, int index,
                                               const GridGeometry<Dim>& geometry, const ShapeFunctionInfo& shape,
                                               const ParticleSeeds<Dim>& seeds, std::vector<std::string>& warnings) {
  const std::string shape_key = body_key(index, "shape");
  geometry::CpdiParticles<Dim> elements;
  if (!seeds.volumes.empty()) {  // particles of their own volumes (a particle file)
    elements.positions = seeds.positions;
    elements.volumes = seeds.volumes;
    return elements;
  }
  // CPDI: every sub-cell becomes one or more particle elements (segments, quads, triangles, tets).
  const bool conforming = bd.domains == "conforming";
  // A conforming mesh of the shape is made of simplices: the CPDI elements with Dim + 1 corners (T3, Tet4).
  if (conforming && find_shape_function(scene.solver.shape_function)->domain_corners != Dim + 1)
    throw SceneError(bd.where, body_key(index, "domains"),
                     "domains: conforming needs shape_function cpdi_t3 (2D) or cpdi_tet4 (3D); the solver uses " +
                         scene.solver.shape_function);
  const Vec<Dim>& h = geometry.h;
  if (conforming) {  // CGAL triangle / tetrahedron mesh of the shape (geometry/conforming_domains.hpp)
    Real spacing = h[0] / bd.particles_per_cell[0];
    for (int d = 1; d < Dim; ++d) spacing = std::min<Real>(spacing, h[d] / bd.particles_per_cell[d]);
    try {
      elements = geometry::conforming_cpdi_particles<Dim>(bd.shape, spacing, &warnings);
    } catch (const ShapeError& e) {
      throw SceneError(bd.shape.where, shape_key, "body '" + bd.name + "': " + e.what());
    }
  } else if (shape.domain_corners > 0) {
    Vec<Dim> spacing;
    for (int d = 0; d < Dim; ++d) spacing[d] = h[d] / bd.particles_per_cell[d];
    elements = geometry::cpdi_particles<Dim>(seeds, spacing, shape.domain_corners);
  } else {
    elements.positions = seeds.positions;
    elements.volumes.assign(seeds.positions.size(), seeds.volume);
    if (geometry.coordinates == Coordinates::axisymmetric)  // the ring of the lattice sub-cell, V = 2 pi r A
      for (std::size_t k = 0; k < elements.positions.size(); ++k) {
        const Real r = elements.positions[k][0];
        if (!(r > 0))
          throw SceneError(bd.shape.where, shape_key,
                           fmt::format("body '{}' has a particle at r = {:g} m: on or behind the axis", bd.name, r));
        elements.volumes[k] = axisym::revolved_volume(r, seeds.sub_cell_volume);
      }
  }
  return elements;
}

/// One particle per element, with the material's density and the body's initial velocity (expressions of x).
template <int Dim>
void add_particles(Body<Dim>& body, const BodyDescription& bd, const geometry::CpdiParticles<Dim>& elements) {
  const std::array<Expression, 3> velocity{Expression(bd.velocity[0], {"x", "y", "z"}),
                                           Expression(bd.velocity[1], {"x", "y", "z"}),
                                           Expression(bd.velocity[2], {"x", "y", "z"})};
  auto& p = body.particles;
  const Real rho = body.material->density();
  for (std::size_t k = 0; k < elements.positions.size(); ++k) {
    const Vec<Dim>& x = elements.positions[k];
    p.add(x, rho * elements.volumes[k], elements.volumes[k]);
    double xyz[3] = {0, 0, 0};
    for (int d = 0; d < Dim; ++d) xyz[d] = x[d];
    for (int d = 0; d < Dim; ++d) p.v.back()[d] = velocity[d].evaluate(xyz, 0);
  }
}

/// The particle-domain fields the shape function reads: CPDI corners (tracked, or offsets convected with
/// F) or GIMP half-lengths. Returns true when the corners are tracked (a module then moves them).
template <int Dim>
bool add_domain_fields(Body<Dim>& body, const SceneDescription& scene, const BodyDescription& bd,
                       const GridGeometry<Dim>& geometry, const ShapeFunctionInfo& shape,
                       const geometry::CpdiParticles<Dim>& elements) {
  auto& p = body.particles;
  bool track_corners = false;
  if (shape.domain_corners > 0) {
    CornerSet<Dim> none;
    none.fill(VecU<Dim>::Zero());
    body.domain_corners = shape.domain_corners;
    if (scene.solver.cpdi_domain_update == CpdiDomainUpdate::corners) {  // CPDI2: tracked corners (eq. 3.38)
      auto& corners = p.add_field(keys::cpdi_corners<Dim>, none);
      for (Index i = 0; i < p.size(); ++i)
        for (int c = 0; c < 4; ++c) corners[i][c] = p.x[i] + elements.offsets[i][c];
      track_corners = true;
    } else {  // original CPDI: corners convect with F (eq. 3.27)
      p.add_field(keys::cpdi_corner_offsets0<Dim>, none) = elements.offsets;
    }
  }
  body.stretched_domain = find_shape_function(scene.solver.shape_function)->stretched_domain;
  if (shape.particle_domain) {
    // GIMP: the initial particle domain is the sub-cell the particle was placed in (review §3.3).
    VecU<Dim> half;
    for (int d = 0; d < Dim; ++d) half[d] = 0.5 * geometry.h[d] / bd.particles_per_cell[d];
    p.add_field(keys::domain_half_length0<Dim>, half);
  }
  return track_corners;
}

/// The material of a body: its model's, wrapped when the scene material has a `failure:` block or Johnson-Cook
/// damage (failing_material.hpp): its strain energy is then the work its stress did (eq. 16.4), so that a fully
/// damaged point, which carries no shear and no tension but whose model's energy density grows with its expansion,
/// books only what its stress received.
template <int Dim>
std::shared_ptr<Material<Dim>> body_material(const MaterialDescription& description) {
  std::unique_ptr<Material<Dim>> material = make_material<Dim>(description);
  if (description.failure || description.parameters.contains("damage_d1"))
    return std::make_shared<FailingMaterial<Dim>>(std::move(material));
  return material;
}

/// The on-demand fields a run of the scene adds to a body besides its particle domains: APIC's affine velocity
/// (and PolyPIC's higher modes),
/// the axisymmetric hoop fields, what the output and the histories read, the material's history.
template <int Dim>
void add_run_fields(Body<Dim>& body, const SceneDescription& scene, const GridGeometry<Dim>& geometry) {
  if (carries_affine_velocity(scene.solver.velocity_transfer))
    body.particles.add_field(keys::affine_velocity<Dim>, MatU<Dim>::Zero());  // C_p = 0 at the start
  if constexpr (Dim >= 2)
    if (scene.solver.velocity_transfer == VelocityTransfer::polypic)  // and PolyPIC's higher modes (none in 1D)
      body.particles.add_field(keys::polypic_modes<Dim>, keys::zero_poly_modes<Dim>());
  if constexpr (Dim == 2)
    if (geometry.coordinates == Coordinates::axisymmetric) axisym::add_hoop_fields(body.particles);  // F_tt, L_tt
  prepare_output_fields<Dim>(scene.output.fields, body);                  // what the output reads (displacement: X_p)
  prepare_output_fields<Dim>(history_output_fields(scene.output), body);  // and what the histories read
  body.material->prepare_particles(body.particles);  // the model's history fields (plasticity), if any
  add_set_fields(scene, body);                       // set membership, a loaded set's body force
}

/// Body `index` of the scene: material, particles, and every on-demand field its run needs (domains, APIC,
/// the output's, the material's history); `track_corners` is set when its CPDI corners are tracked.
template <int Dim>
Body<Dim> build_body(const SceneDescription& scene, int index, const GridGeometry<Dim>& geometry,
                     const ShapeFunctionInfo& shape, bool& track_corners) {
  const BodyDescription& bd = scene.bodies[index];
  Body<Dim> body;
  body.name = bd.name;
  body.index = index;
  body.material = body_material<Dim>(scene.materials.at(bd.material));
  std::vector<std::string> warnings;  // repairs of mesh files (printed, the run goes on)
  const ParticleSeeds<Dim> seeds = shape_particles<Dim>(scene, bd, index, geometry, shape, warnings);
  const geometry::CpdiParticles<Dim> elements =
      particle_elements<Dim>(scene, bd, index, geometry, shape, seeds, warnings);
  add_particles<Dim>(body, bd, elements);
  apply_seed_state(body, seeds);    // what a particle file gives besides positions and volumes
  mark_particle_sets(scene, body);  // which particles belong to which set, from their state at t = 0
  track_corners = add_domain_fields<Dim>(body, scene, bd, geometry, shape, elements) || track_corners;
  add_run_fields<Dim>(body, scene, geometry);
  // The fill and the conforming domains each ask for the mesh, and each gets its repairs: print each once.
  for (auto w = warnings.begin(); w != warnings.end(); ++w)
    if (std::find(warnings.begin(), w, *w) == w) std::cerr << "warning: " << *w << '\n';
  return body;
}

template <int Dim>
SimulationSettings<Dim> simulation_settings(const SolverDescription& solver, Real max_particle_mass) {
  SimulationSettings<Dim> settings;
  settings.transfer.flip_fraction = solver.flip_fraction;
  settings.transfer.damping = solver.damping;
  settings.transfer.mass_cutoff = solver.mass_cutoff * max_particle_mass;
  for (int d = 0; d < Dim; ++d) settings.transfer.gravity[d] = solver.gravity[d];
  settings.fixed_dt = solver.dt;
  settings.cfl = solver.cfl.value_or(0.5);
  settings.end_time = solver.end_time;
  settings.snapshot_interval = solver.snapshot_interval;
  settings.sort_interval = solver.sort_interval;
  return settings;
}

template <int Dim>
Real max_particle_mass(const std::vector<Body<Dim>>& bodies) {
  Real m = 0;
  for (const auto& b : bodies)
    for (const Real mp : b.particles.mass) m = std::max(m, mp);
  return m;
}

/// Refuses a fixed dt above the stable time step of the initial state.
template <int Dim>
void check_fixed_time_step(const SceneDescription& scene, const Simulation<Dim>& sim) {
  const auto& fixed_dt = sim.settings().fixed_dt;
  if (!fixed_dt) return;
  if (scheme_of(scene.solver).traits.unconditionally_stable) return;
  const Real bound = sim.stable_time_step();
  if (*fixed_dt > bound)
    throw SceneError(scene.solver.dt_where, "solver.dt",
                     fmt::format("dt = {:.6g} s is larger than the stable time step {:.6g} s of the initial state "
                                 "({}); use dt <= {:.6g} or `cfl` instead",
                                 *fixed_dt, bound, sim.time_step_limiter(), bound));
}

/// Refuses an initial state whose mass, momentum or energy is not a finite number (a density of 1e308 on the heat
/// plate: its thermal energy m c T overflows), at the key that makes it so: the body's velocity for the kinetic
/// energy and the momentum, solver.gravity for the potential, the material's density otherwise.
template <int Dim>
void check_initial_state(const SceneDescription& scene, const Simulation<Dim>& sim) {
  for (std::size_t b = 0; b < sim.bodies().size(); ++b) {
    const EnergyBalance e = sim.body_energy(sim.bodies()[b]);
    const BodyDescription& bd = scene.bodies[b];
    const auto fail = [&](const SourceLocation& where, const std::string& key, const char* what) {
      throw SceneError(where, key,
                       fmt::format("body '{}' starts with a {} that is not a finite number in double precision "
                                   "(mass {:.6g} kg, kinetic energy {:.6g} J, potential {:.6g} J, heat {:.6g} J)",
                                   bd.name, what, e.mass, e.kinetic, e.gravity, e.thermal));
    };
    if (!std::isfinite(e.kinetic) || !e.momentum.allFinite())
      fail(locate_body_key(scene, bd.where, "velocity"), body_key(static_cast<int>(b), "velocity"),
           "kinetic energy or momentum");
    if (!std::isfinite(e.gravity)) fail(locate_key(scene, {"solver", "gravity"}), "solver.gravity", "potential energy");
    if (!std::isfinite(e.mass) || !std::isfinite(e.total()) || !std::isfinite(e.thermal))
      fail(locate_key(scene, {"materials", bd.material, "density"}), "materials." + bd.material + ".density",
           "mass or energy");
  }
}

}  // namespace

template <int Dim>
std::vector<Body<Dim>> prototype_bodies(const SceneDescription& scene, const GridGeometry<Dim>& geometry) {
  const ShapeFunctionInfo& shape = *find_shape_function(scene.solver.shape_function);
  std::vector<Body<Dim>> bodies;
  for (int k = 0; k < static_cast<int>(scene.bodies.size()); ++k) {
    const BodyDescription& bd = scene.bodies[k];
    Body<Dim> body;
    body.name = bd.name;
    body.index = k;
    body.material = body_material<Dim>(scene.materials.at(bd.material));
    add_domain_fields<Dim>(body, scene, bd, geometry, shape, geometry::CpdiParticles<Dim>{});
    add_run_fields<Dim>(body, scene, geometry);
    bodies.push_back(std::move(body));
  }
  prepare_scene_extensions<Dim>(scene, bodies, geometry);  // the modules' particle fields (thermal: temperature)
  return bodies;
}

namespace {

/// The failure module (failure/failure_module.hpp) of a scene in which a material has a `failure:` block. Erosion
/// removes particles, which a scheme that keeps its particles in their initial order cannot (TLMPM); the criterion
/// min_time_step needs each particle's wave speed of its model.
template <int Dim>
void add_failure_module(const SceneDescription& scene, Simulation<Dim>& sim, bool reorders_particles) {
  std::vector<BodyFailure> bodies;
  for (const auto& b : sim.bodies()) {
    const MaterialDescription& m = scene.materials.at(scene.bodies[static_cast<std::size_t>(b.index)].material);
    if (!m.failure) continue;
    const std::string key = "materials." + m.name + ".failure";
    if (m.failure->action == FailureAction::erode && !reorders_particles)
      throw SceneError(m.failure_where, key,
                       fmt::format("scheme {}: erosion removes particles, which a scheme that keeps per-particle data "
                                   "in the particles' initial order cannot (the reference stencils); use action: fail, "
                                   "or scheme usl, musl or usf",
                                   scene.solver.scheme));
    std::vector<Real> speeds;
    if (m.failure->min_time_step && !b.material->particle_wave_speeds(b.particles, speeds))
      throw SceneError(m.failure_where, key + ".min_time_step",
                       fmt::format("model {} gives no wave speed per particle, which the particle's own time step "
                                   "(eq. 16.3) needs; use another criterion",
                                   m.model));
    bodies.push_back({b.index, *m.failure});
  }
  if (!bodies.empty()) sim.add_module(std::make_shared<FailureModule<Dim>>(std::move(bodies), sim.settings().cfl));
}

/// With `solver.damping`: the books of the damping's work (local_damping_book.hpp). The bodies a module moves with a
/// prescribed velocity (a ReactionProvider's partners named like a body: contact's rigid bodies) are not damped.
template <int Dim>
void add_damping_book(const SceneDescription& scene, Simulation<Dim>& sim) {
  if (!(scene.solver.damping > 0)) return;
  std::vector<int> prescribed;
  for (const auto& m : sim.modules())
    if (const auto* provider = dynamic_cast<const ReactionProvider<Dim>*>(m.get()))
      for (const auto& name : provider->reaction_partners())
        for (const auto& b : sim.bodies())
          if (b.name == name) prescribed.push_back(b.index);
  sim.add_module(std::make_shared<LocalDampingBook<Dim>>(scene.solver.damping, std::move(prescribed)));
}

/// The energy sentinel of every run (energy_sentinel.hpp), with the rigid partners of the modules that hold the
/// bodies (reaction_provider.hpp) and the method it quotes hints for.
template <int Dim>
void add_energy_sentinel(const SceneDescription& scene, Simulation<Dim>& sim) {
  HintContext context;
  context.scheme = scheme_of(scene.solver).traits;
  context.shape_function = scene.solver.shape_function;
  context.transfer = scene.solver.velocity_transfer;
  context.flip_fraction = scene.solver.flip_fraction;
  context.fixed_dt = scene.solver.dt.has_value();
  for (const auto& [name, m] : scene.materials) {
    const auto volumetric = m.parameters.find("volumetric_deformation");
    context.fluid_full_deformation =
        context.fluid_full_deformation || (volumetric != m.parameters.end() && volumetric->second == 0);
  }
  std::vector<typename EnergySentinel<Dim>::Partner> partners;
  for (const auto& m : sim.modules()) {
    context.contact = context.contact || m->name() == "contact";
    const auto* provider = dynamic_cast<const ReactionProvider<Dim>*>(m.get());
    if (!provider) continue;
    const auto names = provider->reaction_partners();
    for (int k = 0; k < static_cast<int>(names.size()); ++k) {
      int body = -1;
      for (const auto& b : sim.bodies())
        if (b.name == names[static_cast<std::size_t>(k)]) body = b.index;
      partners.push_back({provider, k, body});
    }
  }
  sim.add_energy_sentinel(std::make_shared<EnergySentinel<Dim>>(scene.solver.energy_tolerance,
                                                                scene.solver.on_energy_drift, context, sim.energy(),
                                                                sim.boundary().does_work(), std::move(partners)));
}

}  // namespace

/// The gravity stage of the scene (gravity_stage.hpp), with its refusals: particles that leave through an outflow
/// face while settling (the books of the run start after the stage), a stage that does not settle and should stop.
template <int Dim>
GravityStageReport settle_under_gravity(const SceneDescription& scene, Simulation<Dim>& sim) {
  const GravityStageDescription& stage = *scene.solver.gravity_stage;
  const GravityStageReport report = run_gravity_stage<Dim>(
      sim, {.damping = stage.damping, .tolerance = stage.tolerance, .max_steps = stage.max_steps});
  const auto fail = [&](const std::string& message) { throw SceneError(stage.where, "solver.gravity_stage", message); };
  for (const auto& book : sim.boundary().outflow())
    if (book.particle_count() > 0)
      fail(
          fmt::format("{} particles left through the outflow face {} while the bodies settled under gravity: the "
                      "stage is for bodies that come to rest in the grid",
                      book.particle_count(), face_names[static_cast<std::size_t>(book.face)]));
  if (!report.converged && stage.on_no_equilibrium == NoEquilibriumAction::stop)
    fail(
        fmt::format("the bodies did not come to rest under gravity: the unbalanced force ratio is {:.3g} after {} "
                    "steps (tolerance {:.3g}); a body that fails under its own weight (a slope steeper than it "
                    "stands) never settles. Raise max_steps, or give on_no_equilibrium: warn to run from the state "
                    "reached",
                    report.ratio, report.steps, report.tolerance));
  return report;
}

template <int Dim>
std::unique_ptr<Simulation<Dim>> build_simulation(const SceneDescription& scene, bool gravity_stage,
                                                  GravityStageReport* stage_report) {
  const GridGeometry<Dim> geometry = grid_geometry<Dim>(scene.grid);
  check_memory<Dim>(scene, geometry, available_memory());  // before anything the size of the scene is allocated
  auto scheme = make_scene_scheme<Dim>(scene);
  const bool reorders_particles = scheme->reorders_particles();
  const ShapeFunctionInfo& shape = *find_shape_function(scene.solver.shape_function);
  check_output_against_shape_function(scene, shape);

  std::vector<Body<Dim>> bodies;
  bodies.reserve(scene.bodies.size());
  bool track_corners = false;
  for (int k = 0; k < static_cast<int>(scene.bodies.size()); ++k)
    bodies.push_back(build_body<Dim>(scene, k, geometry, shape, track_corners));
  apply_geostatic_stress<Dim>(scene, bodies, geometry);  // a set's stress at rest under gravity (over all bodies)
  // Optional modules the scene asks for (thermal: heat conduction), built before the first snapshot so that
  // their particle fields are part of it.
  std::vector<std::shared_ptr<Module<Dim>>> modules = prepare_scene_extensions<Dim>(scene, bodies, geometry);
  if (const auto message = unavailable_output_field<Dim>(scene.output.fields, bodies))
    throw SceneError(scene.output.where, "output.fields", *message);

  const SimulationSettings<Dim> settings = simulation_settings<Dim>(scene.solver, max_particle_mass(bodies));
  GridBoundary<Dim> boundary = make_grid_boundary<Dim>(scene, geometry, *scheme);  // the faces' kinds
  auto sim =
      std::make_unique<Simulation<Dim>>(geometry, std::move(bodies), std::move(scheme), std::move(boundary), settings);
  for (auto& m : modules) sim->add_module(std::move(m));
  build_scene_extensions<Dim>(scene, *sim);  // modules with their own scene section (contact)
  if (auto sets = scene_set_conditions<Dim>(scene)) sim->add_module(std::move(sets));  // after contact: it holds last
  if (track_corners) sim->add_module(std::make_shared<CpdiCornerTracking<Dim>>(shape.domain_corners));
  if (scene.solver.gravity_stage && gravity_stage) {  // before the books: the run's E(0) is the settled state
    GravityStageReport report = settle_under_gravity<Dim>(scene, *sim);
    if (stage_report) *stage_report = std::move(report);
  }
  add_failure_module<Dim>(scene, *sim, reorders_particles);
  add_damping_book<Dim>(scene, *sim);     // after contact: it books the velocities contact corrected
  add_energy_sentinel<Dim>(scene, *sim);  // last: its E(0) is the audit of the complete initial state
  check_fixed_time_step<Dim>(scene, *sim);
  check_time_step(estimate_steps<Dim>(scene, *sim), scene);  // 0, infinite, or too small to reach end_time
  check_initial_state<Dim>(scene, *sim);
  return sim;
}

template std::vector<Body<1>> prototype_bodies<1>(const SceneDescription&, const GridGeometry<1>&);
template std::vector<Body<2>> prototype_bodies<2>(const SceneDescription&, const GridGeometry<2>&);
template std::vector<Body<3>> prototype_bodies<3>(const SceneDescription&, const GridGeometry<3>&);
template std::unique_ptr<Simulation<1>> build_simulation<1>(const SceneDescription&, bool, GravityStageReport*);
template std::unique_ptr<Simulation<2>> build_simulation<2>(const SceneDescription&, bool, GravityStageReport*);
template std::unique_ptr<Simulation<3>> build_simulation<3>(const SceneDescription&, bool, GravityStageReport*);

}  // namespace mpm::app
