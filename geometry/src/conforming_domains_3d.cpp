// Conforming CPDI-Tet4 domains: CGAL Mesh_3 of the closed surface (a polyhedral domain with features),
// every crease of the input protected so that the tetrahedra fill exactly the polyhedron.
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_criteria_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polyhedral_mesh_domain_with_features_3.h>
#include <CGAL/Random.h>
#include <CGAL/make_mesh_3.h>
#include <fmt/format.h>

#include <cmath>
#include <numeric>

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

/// One particle per tetrahedron of the complex: centroid, volume, right-handed corners as offsets.
CpdiParticles<3> elements(const C3t3& c3t3) {
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
  // Sliver exudation leaves a few flat elements whose four corners lie on one flat input facet (volume
  // ~1e-24 m^3 where the mean is 1e-5): they hold no volume and their CPDI gradient weights ~ 1/V would
  // blow up, so they are dropped.
  const Real mean =
      std::accumulate(out.volumes.begin(), out.volumes.end(), 0.0) / std::max<Real>(1, out.volumes.size());
  CpdiParticles<3> kept;
  for (std::size_t k = 0; k < out.volumes.size(); ++k)
    if (out.volumes[k] > 1e-12 * mean) {
      kept.positions.push_back(out.positions[k]);
      kept.volumes.push_back(out.volumes[k]);
      kept.offsets.push_back(out.offsets[k]);
    }
  return kept;
}

}  // namespace

CpdiParticles<3> conforming_tetrahedra(const ShapeDescription& shape, Real spacing,
                                       std::vector<std::string>* warnings) {
  const std::string file = shape_file(shape);
  const auto region = make_region<3>(shape, warnings);
  SurfaceMesh surface;
  if (const SurfaceMesh* mesh = detail::surface_of(*region))
    surface = *mesh;
  else if (const auto* box = dynamic_cast<const BoxRegion<3>*>(region.get()))
    surface = detail::box_mesh(box->bounds());
  else
    throw GeometryError(file, fmt::format("conforming CPDI domains in 3D need a closed surface (a mesh or a "
                                          "box), not a {}",
                                          shape.kind));
  // Every crease whose faces' normals differ by more than 1 degree is a protected feature, so that the
  // tetrahedra's boundary facets lie on the input facets and the volumes sum to the mesh volume. Mesh_3 can
  // fail on some inputs (curves meeting at small angles); other protection sizes are tried, and at last
  // only the creases sharper than 30 degrees (the volume is then approximate, with a warning).
  const double mesh_volume = CGAL::Polygon_mesh_processing::volume(surface);
  namespace p = CGAL::parameters;
  const struct { double feature_angle, edge_size; } attempts[] = {{1, 0.5}, {1, 1.0}, {1, 0.3}, {1, 0.75}, {30, 1.0}};
  std::string failure;
  for (const auto& attempt : attempts) {
    try {
      // Mesh_3's perturbation draws from CGAL's default random generator, seeded from the clock: seed it.
      // The elements still vary slightly from run to run (the sphere of test_conforming_domains: 11119 to
      // 11124 tetrahedra, each run exact in volume): Mesh_3 orders some handles by memory address, so the
      // result follows address-space randomisation; with it off (`setarch -R`) the count is fixed.
      CGAL::get_default_random() = CGAL::Random(0);
      Domain domain(surface);
      domain.detect_features(attempt.feature_angle);
      const Criteria criteria(p::edge_size = attempt.edge_size * spacing, p::facet_angle = 25, p::facet_size = spacing,
                              p::facet_distance = spacing / 10, p::cell_radius_edge_ratio = 3, p::cell_size = spacing);
      // Perturbation and exudation remove the slivers (flat tetrahedra of near-zero volume, whose CPDI
      // gradient weights ~ 1/V blow up the first step).
      const C3t3 c3t3 = CGAL::make_mesh_3<C3t3>(domain, criteria, p::perturb(), p::exude());
      CpdiParticles<3> out = elements(c3t3);
      const double sum = std::accumulate(out.volumes.begin(), out.volumes.end(), 0.0);
      if (std::abs(sum / mesh_volume - 1) > 1e-10 && warnings)
        warnings->push_back(
            fmt::format("{}: the conforming tetrahedra approximate the surface: their volumes sum to "
                        "{:.6g} m^3, the mesh encloses {:.6g} m^3 ({:+.3g}%)",
                        file.empty() ? "box" : file, sum, mesh_volume, 100 * (sum / mesh_volume - 1)));
      return out;
    } catch (const CGAL::Failure_exception& e) {
      failure = e.message();
    }
  }
  throw GeometryError(file, "CGAL Mesh_3 could not mesh the surface into tetrahedra: " + failure);
}

}  // namespace mpm::geometry
