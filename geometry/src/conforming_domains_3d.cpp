// Conforming CPDI-Tet4 domains: CGAL Mesh_3 of the closed surface, with its sharp edges (dihedral
// angle further than `feature_angle` from flat) protected so that creases and flat faces are kept.
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_criteria_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/Polyhedral_mesh_domain_with_features_3.h>
#include <CGAL/make_mesh_3.h>
#include <fmt/format.h>

#include "mpm/geometry/conforming_domains.hpp"
#include "surface_mesh_io.hpp"

namespace mpm::geometry {

namespace {
using detail::Kernel;
using detail::SurfaceMesh;
using Domain = CGAL::Polyhedral_mesh_domain_with_features_3<Kernel, SurfaceMesh>;
using Tr = CGAL::Mesh_triangulation_3<Domain, CGAL::Default, CGAL::Sequential_tag>::type;
using C3t3 = CGAL::Mesh_complex_3_in_triangulation_3<Tr, Domain::Corner_index, Domain::Curve_index>;
using Criteria = CGAL::Mesh_criteria_3<Tr>;
}  // namespace

CpdiParticles<3> conforming_tetrahedra(const ShapeDescription& shape, Real spacing,
                                       std::vector<std::string>* warnings) {
  SurfaceMesh surface;
  if (shape.type == "mesh")
    surface = detail::load_surface_mesh(shape, warnings);
  else if (shape.type == "box")
    surface = detail::box_mesh(shape.min, shape.max);
  else
    throw GeometryError(shape.file, fmt::format("conforming CPDI domains in 3D need a closed surface (a mesh or a "
                                                "box), not a {}",
                                                shape.type));
  Domain domain(surface);
  domain.detect_features(30);  // creases sharper than 30 degrees are protected
  namespace p = CGAL::parameters;
  const Criteria criteria(p::edge_size = spacing, p::facet_angle = 25, p::facet_size = spacing,
                          p::facet_distance = spacing / 10, p::cell_radius_edge_ratio = 3, p::cell_size = spacing);
  const C3t3 c3t3 = CGAL::make_mesh_3<C3t3>(domain, criteria, p::no_perturb(), p::no_exude());

  CpdiParticles<3> out;
  const auto& tr = c3t3.triangulation();
  const auto point = tr.geom_traits().construct_point_3_object();
  for (auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c) {
    CornerSet<3> corners;
    Vec<3> centroid = Vec<3>::Zero();
    for (int k = 0; k < 4; ++k) {
      const auto p = point(tr.point(c, k));
      corners[k] = VecU<3>(p.x(), p.y(), p.z());
      centroid += Vec<3>(corners[k]);
    }
    centroid /= 4;
    if (CpdiTetrahedron::volume(corners) < 0) std::swap(corners[2], corners[3]);  // right-handed
    const Real volume = CpdiTetrahedron::volume(corners);
    for (int k = 0; k < 4; ++k) corners[k] -= VecU<3>(centroid);
    out.positions.push_back(centroid);
    out.volumes.push_back(volume);
    out.offsets.push_back(corners);
  }
  return out;
}

}  // namespace mpm::geometry
