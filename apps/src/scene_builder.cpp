#include "mpm/app/scene_builder.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <iostream>

#include "mpm/cpdi_corner_tracking.hpp"
#include "mpm/expression.hpp"
#include "mpm/geometry/conforming_domains.hpp"
#include "mpm/geometry/cpdi_domains.hpp"
#include "mpm/geometry/geometry_error.hpp"
#include "mpm/geometry/shape_filler.hpp"
#include "mpm/material_registry.hpp"
#include "mpm/scene_error.hpp"
#include "mpm/scene_extension.hpp"

namespace mpm::app {

template <int Dim>
std::unique_ptr<Simulation<Dim>> build_simulation(const SceneDescription& scene) {
  const auto& gd = scene.grid;
  Vec<Dim> origin, h;
  std::array<int, Dim> cells{};
  for (int d = 0; d < Dim; ++d) {
    origin[d] = gd.origin[d];
    h[d] = gd.cell_size[d];
    cells[d] = gd.cells[d];
  }
  const GridGeometry<Dim> geometry(origin, h, cells);
  auto scheme = make_scheme<Dim>(std::string(enum_name(scene.solver.scheme)), scene.solver.shape_function);

  const auto wants = [&](const char* field) {
    return std::find(scene.output.fields.begin(), scene.output.fields.end(), field) != scene.output.fields.end();
  };
  std::vector<Body<Dim>> bodies;
  Real max_particle_mass = 0;
  bool track_corners = false;
  for (const auto& bd : scene.bodies) {
    const MaterialDescription& md = scene.materials.at(bd.material);
    Body<Dim> body;
    body.name = bd.name;
    body.index = static_cast<int>(bodies.size());
    body.material = make_material<Dim>(md);
    const std::string shape_key = "bodies[" + std::to_string(body.index) + "].shape";
    std::vector<std::string> warnings;  // repairs of mesh files (printed, the run goes on)
    geometry::ParticleSeeds<Dim> seeds;
    try {
      seeds = geometry::fill_shape<Dim>(bd.shape, geometry, bd.particles_per_cell, &warnings);
    } catch (const geometry::GeometryError& e) {
      throw SceneError(bd.shape.where, shape_key, "body '" + bd.name + "': " + e.what());
    }
    if (seeds.positions.empty())
      throw SceneError(bd.where, "bodies[" + std::to_string(body.index) + "].shape",
                       "body '" + bd.name + "' contains no particle: the shape is smaller than a particle spacing");
    std::array<Expression, 3> velocity{Expression(bd.velocity[0], {"x", "y", "z"}),
                                       Expression(bd.velocity[1], {"x", "y", "z"}),
                                       Expression(bd.velocity[2], {"x", "y", "z"})};
    auto& p = body.particles;
    const Real rho = body.material->density();
    const ShapeFunctionInfo& shape = *find_shape_function(scene.solver.shape_function);
    // CPDI: every sub-cell becomes one or more particle elements (segments, quads, triangles, tets).
    geometry::CpdiParticles<Dim> elements;
    const bool conforming = bd.domains == "conforming";
    if (conforming && !((Dim == 2 && scene.solver.shape_function == "cpdi_t3") ||
                        (Dim == 3 && scene.solver.shape_function == "cpdi_tet4")))
      throw SceneError(bd.where, "bodies[" + std::to_string(body.index) + "].domains",
                       "domains: conforming needs shape_function cpdi_t3 (2D) or cpdi_tet4 (3D); the solver uses " +
                           scene.solver.shape_function);
    if (conforming) {  // CGAL triangle / tetrahedron mesh of the shape (geometry/conforming_domains.hpp)
      Real spacing = h[0] / bd.particles_per_cell[0];
      for (int d = 1; d < Dim; ++d) spacing = std::min<Real>(spacing, h[d] / bd.particles_per_cell[d]);
      try {
        elements = geometry::conforming_cpdi_particles<Dim>(bd.shape, spacing, &warnings);
      } catch (const geometry::GeometryError& e) {
        throw SceneError(bd.shape.where, shape_key, "body '" + bd.name + "': " + e.what());
      }
    } else if (shape.domain_corners > 0) {
      Vec<Dim> spacing;
      for (int d = 0; d < Dim; ++d) spacing[d] = h[d] / bd.particles_per_cell[d];
      elements = geometry::cpdi_particles<Dim>(seeds, spacing, shape.domain_corners);
    } else {
      elements.positions = seeds.positions;
      elements.volumes.assign(seeds.positions.size(), seeds.volume);
    }
    for (std::size_t k = 0; k < elements.positions.size(); ++k) {
      const Vec<Dim>& x = elements.positions[k];
      p.add(x, rho * elements.volumes[k], elements.volumes[k]);
      double xyz[3] = {0, 0, 0};
      for (int d = 0; d < Dim; ++d) xyz[d] = x[d];
      for (int d = 0; d < Dim; ++d) p.v.back()[d] = velocity[d].evaluate(xyz, 0);
    }
    if (shape.domain_corners > 0) {
      CornerSet<Dim> none;
      none.fill(VecU<Dim>::Zero());
      body.domain_corners = shape.domain_corners;
      if (scene.solver.cpdi_domain_update == CpdiDomainUpdate::corners) {  // CPDI2: tracked corners (eq. 3.38)
        auto& corners = p.template add_field<CornerSet<Dim>>("cpdi_corners", none);
        for (Index i = 0; i < p.size(); ++i)
          for (int c = 0; c < 4; ++c) corners[i][c] = p.x[i] + elements.offsets[i][c];
        track_corners = true;
      } else {  // original CPDI: corners convect with F (eq. 3.27)
        p.template add_field<CornerSet<Dim>>("cpdi_corner_offsets0", none) = elements.offsets;
      }
    }
    // On-demand fields, allocated only when the output asks for them.
    if (wants("displacement")) {
      auto& x0 = p.template add_field<VecU<Dim>>("reference_position", VecU<Dim>::Zero());
      for (Index i = 0; i < p.size(); ++i) x0[i] = p.x[i];
    }
    if (wants("domains") && !shape.particle_domain && shape.domain_corners == 0)
      throw SceneError(scene.output.where, "output.fields",
                       "domains are only defined for shape functions with particle domains (gimp, cpgimp, cpdi_*), "
                       "not " +
                           scene.solver.shape_function);
    if (wants("domain_size") && !shape.particle_domain)
      throw SceneError(scene.output.where, "output.fields",
                       "domain_size is only defined for shape functions with particle domains (gimp, cpgimp), not " +
                           scene.solver.shape_function);
    body.stretched_domain = scene.solver.shape_function == "cpgimp";
    if (shape.particle_domain) {
      // GIMP: the initial particle domain is the sub-cell the particle was placed in (review §3.3).
      VecU<Dim> half;
      for (int d = 0; d < Dim; ++d) half[d] = 0.5 * h[d] / bd.particles_per_cell[d];
      p.template add_field<VecU<Dim>>("domain_half_length0", half);
    }
    if (scene.solver.velocity_transfer == VelocityTransfer::apic)
      p.template add_field<MatU<Dim>>("affine_velocity", MatU<Dim>::Zero());  // C_p = 0 at the start
    if (wants("velocity_gradient")) p.template add_field<MatU<Dim>>("velocity_gradient", MatU<Dim>::Zero());
    body.material->prepare_particles(p);  // the model's history fields (plasticity), if it has any
    for (const Real v : elements.volumes) max_particle_mass = std::max(max_particle_mass, rho * v);
    for (const auto& w : warnings) std::cerr << "warning: " << w << '\n';
    bodies.push_back(std::move(body));
  }
  // Optional modules the scene asks for (thermal: heat conduction), built before the first snapshot so that
  // their particle fields are part of it.
  std::vector<std::shared_ptr<Module<Dim>>> modules = prepare_scene_extensions<Dim>(scene, bodies, geometry);
  if (wants("temperature") && std::none_of(bodies.begin(), bodies.end(),
                                           [](const Body<Dim>& b) { return b.particles.has_field("temperature"); }))
    throw SceneError(scene.output.where, "output.fields",
                     "temperature: no body tracks temperature; give a material specific_heat (johnson_cook, "
                     "j2_plasticity), add a thermal: section, or remove temperature from the fields");
  if (wants("heat_flux") &&
      std::none_of(bodies.begin(), bodies.end(), [](const Body<Dim>& b) { return b.particles.has_field("heat_flux"); }))
    throw SceneError(scene.output.where, "output.fields",
                     "heat_flux: no body conducts heat; add a thermal: section (and thermal_conductivity to the "
                     "materials) or remove heat_flux from the fields");

  SimulationSettings<Dim> settings;
  settings.transfer.flip_fraction = scene.solver.flip_fraction;
  settings.transfer.mass_cutoff = scene.solver.mass_cutoff * max_particle_mass;
  for (int d = 0; d < Dim; ++d) settings.transfer.gravity[d] = scene.solver.gravity[d];
  settings.fixed_dt = scene.solver.dt;
  settings.cfl = scene.solver.cfl.value_or(0.5);
  settings.end_time = scene.solver.end_time;
  settings.snapshot_interval = scene.solver.snapshot_interval;
  settings.sort_interval = scene.solver.sort_interval;

  auto sim = std::make_unique<Simulation<Dim>>(geometry, std::move(bodies), std::move(scheme),
                                               GridBoundary<Dim>(geometry, gd.boundary), settings);
  for (auto& m : modules) sim->add_module(std::move(m));
  build_scene_extensions<Dim>(scene, *sim);  // modules with their own scene section (contact)
  if (track_corners)
    sim->add_module(
        std::make_shared<CpdiCornerTracking<Dim>>(find_shape_function(scene.solver.shape_function)->domain_corners));
  if (settings.fixed_dt) {
    const Real bound = sim->stable_time_step();
    if (*settings.fixed_dt > bound)
      throw SceneError(scene.solver.dt_where, "solver.dt",
                       fmt::format("dt = {:.6g} s is larger than the stable time step {:.6g} s of the initial state "
                                   "({}); use dt <= {:.6g} or `cfl` instead",
                                   *settings.fixed_dt, bound, sim->time_step_limiter(), bound));
  }
  return sim;
}

template std::unique_ptr<Simulation<1>> build_simulation<1>(const SceneDescription&);
template std::unique_ptr<Simulation<2>> build_simulation<2>(const SceneDescription&);
template std::unique_ptr<Simulation<3>> build_simulation<3>(const SceneDescription&);

}  // namespace mpm::app
