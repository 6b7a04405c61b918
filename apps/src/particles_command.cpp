#include "mpm/app/particles_command.hpp"

#include <fmt/format.h>
#include <fmt/ostream.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <numeric>
#include <ostream>
#include <stdexcept>

#include "mpm/app/body_summary.hpp"
#include "mpm/app/memory_budget.hpp"
#include "mpm/app/modules.hpp"
#include "mpm/app/run_scene.hpp"
#include "mpm/app/scene_builder.hpp"
#include "mpm/geometry/cad_region.hpp"
#include "mpm/geometry/conforming_domains.hpp"
#include "mpm/geometry/cpdi_domains.hpp"
#include "mpm/geometry/file_shapes.hpp"
#include "mpm/geometry/geometry_error.hpp"
#include "mpm/geometry/gmsh_body.hpp"
#include "mpm/geometry/mass_properties.hpp"
#include "mpm/geometry/particle_count.hpp"
#include "mpm/geometry/shape_filler.hpp"
#include "mpm/io/vtk_writer.hpp"
#include "mpm/output/particle_domain_mesh.hpp"
#include "mpm/scene/scene_error.hpp"
#include "mpm/scene/scene_limits.hpp"
#include "mpm/scene/scene_loader.hpp"

namespace mpm::app {
namespace {

/// A bad command line: exit status 2 with the message.
struct UsageError : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

std::string lower_extension(const std::string& file) {
  std::string ext = std::filesystem::path(file).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

std::filesystem::path domains_path(const std::filesystem::path& output) {
  return output.parent_path() / (output.stem().string() + "_domains.vtu");
}

template <int Dim>
void push_point(std::vector<double>& out, const Vec<Dim>& x) {
  for (int d = 0; d < 3; ++d) out.push_back(d < Dim ? x[d] : 0.0);
}

/// A file without a length unit (a surface or Gmsh mesh) drawn in millimetres and read as metres is 1000 times too
/// large and its fill 1e9 (3D) times too big: when the fill would fit with the coordinates taken as millimetres, the
/// refusal says so (a user saw "15.8 PB of memory" and no reason).
template <int Dim>
std::string millimetre_hint(const ParticlesOptions& o, const geometry::Region<Dim>& region, double bytes,
                            const MemoryBudget& budget) {
  const std::string ext = lower_extension(o.input);
  const bool unitless = ext == ".stl" || ext == ".obj" || ext == ".off" || ext == ".ply" || ext == ".msh";
  if (!unitless || o.scale != 1 || !(bytes * std::pow(1e-3, Dim) <= budget.bytes)) return "";
  const geometry::Box<Dim> box = region.bounds();
  std::string size;
  for (int d = 0; d < Dim; ++d) size += fmt::format("{}{:.4g}", d ? " x " : "", box.hi[d] - box.lo[d]);
  return fmt::format(
      ". The input spans {} m: if its coordinates are millimetres, --scale 0.001 (in a scene, the "
      "shape's `scale: 1.0e-3`) makes it fit",
      size);
}

/// Refuses a fill that cannot fit in memory before it is made: the particle count of the region's lattice (on a
/// sample, geometry/particle_count.hpp) times what this command keeps per particle (position and volume, then the
/// .vtu's points and three fields, 3 x 8 + 3 x 8 B, and CPDI corners), against the memory available.
template <int Dim>
void check_fill_memory(const ParticlesOptions& o, const geometry::Region<Dim>& region, const GridGeometry<Dim>& grid,
                       const std::array<int, 3>& ppc) {
  const auto count = geometry::count_particles<Dim>(region, grid, ppc);
  const double elements = o.domains.empty() ? 1 : (Dim == 2 ? 2 : 6);
  const double per_particle = (Dim + 1) * 8.0 + 48 + (o.domains.empty() ? 0 : (Dim + 1) * Dim * 8.0 * 2);
  const double bytes = count.count * elements * per_particle;
  const MemoryBudget budget = available_memory();
  if (bytes > budget.bytes)
    throw UsageError(
        fmt::format("--ppc {} with cells of {:g} m makes about {:.3g} particles{}, about {} of memory; "
                    "{} available ({}): use a smaller --ppc or a larger --spacing{}",
                    o.particles_per_cell, grid.h[0], count.count * elements,
                    count.exact ? "" : " (estimated on a sample of the input)", format_bytes(bytes),
                    format_bytes(budget.bytes), budget.source, millimetre_hint<Dim>(o, region, bytes, budget)));
}

/// Particles of an input file on a grid: the scene's or one of `spacing` around the input.
template <int Dim>
std::string write_input(const ParticlesOptions& o, const ShapeDescription& shape,
                        const std::optional<SceneDescription>& scene, std::ostream& err) {
  std::vector<std::string> warnings;
  const auto region = geometry::make_region<Dim>(shape, &warnings);
  Vec<Dim> origin, h;
  std::array<int, Dim> cells{};
  if (scene) {
    if (scene->dimension != Dim)
      throw UsageError(
          fmt::format("{} makes a {}D body; the scene {} is {}D", o.input, Dim, o.scene, scene->dimension));
    for (int d = 0; d < Dim; ++d) {
      origin[d] = scene->grid.origin[d];
      h[d] = scene->grid.cell_size[d];
      cells[d] = scene->grid.cells[d];
    }
  } else {  // cells of `spacing` aligned with 0, one empty cell around the input
    const geometry::Box<Dim> box = region->bounds();
    for (int d = 0; d < Dim; ++d) {
      h[d] = *o.spacing;
      origin[d] = (std::floor(box.lo[d] / h[d]) - 1) * h[d];
      const double n = std::ceil(box.hi[d] / h[d]) + 1 - std::floor(box.lo[d] / h[d]) + 1;
      if (!(n <= 1e9))
        throw UsageError(
            fmt::format("--spacing {:g} m makes {:.3g} cells on an axis of the input (at most 1e9)", *o.spacing, n));
      cells[d] = static_cast<int>(n);
    }
  }
  const GridGeometry<Dim> grid(origin, h, cells);
  const std::array<int, 3> ppc{o.particles_per_cell, o.particles_per_cell, o.particles_per_cell};
  check_fill_memory<Dim>(o, *region, grid, ppc);
  const auto seeds = geometry::fill_shape<Dim>(shape, grid, ppc, &warnings);
  if (seeds.positions.empty())
    throw geometry::GeometryError(o.input, "no particle: the body is smaller than a particle spacing");

  geometry::CpdiParticles<Dim> elements;
  Vec<Dim> spacing = h / o.particles_per_cell;
  if (o.domains == "conforming") {
    elements = geometry::conforming_cpdi_particles<Dim>(shape, spacing.minCoeff(), &warnings);
  } else if (o.domains == "lattice") {
    elements = geometry::cpdi_particles<Dim>(seeds, spacing, Dim == 2 ? 3 : 4);
  } else {
    elements.positions = seeds.positions;
    elements.volumes = seeds.volumes;  // a kind's own particles' (a Gmsh mesh's elements), else the lattice's
    if (elements.volumes.empty()) elements.volumes.assign(seeds.positions.size(), seeds.volume);
  }
  // The region, the fill and the domains each ask for the mesh, and each gets its repairs: print each once.
  for (auto w = warnings.begin(); w != warnings.end(); ++w)
    if (std::find(warnings.begin(), w, *w) == w) err << "warning: " << *w << '\n';

  io::PointCloud cloud;
  io::FieldArray volume{"volume", 1, elements.volumes}, body{"body", 1, {}}, id{"id", 1, {}};
  for (std::size_t k = 0; k < elements.positions.size(); ++k) {
    push_point<Dim>(cloud.points, elements.positions[k]);
    body.values.push_back(0);
    id.values.push_back(static_cast<double>(k));
  }
  cloud.fields = {volume, body, id};
  io::write_vtu(o.output, cloud);
  if (!o.domains.empty()) {
    io::CellMesh cells_mesh;
    cells_mesh.corners = Dim == 2 ? 3 : 4;
    cells_mesh.cell_type = Dim == 2 ? 5 : 10;  // VTK_TRIANGLE, VTK_TETRA
    for (std::size_t k = 0; k < elements.positions.size(); ++k)
      for (int c = 0; c < cells_mesh.corners; ++c)
        push_point<Dim>(cells_mesh.points, Vec<Dim>(elements.positions[k] + Vec<Dim>(elements.offsets[k][c])));
    cells_mesh.cell_fields = {volume, id};
    io::write_cells_vtu(domains_path(o.output), cells_mesh);
  }
  const double total = std::accumulate(elements.volumes.begin(), elements.volumes.end(), 0.0);
  std::string certificate;
  if constexpr (Dim == 3)
    if (const auto source = geometry::exact_properties(*region))  // CAD and mesh bodies: the lattice against them
      certificate = "\n" + geometry::format_certificate(geometry::certify(
                               source->exact,
                               geometry::particle_properties(
                                   seeds.positions, seeds.volumes.empty() ? std::vector<Real>(seeds.positions.size(),
                                                                                              seeds.sub_cell_volume)
                                                                          : seeds.volumes),
                               source->source));
  std::string text =
      fmt::format("{}: {} particles ({}D, cells of {:.6g} m, {} per cell per axis{}), volume {:.10g} m^{}",
                  o.output.string(), elements.positions.size(), Dim, h[0], o.particles_per_cell,
                  o.domains.empty() ? "" : ", " + o.domains + " CPDI domains", total, Dim);
  if (const auto exact = region->exact_volume())
    text += fmt::format(" (body: {:.10g} m^{}, relative difference {:.3g})", *exact, Dim, total / *exact - 1);
  if (!certificate.empty()) {
    certificate.pop_back();  // the caller ends the text
    text += certificate;
  }
  return text;
}

/// All bodies of a scene as the simulation builds them.
template <int Dim>
std::string write_scene(const ParticlesOptions& o, const SceneDescription& scene) {
  const auto sim = build_simulation<Dim>(scene);
  io::PointCloud cloud;
  io::FieldArray volume{"volume", 1, {}}, body{"body", 1, {}}, id{"id", 1, {}};
  double total = 0;
  for (const auto& b : sim->bodies()) {
    const auto& p = b.particles;
    for (Index i = 0; i < p.size(); ++i) {
      push_point<Dim>(cloud.points, Vec<Dim>(p.x[i]));
      volume.values.push_back(p.volume0[i]);
      body.values.push_back(b.index);
      id.values.push_back(p.id[i]);
      total += p.volume0[i];
    }
  }
  cloud.fields = {volume, body, id};
  if (!o.domains.empty())
    for (const auto& b : sim->bodies())
      if (!has_particle_domains(b))
        throw UsageError(
            fmt::format("--domains: the scene's shape function {} has no particle domains (use gimp, "
                        "cpgimp or a cpdi_* function)",
                        scene.solver.shape_function));
  io::write_vtu(o.output, cloud);
  if (!o.domains.empty()) io::write_cells_vtu(domains_path(o.output), particle_domain_mesh(sim->bodies()));
  std::string bodies = body_summary<Dim>(*sim) + set_summary<Dim>(*sim, scene) +
                       body_certificates<Dim>(*sim, scene);  // a line per body, then CAD
                                                             // and mesh bodies' certificates
  bodies.pop_back();                                         // the caller ends the text
  return fmt::format("{}: {} particles in {} {} ({}D), volume {:.10g} m^{}\n{}", o.output.string(), cloud.size(),
                     sim->bodies().size(), sim->bodies().size() == 1 ? "body" : "bodies", Dim, total, Dim, bodies);
}

std::string run(const ParticlesOptions& o, std::ostream& err) {
  if (o.output.extension() != ".vtu") throw UsageError("-o: the output must be a .vtu file, got " + o.output.string());
  if (o.input.empty() && o.scene.empty()) throw UsageError("give an input file (mesh or image) or --scene SCENE");
  if (!o.input.empty() && o.scene.empty() && !o.spacing)
    throw UsageError("give the grid: --spacing H (cell size, m) or --scene SCENE");
  if (o.spacing && !o.scene.empty()) throw UsageError("give either --spacing or --scene, not both");
  if (o.particles_per_cell < 1 || o.particles_per_cell > max_particles_per_cell)
    throw UsageError(fmt::format("--ppc must be between 1 and {} (particles per cell per axis), got {}",
                                 max_particles_per_cell, o.particles_per_cell));
  register_modules();  // the modules' shape kinds (geometry: mesh, image), materials and sections
  std::optional<SceneDescription> scene;
  if (!o.scene.empty()) scene = load_scene(o.scene);
  if (o.input.empty()) {
    if (o.domains != "" && o.domains != "scene")
      throw UsageError("--domains " + o.domains + " applies to an input file; with a scene alone use --domains scene");
    switch (scene->dimension) {
      case 1:
        return write_scene<1>(o, *scene);
      case 2:
        return write_scene<2>(o, *scene);
      default:
        return write_scene<3>(o, *scene);
    }
  }
  if (o.domains != "" && o.domains != "lattice" && o.domains != "conforming")
    throw UsageError("--domains with an input file: lattice or conforming, got " + o.domains);

  const std::string ext = lower_extension(o.input);
  int dimension = 3;
  bool cad = false;
  ShapeDescription shape;
  if (ext == ".stl" || ext == ".obj" || ext == ".off" || ext == ".ply") {
    geometry::MeshShape mesh;
    mesh.file = o.input;
    mesh.scale = o.scale;
    mesh.section = o.section;
    dimension = o.section ? 2 : 3;
    shape = make_shape("mesh", mesh);
  } else if (ext == ".step" || ext == ".stp" || ext == ".iges" || ext == ".igs" || ext == ".brep") {
    geometry::CadShape solids;  // all of them
    solids.file = o.input;
    solids.scale = o.scale;
    shape = make_shape("cad", solids);
    cad = true;
  } else if (ext == ".msh") {
    geometry::GmshShape gmsh;  // all elements of the mesh's highest dimension
    gmsh.file = o.input;
    gmsh.scale = o.scale;
    dimension = geometry::gmsh_dimension(o.input);
    shape = make_shape("gmsh", gmsh);
  } else if (ext == ".png" || ext == ".pgm" || ext == ".vti") {
    geometry::ImageShape image;
    image.file = o.input;
    dimension = ext == ".vti" ? 3 : 2;
    if (o.pixel_size)
      image.pixel_size = {*o.pixel_size, *o.pixel_size, *o.pixel_size};
    else if (dimension == 2)
      throw UsageError("--pixel-size is required for a picture (the size of a pixel, m)");
    if (!o.threshold && !o.label) throw UsageError("an image needs --threshold T or --label L");
    image.threshold = o.threshold;
    image.label = o.label;
    shape = make_shape("image", image);
  } else {
    throw geometry::GeometryError(o.input,
                                  fmt::format("unsupported input format '{}' (meshes: .stl, .obj, .off, "
                                              ".ply; CAD: .step, .stp, .iges, .igs, .brep; Gmsh: .msh; images: .png, "
                                              ".pgm, .vti)",
                                              ext));
  }
  if (dimension == 2) return write_input<2>(o, shape, scene, err);
  std::string text = write_input<3>(o, shape, scene, err);
  if (cad)  // the solids a scene can choose by `solid: INDEX` or `part: NAME`
    text += fmt::format("\n  solids of {}: {}", o.input, fmt::join(geometry::cad_solid_labels(o.input), ", "));
  return text;
}

}  // namespace

int particles_command(const ParticlesOptions& options, std::ostream& out, std::ostream& err) {
  try {
    out << run(options, err) << '\n';
    return exit_ok;
  } catch (const UsageError& e) {
    err << "error: mpm particles: " << e.what() << '\n';
  } catch (const geometry::GeometryError& e) {
    err << "error: " << e.what() << '\n';
  } catch (const SceneError& e) {
    err << "error: " << e.what() << '\n';
  } catch (const std::exception& e) {
    err << "error: " << e.what() << '\n';
    return exit_runtime_error;
  }
  return exit_bad_input;
}

}  // namespace mpm::app
