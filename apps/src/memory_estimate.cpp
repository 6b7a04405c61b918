#include "mpm/app/memory_estimate.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "mpm/app/key_location.hpp"
#include "mpm/app/scene_builder.hpp"
#include "mpm/body_shape/shape_kind.hpp"
#include "mpm/geometry/particle_count.hpp"
#include "mpm/scene/scene_error.hpp"
#include "mpm/schemes/scheme_registry.hpp"
#include "mpm/shape/shape_functions.hpp"

namespace mpm::app {
namespace {

/// Particle elements per lattice sub-cell: CPDI splits each into segments, quads, 2 triangles or 6 tetrahedra
/// (geometry/cpdi_domains.hpp; a conforming mesh at the same spacing has about as many).
int elements_per_sub_cell(int dimension, int corners) {
  if (corners == 0 || dimension == 1) return 1;
  if (dimension == 2) return corners == 3 ? 2 : 1;
  return 6;
}

/// What the scheme keeps per particle besides the fields (TLMPM: its cached reference stencils), by its trait.
template <int Dim>
std::size_t scheme_bytes_per_particle(const SceneDescription& scene) {
  const SchemeBytesPerParticle bytes = scheme_of(scene.solver).traits.bytes_per_particle;
  if (!bytes) return 0;
  int support = 0;
  dispatch_shape(scene.solver.shape_function, [&]<class Shape>() { support = Shape::support; });
  return bytes(Dim, support);
}

/// The count of one body: an upper bound (bounding box, or the grid for shapes read from files) or the sample.
template <int Dim>
void count_body(BodyMemory& m, const BodyDescription& bd, const GridGeometry<Dim>& geometry, bool sample, int index) {
  const ShapeKind& kind = shape_kind(bd.shape);
  geometry::Box<Dim> grid_box{geometry.origin, geometry.upper()};
  try {
    // Particles of the kind's own: a particle file (as many as its rows, bounded by the file itself), an image's
    // pixels.
    if (const auto own = kind.own_count ? kind.own_count(bd.shape.spec, Dim) : std::nullopt) {
      m.particles = own->count;
      m.exact = m.sampled = own->exact;
      return;
    }
    // Filling a shape that reads a file (a mesh, an image) costs the read: an upper bound is taken from the grid
    // instead until a closer count is needed.
    if (!sample && !shape_file(bd.shape).empty()) {
      m.particles = geometry::lattice_points_in<Dim>(grid_box, geometry, bd.particles_per_cell);
      return;
    }
    const auto region = geometry::make_region<Dim>(bd.shape);
    if (!sample) {
      m.particles = geometry::lattice_points_in<Dim>(region->bounds(), geometry, bd.particles_per_cell);
      return;
    }
    const auto count = geometry::count_particles<Dim>(*region, geometry, bd.particles_per_cell);
    m.particles = count.count;
    m.exact = count.exact;
    m.sampled = true;
  } catch (const ShapeError& e) {
    throw SceneError(bd.shape.where, fmt::format("bodies[{}].shape", index), "body '" + bd.name + "': " + e.what());
  }
}

std::string count_text(double n) { return n < 1e6 ? fmt::format("{:.0f}", n) : fmt::format("{:.3g}", n); }

/// The refusal: what needs the memory, the estimate, what is available, what to change.
[[noreturn]] void refuse(const SceneDescription& scene, const MemoryEstimate& e, const MemoryBudget& budget,
                         bool grid_alone) {
  const std::string available = fmt::format("{} available ({})", format_bytes(budget.bytes), budget.source);
  const std::string grid =
      fmt::format("{} grid nodes x {} B = {}", count_text(e.nodes), e.bytes_per_node, format_bytes(e.grid_bytes()));
  if (grid_alone)
    throw SceneError(locate_key(scene, {"grid", "cell_size"}), "grid.cell_size",
                     fmt::format("the grid alone needs about {} of memory ({}), {}: use a larger cell_size",
                                 format_bytes(e.grid_bytes()), grid, available));
  std::size_t worst = 0;
  for (std::size_t b = 1; b < e.bodies.size(); ++b)
    if (e.bodies[b].bytes() > e.bodies[worst].bytes()) worst = b;
  std::string parts;
  for (const auto& m : e.bodies)
    parts += fmt::format("body '{}': {} particles{} x ({:.0f} x {} B + {} B) = {}; ", m.name, count_text(m.particles),
                         m.exact ? "" : " (estimated on a sample of its region)", particle_state_copies, m.state_bytes,
                         m.bytes_per_particle - m.state_bytes, format_bytes(m.bytes()));
  const BodyDescription& bd = scene.bodies[worst];
  std::string ppc = std::to_string(bd.particles_per_cell[0]);
  for (int d = 1; d < scene.dimension; ++d) ppc += " x " + std::to_string(bd.particles_per_cell[d]);
  throw SceneError(locate_body_key(scene, bd.where, "particles_per_cell"),
                   fmt::format("bodies[{}].particles_per_cell", worst),
                   fmt::format("the scene needs about {} of memory ({}{}; {:.0f} copies of the particle state: the "
                               "state, the stability guard's snapshot and the sort's scratch), {}: use fewer "
                               "particles per cell (now {}) or a larger grid.cell_size",
                               format_bytes(e.bytes()), parts, grid, particle_state_copies, available, ppc));
}

}  // namespace

double BodyMemory::bytes() const {
  return particles * (particle_state_copies * static_cast<double>(state_bytes) +
                      static_cast<double>(bytes_per_particle - state_bytes));
}

double MemoryEstimate::particles() const {
  double n = 0;
  for (const auto& b : bodies) n += b.particles;
  return n;
}

double MemoryEstimate::bytes() const {
  double total = grid_bytes();
  for (const auto& b : bodies) total += b.bytes();
  return total;
}

template <int Dim>
MemoryEstimate estimate_grid_memory(const GridGeometry<Dim>& geometry) {
  MemoryEstimate e;
  e.nodes = 1;
  for (int d = 0; d < Dim; ++d) e.nodes *= static_cast<double>(geometry.cells(d)) + 1;
  e.bytes_per_node = 2 * (sizeof(NodeRecord<Dim>) + sizeof(NodeVelocity<Dim>));
  return e;
}

template <int Dim>
MemoryEstimate estimate_memory(const SceneDescription& scene, const GridGeometry<Dim>& geometry, bool sample) {
  MemoryEstimate e = estimate_grid_memory<Dim>(geometry);
  const auto prototypes = prototype_bodies<Dim>(scene, geometry);
  const ShapeFunctionInfo& shape = *find_shape_function(scene.solver.shape_function);
  const int elements = elements_per_sub_cell(Dim, shape.domain_corners);
  const std::size_t scheme_bytes = scheme_bytes_per_particle<Dim>(scene);
  for (std::size_t b = 0; b < scene.bodies.size(); ++b) {
    BodyMemory m;
    m.name = scene.bodies[b].name;
    m.state_bytes = prototypes[b].particles.bytes_per_particle();
    m.bytes_per_particle = m.state_bytes + scheme_bytes;
    count_body<Dim>(m, scene.bodies[b], geometry, sample, static_cast<int>(b));
    m.particles *= elements;
    e.bodies.push_back(m);
  }
  return e;
}

template <int Dim>
void check_memory(const SceneDescription& scene, const GridGeometry<Dim>& geometry, const MemoryBudget& budget) {
  const MemoryEstimate grid = estimate_grid_memory<Dim>(geometry);
  if (grid.grid_bytes() > budget.bytes) refuse(scene, grid, budget, true);
  if (estimate_memory<Dim>(scene, geometry, false).bytes() <= budget.bytes) return;  // the upper bound fits
  const MemoryEstimate e = estimate_memory<Dim>(scene, geometry, true);
  if (e.bytes() > budget.bytes) refuse(scene, e, budget, false);
}

template MemoryEstimate estimate_grid_memory<1>(const GridGeometry<1>&);
template MemoryEstimate estimate_grid_memory<2>(const GridGeometry<2>&);
template MemoryEstimate estimate_grid_memory<3>(const GridGeometry<3>&);
template MemoryEstimate estimate_memory<1>(const SceneDescription&, const GridGeometry<1>&, bool);
template MemoryEstimate estimate_memory<2>(const SceneDescription&, const GridGeometry<2>&, bool);
template MemoryEstimate estimate_memory<3>(const SceneDescription&, const GridGeometry<3>&, bool);
template void check_memory<1>(const SceneDescription&, const GridGeometry<1>&, const MemoryBudget&);
template void check_memory<2>(const SceneDescription&, const GridGeometry<2>&, const MemoryBudget&);
template void check_memory<3>(const SceneDescription&, const GridGeometry<3>&, const MemoryBudget&);

}  // namespace mpm::app
