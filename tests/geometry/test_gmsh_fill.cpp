// Gmsh volume gmsh_meshes (geometry/gmsh_body.hpp, `gmsh: FILE`): hand-written .msh files of format 2.2 and 4.1
// (tests/data/gmsh_meshes/gmsh_*.msh) become one particle per element at its centroid with its exact volume; physical
// groups choose the elements; the mesh's exact properties (the certificate's source) equal an independent
// decomposition into tetrahedra; bad files are refused naming the file, the line and the element.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <numeric>

#include "mpm/geometry/geometry_error.hpp"
#include "mpm/geometry/gmsh_body.hpp"
#include "mpm/geometry/gmsh_mesh.hpp"
#include "mpm/geometry/mass_properties.hpp"

namespace fs = std::filesystem;
using namespace mpm;
using namespace mpm::geometry;

namespace {

const fs::path gmsh_meshes = fs::path(MPM_SOURCE_DIR) / "tests" / "data" / "meshes";

GmshShape gmsh_shape(const std::string& name, std::vector<std::string> groups = {}) {
  GmshShape shape;
  shape.file = (gmsh_meshes / name).string();
  shape.groups = std::move(groups);
  return shape;
}

/// Moments of a planar-faced hexahedron (Gmsh order) as 6 tetrahedra around the diagonal 0-6 (exact for planar faces).
void add_hexahedron_tets(RawMoments& m, const std::array<Vec<3>, 8>& x) {
  const int tets[6][4] = {{0, 1, 2, 6}, {0, 2, 3, 6}, {0, 3, 7, 6}, {0, 7, 4, 6}, {0, 4, 5, 6}, {0, 5, 1, 6}};
  for (const auto& t : tets) m.add_tetrahedron(x[t[0]], x[t[1]], x[t[2]], x[t[3]]);
}

std::string gmsh_error_of(const GmshShape& shape, int dimension = 3) {
  try {
    gmsh_particles(shape, dimension);
  } catch (const GeometryError& e) {
    return e.what();
  }
  return "";
}

void expect_same_gmsh(const MassProperties& a, const MassProperties& b, double tolerance) {
  EXPECT_NEAR(a.volume, b.volume, tolerance);
  EXPECT_LT((a.centroid - b.centroid).norm(), tolerance);
  EXPECT_LT((a.inertia - b.inertia).cwiseAbs().maxCoeff(), tolerance) << a.inertia << "\n\n" << b.inertia;
}

}  // namespace

// Format 4.1: a unit hexahedron, a prism (right triangle of legs 1, height 1) and a tetrahedron (legs 1), one
// particle each with volume 1, 1/2, 1/6 and the centroid (1/2, 1/2, 1/2), (1/3, 1/3, 3/2), (5/4, 1/4, 1/4); the
// surface triangle of group 'skin' is not a particle. Exact to round-off (1e-14).
TEST(GmshFill, Format41ElementsAndProperties) {
  const GmshParticles p = gmsh_particles(gmsh_shape("gmsh_blocks_41.msh"), 3);
  ASSERT_EQ(p.positions.size(), 3u);
  EXPECT_NEAR(p.volumes[0], 1.0, 1e-14);
  EXPECT_NEAR(p.volumes[1], 0.5, 1e-14);
  EXPECT_NEAR(p.volumes[2], 1.0 / 6, 1e-14);
  EXPECT_LT((p.positions[0] - Vec<3>(0.5, 0.5, 0.5)).norm(), 1e-14);
  EXPECT_LT((p.positions[1] - Vec<3>(1.0 / 3, 1.0 / 3, 1.5)).norm(), 1e-14);
  EXPECT_LT((p.positions[2] - Vec<3>(1.25, 0.25, 0.25)).norm(), 1e-14);
  // the exact properties against tetrahedra: the hexahedron's six, the prism's three, the tetrahedron
  RawMoments m;
  add_hexahedron_tets(m, {Vec<3>(0, 0, 0), Vec<3>(1, 0, 0), Vec<3>(1, 1, 0), Vec<3>(0, 1, 0), Vec<3>(0, 0, 1),
                          Vec<3>(1, 0, 1), Vec<3>(1, 1, 1), Vec<3>(0, 1, 1)});
  m.add_tetrahedron(Vec<3>(0, 0, 1), Vec<3>(1, 0, 1), Vec<3>(0, 1, 1), Vec<3>(0, 0, 2));
  m.add_tetrahedron(Vec<3>(1, 0, 1), Vec<3>(0, 1, 1), Vec<3>(0, 0, 2), Vec<3>(1, 0, 2));
  m.add_tetrahedron(Vec<3>(0, 1, 1), Vec<3>(0, 0, 2), Vec<3>(1, 0, 2), Vec<3>(0, 1, 2));
  m.add_tetrahedron(Vec<3>(1, 0, 0), Vec<3>(2, 0, 0), Vec<3>(1, 1, 0), Vec<3>(1, 0, 1));
  MassProperties tets = m.central();
  tets.volume = std::abs(tets.volume);
  EXPECT_NEAR(p.exact.volume, 5.0 / 3, 1e-14);
  expect_same_gmsh(p.exact, tets, 1e-13);
  // the certificate: volume and centroid exact; the inertia misses the elements' own
  const FidelityCertificate c = certify(p.exact, particle_properties(p.positions, p.volumes), "mesh");
  EXPECT_NEAR(c.volume_error, 0, 1e-14);
  EXPECT_NEAR(c.centroid_error, 0, 1e-14);
  EXPECT_GT(c.inertia_error, 0.1);
}

