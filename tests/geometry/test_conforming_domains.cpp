// Conforming CPDI domains (geometry/conforming_domains.hpp): CGAL triangle meshes of polygons (CPDI-T3)
// and Mesh_3 tetrahedra of closed surfaces (CPDI-Tet4). Element volumes must be positive (counter-clockwise
// / right-handed corners) and sum to the body's volume to 1e-10 relative.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numeric>

#include "mpm/body_shape/primitive_shapes.hpp"
#include "mpm/geometry/conforming_domains.hpp"
#include "mpm/geometry/file_shapes.hpp"
#include "mpm/geometry/region.hpp"
#include "mpm/geometry/register.hpp"
#include "test_meshes.hpp"

namespace fs = std::filesystem;
using namespace mpm;
using namespace mpm::geometry;

namespace {

template <int Dim>
double total(const CpdiParticles<Dim>& p) {
  return std::accumulate(p.volumes.begin(), p.volumes.end(), 0.0);
}

/// Every element has the volume of its corners, a positive one, and its centroid at the particle; in 3D
/// no sliver: volume / (longest edge)^3 >= 1e-3 (a regular tetrahedron has 0.118, the worst elements here
/// about 1.6e-3; Mesh_3 without sliver perturbation and exudation left elements of 1e-17 that blew up the
/// CPDI gradients at the first step, and flat elements on a facet, which are dropped).
template <class Element, int Dim>
void check_elements(const CpdiParticles<Dim>& p, int corners) {
  for (std::size_t k = 0; k < p.positions.size(); ++k) {
    CornerSet<Dim> c = p.offsets[k];
    VecU<Dim> mean = VecU<Dim>::Zero();
    for (int i = 0; i < corners; ++i) mean += c[i];
    ASSERT_LT(mean.norm(), 1e-12);
    for (int i = 0; i < corners; ++i) c[i] += VecU<Dim>(p.positions[k]);
    ASSERT_GT(Element::volume(c), 0) << "element " << k;
    ASSERT_NEAR(Element::volume(c), p.volumes[k], 1e-15);
    if constexpr (Dim == 3) {
      double longest = 0;
      for (int i = 0; i < 4; ++i)
        for (int j = i + 1; j < 4; ++j) longest = std::max(longest, (c[i] - c[j]).norm());
      ASSERT_GE(p.volumes[k] / std::pow(longest, 3), 1e-3) << "sliver " << k;
    }
  }
}

}  // namespace

// A polygon with a re-entrant corner and a slanted edge, and a box: T3 areas sum to the shoelace area.
TEST(ConformingDomains, TrianglesOfAPolygonSumToItsArea) {
  PolygonShape polygon;
  polygon.vertices = {{0.1, 0.1}, {0.9, 0.2}, {0.8, 0.6}, {0.45, 0.45}, {0.3, 0.9}, {0.1, 0.7}};
  const auto& v = polygon.vertices;
  double shoelace = 0;
  for (std::size_t i = 0, j = v.size() - 1; i < v.size(); j = i++)
    shoelace += (v[j][0] * v[i][1] - v[i][0] * v[j][1]) / 2;
  const ShapeDescription s = make_shape("polygon", polygon);
  const auto p = conforming_triangles(s, 0.02, nullptr);
  EXPECT_NEAR(total(p) / shoelace, 1, 1e-10);
  check_elements<CpdiTriangle>(p, 3);
  const auto region = make_region<2>(s);
  for (const auto& x : p.positions) EXPECT_TRUE(region->contains(x));
  // About two triangles per (0.02 m)^2 sub-cell.
  EXPECT_GT(p.positions.size(), shoelace / (0.02 * 0.02));
  EXPECT_LT(p.positions.size(), 4 * shoelace / (0.02 * 0.02));

  const ShapeDescription box = make_shape("box", BoxShape{{0.2, 0.3, 0}, {0.7, 0.5, 0}});
  EXPECT_NEAR(total(conforming_triangles(box, 0.01, nullptr)) / 0.1, 1, 1e-10);

  const ShapeDescription disk = make_shape("disk", BallShape{{0.5, 0.5, 0}, 0.2});
  EXPECT_THROW(conforming_triangles(disk, 0.01, nullptr), GeometryError);
}

// Tetrahedra of a cube mesh (sharp edges protected, flat faces) and of a box: volume 1e-10 relative.
TEST(ConformingDomains, TetrahedraOfACubeSumToItsVolume) {
  const fs::path dir = fs::temp_directory_path() / ("mpm_geometry_tet_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  mpm::test::write_off(dir / "cube.off", mpm::test::cube_mesh());
  mpm::geometry::register_module();  // the mesh kind
  MeshShape mesh;
  mesh.file = (dir / "cube.off").string();
  mesh.scale = 0.5;
  mesh.rotation = {0, 0, 30};
  const auto p = conforming_tetrahedra(make_shape("mesh", mesh), 0.1, nullptr);
  std::printf("cube: %zu tetrahedra, volume %.17g\n", p.positions.size(), total(p));
  EXPECT_NEAR(total(p) / 0.125, 1, 1e-10);
  check_elements<CpdiTetrahedron>(p, 4);

  // Curved surfaces: every crease is protected, so the tetrahedra fill the polyhedron exactly.
  const struct {
    std::string name;
    mpm::test::TriMesh mesh;
  } curved[] = {{"torus.off", mpm::test::torus_mesh(0.3, 0.12, {0, 0, 0}, 24, 12)},
                {"sphere.off", mpm::test::sphere_mesh(0.3, {0, 0, 0}, 12, 24)}};
  for (const auto& c : curved) {
    mpm::test::write_off(dir / c.name, c.mesh);
    mesh.file = (dir / c.name).string();
    mesh.scale = 1;
    mesh.rotation = {0, 0, 0};
    std::vector<std::string> warnings;
    const auto t = conforming_tetrahedra(make_shape("mesh", mesh), 0.05, &warnings);
    const double exact = mpm::test::polyhedron_volume(c.mesh);
    std::printf("%s: %zu tetrahedra, relative volume difference %.3g\n", c.name.c_str(), t.positions.size(),
                total(t) / exact - 1);
#ifdef MPM_SANITIZE
    // CGAL Mesh_3's result depends on where its cells are allocated (it orders handles by address: even the
    // release build gives 11119 to 11124 tetrahedra for the sphere from run to run, a fixed count with address
    // randomisation off). ASan's allocator places them elsewhere, and there the sphere's protected creases do
    // not all survive: 3789 tetrahedra, -1.63%. Then the approximation must be the one the warning states.
    if (!warnings.empty()) {
      ASSERT_EQ(warnings.size(), 1u);
      EXPECT_NE(warnings[0].find(fmt::format("({:+.3g}%)", 100 * (total(t) / exact - 1))), std::string::npos)
          << warnings[0];
      check_elements<CpdiTetrahedron>(t, 4);
      continue;
    }
#endif
    EXPECT_NEAR(total(t) / exact, 1, 1e-10) << c.name;
    EXPECT_TRUE(warnings.empty()) << warnings[0];
    check_elements<CpdiTetrahedron>(t, 4);
  }

  const ShapeDescription box = make_shape("box", BoxShape{{0, 0, 0}, {0.3, 0.2, 0.1}});
  EXPECT_NEAR(total(conforming_tetrahedra(box, 0.05, nullptr)) / 0.006, 1, 1e-10);
  fs::remove_all(dir);
}
