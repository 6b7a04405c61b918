#include "mpm/geometry/mesh_region.hpp"

#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_slicer.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <fmt/format.h>

#include <iterator>
#include <optional>

#include "known_properties.hpp"
#include "mpm/geometry/geometry_error.hpp"
#include "mpm/geometry/polygon_region.hpp"
#include "surface_mesh_io.hpp"

namespace mpm::geometry {

namespace {

using detail::Kernel;
using detail::Point3;
using detail::SurfaceMesh;
namespace PMP = CGAL::Polygon_mesh_processing;

/// Inside a closed triangle mesh: CGAL's ray-shooting Side_of_triangle_mesh on an AABB tree (built on the
/// first query). Mesh and test are shared with the process's cache of read meshes (surface_mesh_cache.cpp).
class MeshRegion : public Region<3>, public detail::KnownProperties {
 public:
  explicit MeshRegion(detail::ClosedSurface surface)
      : mesh_(std::move(surface.mesh)), side_(std::move(surface.inside)), volume_(PMP::volume(*mesh_)) {
    const CGAL::Bbox_3 b = PMP::bbox(*mesh_);
    bounds_.lo = Vec<3>(b.xmin(), b.ymin(), b.zmin());
    bounds_.hi = Vec<3>(b.xmax(), b.ymax(), b.zmax());
  }
  bool contains(const Vec<3>& x) const override {
    if ((x.array() < bounds_.lo.array()).any() || (x.array() > bounds_.hi.array()).any()) return false;
    return (*side_)(Point3(x[0], x[1], x[2])) != CGAL::ON_UNBOUNDED_SIDE;
  }
  Box<3> bounds() const override { return bounds_; }
  std::optional<Real> exact_volume() const override { return volume_; }
  const SurfaceMesh& mesh() const { return *mesh_; }
  MassProperties mass_properties() const override {
    std::vector<Vec<3>> points;
    points.reserve(mesh_->number_of_vertices());
    for (const auto v : mesh_->vertices()) {
      const Point3& p = mesh_->point(v);
      points.emplace_back(p.x(), p.y(), p.z());
    }
    std::vector<std::array<std::size_t, 3>> triangles;
    triangles.reserve(mesh_->number_of_faces());
    for (const auto f : mesh_->faces()) {
      std::array<std::size_t, 3> t{};
      int k = 0;
      for (const auto v : CGAL::vertices_around_face(mesh_->halfedge(f), *mesh_)) t[k++ % 3] = std::size_t(v);
      triangles.push_back(t);
    }
    return mesh_properties(points, triangles);
  }
  std::string properties_source() const override { return "surface mesh (exact integrals)"; }

 private:
  std::shared_ptr<const SurfaceMesh> mesh_;  // before side_, which refers to it
  std::shared_ptr<const detail::InsideTest> side_;
  Box<3> bounds_;
  Real volume_;
};

}  // namespace

std::unique_ptr<Region<3>> detail::surface_region(SurfaceMesh mesh) {
  return std::make_unique<MeshRegion>(detail::ClosedSurface::of(std::move(mesh)));
}

std::optional<SourceProperties> exact_properties(const Region<3>& region) {
  const auto* known = dynamic_cast<const detail::KnownProperties*>(&region);
  if (!known) return std::nullopt;
  return SourceProperties{known->mass_properties(), known->properties_source()};
}

const SurfaceMesh* detail::surface_of(const Region<3>& region) {
  const auto* mesh = dynamic_cast<const MeshRegion*>(&region);
  return mesh ? &mesh->mesh() : nullptr;
}

std::unique_ptr<Region<3>> make_mesh_region(const MeshShape& shape, std::vector<std::string>* warnings,
                                            MeshSummary* summary) {
  auto region = std::make_unique<MeshRegion>(detail::shared_surface_mesh(shape, warnings));
  if (summary) {
    summary->vertices = region->mesh().number_of_vertices();
    summary->triangles = region->mesh().number_of_faces();
    summary->volume = *region->exact_volume();
  }
  return region;
}

std::unique_ptr<Region<2>> make_mesh_section(const MeshShape& shape, std::vector<std::string>* warnings) {
  const detail::ClosedSurface shared = detail::shared_surface_mesh(shape, warnings);
  const SurfaceMesh& mesh = *shared.mesh;
  const double z = shape.section.value_or(0.0);
  const CGAL::Bbox_3 b = PMP::bbox(mesh);
  CGAL::Polygon_mesh_slicer<SurfaceMesh, Kernel> slicer(mesh);
  std::vector<std::vector<Point3>> polylines;
  slicer(Kernel::Plane_3(0, 0, 1, -z), std::back_inserter(polylines));
  if (polylines.empty())
    throw GeometryError(shape.file, fmt::format("the plane z = {:.6g} m misses the mesh (it spans z in [{:.6g}, "
                                                "{:.6g}] m after the transform)",
                                                z, b.zmin(), b.zmax()));
  std::vector<PolygonRegion::Loop> loops;
  for (const auto& line : polylines) {
    if (line.size() < 4 || line.front() != line.back())
      throw GeometryError(shape.file, fmt::format("the section by the plane z = {:.6g} m is not a closed curve (the "
                                                  "plane runs along a face or an edge of the mesh; move it slightly)",
                                                  z));
    PolygonRegion::Loop loop;
    for (std::size_t k = 0; k + 1 < line.size(); ++k) loop.emplace_back(line[k].x(), line[k].y());
    loops.push_back(std::move(loop));
  }
  return std::make_unique<PolygonRegion>(std::move(loops));
}

}  // namespace mpm::geometry