// Format 2.2 with physical groups: 'steel' (a unit cube) and 'rubber' (a hexahedron with a sloped face, volume 3/4);
// the trilinear hexahedron's centroid by quadrature equals the tetrahedra's (1e-14).
TEST(GmshFill, Format22GroupsByName) {
  EXPECT_EQ(gmsh_group_names((gmsh_meshes / "gmsh_two_blocks_22.msh").string(), 3),
            (std::vector<std::string>{"steel", "rubber"}));
  const GmshParticles steel = gmsh_particles(gmsh_shape("gmsh_two_blocks_22.msh", {"steel"}), 3);
  ASSERT_EQ(steel.positions.size(), 1u);
  EXPECT_NEAR(steel.volumes[0], 1.0, 1e-14);
  const GmshParticles rubber = gmsh_particles(gmsh_shape("gmsh_two_blocks_22.msh", {"rubber"}), 3);
  ASSERT_EQ(rubber.positions.size(), 1u);
  EXPECT_NEAR(rubber.volumes[0], 0.75, 1e-14);
  RawMoments m;
  add_hexahedron_tets(m, {Vec<3>(1, 0, 0), Vec<3>(2, 0, 0), Vec<3>(2, 1, 0), Vec<3>(1, 1, 0), Vec<3>(1, 0, 1),
                          Vec<3>(1.5, 0, 1), Vec<3>(1.5, 1, 1), Vec<3>(1, 1, 1)});
  expect_same_gmsh(rubber.exact, m.central(), 1e-14);
  EXPECT_LT((rubber.positions[0] - m.central().centroid).norm(), 1e-14);
  const GmshParticles both = gmsh_particles(gmsh_shape("gmsh_two_blocks_22.msh", {"steel", "rubber"}), 3);
  EXPECT_EQ(both.positions.size(), 2u);
  EXPECT_NEAR(both.exact.volume, 1.75, 1e-14);
}

// 2D: a quadrangle with a slanted side (area 9/8) and a triangle (area 1/2); the line element is not a particle.
TEST(GmshFill, TwoDimensionalElements) {
  EXPECT_EQ(gmsh_dimension((gmsh_meshes / "gmsh_plate_22.msh").string()), 2);
  const GmshParticles p = gmsh_particles(gmsh_shape("gmsh_plate_22.msh", {"plate"}), 2);
  ASSERT_EQ(p.positions.size(), 2u);
  EXPECT_NEAR(p.volumes[0], 1.125, 1e-14);
  EXPECT_NEAR(p.volumes[1], 0.5, 1e-14);
  EXPECT_LT((p.positions[1] - Vec<3>((1 + 2 + 1.25) / 3.0, 1.0 / 3, 0)).norm(), 1e-14);
}

// Bad files and choices, each with the file, the line or the group, and what is wrong.
TEST(GmshFill, BadInputRefused) {
  EXPECT_NE(gmsh_error_of(gmsh_shape("gmsh_unknown_type.msh"))
                .find("gmsh_unknown_type.msh: line 14: element 2 has the unknown "
                      "element type 99"),
            std::string::npos);
  EXPECT_NE(gmsh_error_of(gmsh_shape("gmsh_second_order.msh"))
                .find("line 19: element 1 has element type 11 (10 nodes), which "
                      "is not read"),
            std::string::npos);
  EXPECT_NE(gmsh_error_of(gmsh_shape("gmsh_blocks_41.msh", {"empty"}))
                .find("the physical group 'empty' has no 3D element (it is "
                      "empty)"),
            std::string::npos);
  EXPECT_NE(gmsh_error_of(gmsh_shape("gmsh_blocks_41.msh", {"bolt"}))
                .find("no 3D physical group named 'bolt' in the file; its "
                      "3D groups: 'block', 'empty'"),
            std::string::npos)
      << gmsh_error_of(gmsh_shape("gmsh_blocks_41.msh", {"bolt"}));
  EXPECT_NE(gmsh_error_of(gmsh_shape("gmsh_plate_22.msh")).find("the mesh has no 3D element"), std::string::npos);
  // a binary file, an old format, a truncated file
  const fs::path dir = fs::temp_directory_path() / "mpm_gmsh_bad";
  fs::create_directories(dir);
  std::ofstream(dir / "binary.msh") << "$MeshFormat\n4.1 1 8\n";
  GmshShape binary;
  binary.file = (dir / "binary.msh").string();
  EXPECT_NE(gmsh_error_of(binary).find("line 2: binary .msh files are not read"), std::string::npos)
      << gmsh_error_of(binary);
  std::ofstream(dir / "old.msh") << "$MeshFormat\n2.0 0 8\n$EndMeshFormat\n";
  GmshShape old;
  old.file = (dir / "old.msh").string();
  EXPECT_NE(gmsh_error_of(old).find("Gmsh format 2.0 is not read"), std::string::npos) << gmsh_error_of(old);
  std::ofstream(dir / "truncated.msh") << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n3\n1 0 0 0\n2 1 0";
  GmshShape truncated;
  truncated.file = (dir / "truncated.msh").string();
  EXPECT_NE(gmsh_error_of(truncated).find("line 7: the file ends where a node coordinate was expected"),
            std::string::npos)
      << gmsh_error_of(truncated);
  fs::remove_all(dir);
}
