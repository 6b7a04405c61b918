// Conforming CPDI-T3 domains: CGAL constrained Delaunay triangulation of the boundary loops, refined by
// Delaunay_mesher_2 (Ruppert/Shewchuk refinement: angles >= 20.6 degrees, edges <= the size bound).
#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Delaunay_mesh_size_criteria_2.h>
#include <CGAL/Delaunay_mesher_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <fmt/format.h>

#include <cmath>

#include "mpm/geometry/conforming_domains.hpp"
#include "mpm/geometry/polygon_region.hpp"

namespace mpm::geometry {

namespace {
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb = CGAL::Triangulation_vertex_base_2<K>;
using Fb = CGAL::Delaunay_mesh_face_base_2<K>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<K, Tds>;
using Criteria = CGAL::Delaunay_mesh_size_criteria_2<Cdt>;
}  // namespace

CpdiParticles<2> conforming_triangles(const ShapeDescription& shape, Real spacing, std::vector<std::string>* warnings) {
  const auto region = make_region<2>(shape, warnings);
  const auto loops = polygon_loops(*region);
  if (loops.empty())
    throw GeometryError(shape_file(shape),
                        fmt::format("conforming CPDI domains need a polygonal 2D shape (box, polygon or "
                                    "mesh section), not a {}",
                                    shape.kind));
  Cdt cdt;
  for (const auto& loop : loops) {
    std::vector<Cdt::Vertex_handle> v;
    for (const auto& p : loop) v.push_back(cdt.insert(K::Point_2(p[0], p[1])));
    for (std::size_t k = 0; k < v.size(); ++k)
      if (v[k] != v[(k + 1) % v.size()]) cdt.insert_constraint(v[k], v[(k + 1) % v.size()]);
  }
  // Shape bound 0.125 = sin^2 of the smallest angle (20.6 degrees); size bound = the longest edge.
  CGAL::refine_Delaunay_mesh_2(cdt, Criteria(0.125, std::sqrt(2.0) * spacing));

  CpdiParticles<2> out;
  for (const auto f : cdt.finite_face_handles()) {
    if (!f->is_in_domain()) continue;
    CornerSet<2> corners;
    corners.fill(VecU<2>::Zero());
    Vec<2> centroid = Vec<2>::Zero();
    for (int k = 0; k < 3; ++k) {
      const K::Point_2& p = f->vertex(k)->point();
      corners[k] = VecU<2>(p.x(), p.y());
      centroid += Vec<2>(corners[k]);
    }
    centroid /= 3;
    if (!region->contains(centroid)) continue;        // a hole (inner loop) was meshed too
    const Real area = CpdiTriangle::volume(corners);  // CGAL's finite faces are counter-clockwise
    for (int k = 0; k < 3; ++k) corners[k] -= VecU<2>(centroid);
    out.positions.push_back(centroid);
    out.volumes.push_back(area);
    out.offsets.push_back(corners);
  }
  return out;
}

}  // namespace mpm::geometry
