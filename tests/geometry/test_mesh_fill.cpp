// CAD meshes to particles (geometry/mesh_region.hpp): every format, the volume of the particles against
// the exact volume of the polyhedron, the lattice fill against the analytic volume, rotations, sections,
// and every bad-mesh error. Meshes are generated here (test_meshes.hpp), so the reference volumes are exact.
#include <gtest/gtest.h>
#include <unistd.h>

#include <Eigen/Geometry>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numeric>

#include "mpm/geometry/geometry_error.hpp"
#include "mpm/geometry/mesh_region.hpp"
#include "mpm/geometry/register.hpp"
#include "mpm/geometry/shape_filler.hpp"
#include "test_meshes.hpp"

namespace fs = std::filesystem;
using namespace mpm;
using namespace mpm::geometry;
using mpm::test::TriMesh;

namespace {

fs::path mesh_scratch() {
  const fs::path dir = fs::temp_directory_path() / ("mpm_geometry_mesh_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  return dir;
}

ShapeDescription mesh_shape(const fs::path& file) {
  mpm::geometry::register_module();  // the mesh kind
  MeshShape mesh;
  mesh.file = file.string();
  return make_shape("mesh", mesh);
}

GridGeometry<3> grid3(double lo, double hi, double h) {
  const int n = static_cast<int>(std::lround((hi - lo) / h));
  return GridGeometry<3>(Vec<3>::Constant(lo), Vec<3>::Constant(h), {n, n, n});
}

double sum(const ParticleSeeds<3>& s) { return s.volume * static_cast<double>(s.positions.size()); }

/// The error message of filling `shape`, or "" when it does not throw.
std::string fill_error(const ShapeDescription& shape, const GridGeometry<3>& g) {
  try {
    fill_shape<3>(shape, g, {2, 2, 2}, nullptr);
  } catch (const GeometryError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

// The particle volumes sum to the exact polyhedron volume (1e-12 relative, round-off only), and the
// plain lattice count x sub-cell volume is within 2% of it at the stated spacing (the lattice error is
// of the order of surface area x spacing / volume).
TEST(MeshFill, SphereTorusCubeVolumesInEveryFormat) {
  const fs::path dir = mesh_scratch();
  struct Case {
    std::string name;
    TriMesh mesh;
    void (*write)(const fs::path&, const TriMesh&);
    double h;  // cell size, 2 particles per cell per axis
  };
  const std::vector<Case> cases{
      {"cube.off", mpm::test::cube_mesh(), mpm::test::write_off, 0.05},
      {"sphere.stl", mpm::test::sphere_mesh(0.4, {0.5, 0.5, 0.5}, 24, 48), mpm::test::write_stl_ascii, 0.04},
      {"torus.obj", mpm::test::torus_mesh(0.3, 0.12, {0.5, 0.5, 0.5}, 48, 24), mpm::test::write_obj, 0.02},
      {"sphere.ply", mpm::test::sphere_mesh(0.3, {0.5, 0.5, 0.5}, 16, 32), mpm::test::write_ply, 0.04},
  };
  for (const auto& c : cases) {
    c.write(dir / c.name, c.mesh);
    MeshSummary summary;
    const auto region = make_mesh_region(mesh_shape(dir / c.name).as<MeshShape>(), nullptr, &summary);
    const double exact = mpm::test::polyhedron_volume(c.mesh);
    EXPECT_EQ(summary.triangles, c.mesh.triangles.size()) << c.name;
    EXPECT_NEAR(summary.volume / exact, 1, 1e-12) << c.name;
    const auto seeds = fill_shape<3>(mesh_shape(dir / c.name), grid3(-0.1, 1.1, c.h), {2, 2, 2}, nullptr);
    EXPECT_NEAR(sum(seeds) / exact, 1, 1e-12) << c.name;
    const double lattice = seeds.sub_cell_volume * static_cast<double>(seeds.positions.size());
    EXPECT_NEAR(lattice / exact, 1, 0.02) << c.name << ": " << seeds.positions.size() << " particles";
    for (const auto& x : seeds.positions) ASSERT_TRUE(region->contains(x));
  }
  fs::remove_all(dir);
}

// The unit cube on a grid whose sub-cell centres never touch a face: the count is exact (20^3 x 8).
TEST(MeshFill, CubeCountIsExact) {
  const fs::path dir = mesh_scratch();
  mpm::test::write_off(dir / "cube.off", mpm::test::cube_mesh());
  const auto seeds = fill_shape<3>(mesh_shape(dir / "cube.off"), grid3(-0.5, 1.5, 0.05), {2, 2, 2}, nullptr);
  EXPECT_EQ(seeds.positions.size(), 64000u);
  EXPECT_DOUBLE_EQ(seeds.volume, seeds.sub_cell_volume);
  fs::remove_all(dir);
}

// ASCII and binary STL give the same particles (coordinates exact in float).
TEST(MeshFill, BinaryAndAsciiStlAgree) {
  const fs::path dir = mesh_scratch();
  TriMesh m = mpm::test::sphere_mesh(0.25, {0.5, 0.5, 0.5}, 12, 24);
  // Round to float through a volatile: GCC 12.2 at -O3 (SLP vectorizer) left 3 of these 798 values
  // unrounded when written as `x = static_cast<float>(x)` in this double loop.
  for (auto& p : m.points)
    for (auto& x : p) {
      volatile float f = static_cast<float>(x);
      x = f;
    }
  mpm::test::write_stl_ascii(dir / "a.stl", m);
  mpm::test::write_stl_binary(dir / "b.stl", m);
  const auto g = grid3(0, 1, 0.05);
  const auto a = fill_shape<3>(mesh_shape(dir / "a.stl"), g, {2, 2, 2}, nullptr);
  const auto b = fill_shape<3>(mesh_shape(dir / "b.stl"), g, {2, 2, 2}, nullptr);
  ASSERT_EQ(a.positions.size(), b.positions.size());
  EXPECT_EQ(a.positions, b.positions);
  EXPECT_NEAR(sum(a) / mpm::test::polyhedron_volume(m), 1, 1e-12);
  EXPECT_NEAR(sum(b) / mpm::test::polyhedron_volume(m), 1, 1e-12);
  fs::remove_all(dir);
}

// Scale, rotation about x then y then z, translation: every particle lies in the analytically
// transformed box and the count equals the count of lattice points inside it.
TEST(MeshFill, TransformedMeshGivesTransformedParticles) {
  const fs::path dir = mesh_scratch();
  mpm::test::write_off(dir / "cube.off", mpm::test::cube_mesh());
  ShapeDescription s = mesh_shape(dir / "cube.off");
  s.as<MeshShape>().scale = 0.4;
  s.as<MeshShape>().rotation = {20, 0, 30};
  s.as<MeshShape>().translation = {0.5, 0.3, 0.2};
  const Eigen::Matrix3d R = (Eigen::AngleAxisd(30 * M_PI / 180, Eigen::Vector3d::UnitZ()) *
                             Eigen::AngleAxisd(20 * M_PI / 180, Eigen::Vector3d::UnitX()))
                                .toRotationMatrix();
  const auto local = [&](const Vec<3>& x) { return Vec<3>(R.transpose() * (x - Vec<3>(0.5, 0.3, 0.2)) / 0.4); };
  const auto g = grid3(-0.2, 1.2, 0.02);
  const auto seeds = fill_shape<3>(s, g, {2, 2, 2}, nullptr);
  for (const auto& x : seeds.positions) {
    const Vec<3> u = local(x);
    ASSERT_TRUE((u.array() >= -1e-9).all() && (u.array() <= 1 + 1e-9).all()) << x.transpose();
  }
  std::size_t expected = 0;  // lattice points of the same grid inside the analytic box
  const double hs = 0.01;
  for (int k = 0; k < 140; ++k)
    for (int j = 0; j < 140; ++j)
      for (int i = 0; i < 140; ++i) {
        const Vec<3> u = local(Vec<3>(-0.2 + hs * (i + 0.5), -0.2 + hs * (j + 0.5), -0.2 + hs * (k + 0.5)));
        expected += (u.array() >= 0).all() && (u.array() <= 1).all();
      }
  EXPECT_EQ(seeds.positions.size(), expected);
  EXPECT_NEAR(sum(seeds) / (0.4 * 0.4 * 0.4), 1, 1e-12);
  fs::remove_all(dir);
}

// A 2D body is the section of the mesh by a plane: a torus cut through its centre plane is an annulus
// of radii R - a and R + a (polygon area within 0.5% for 96 segments), a sphere cut at height z a disk.
TEST(MeshFill, SectionOfAMeshIsA2dBody) {
  const fs::path dir = mesh_scratch();
  mpm::test::write_off(dir / "torus.off", mpm::test::torus_mesh(0.3, 0.1, {0.5, 0.5, 0.0}, 96, 33));
  ShapeDescription s = mesh_shape(dir / "torus.off");
  s.as<MeshShape>().section = 0.001;
  const GridGeometry<2> g(Vec<2>::Zero(), Vec<2>::Constant(0.01), {100, 100});
  const auto seeds = fill_shape<2>(s, g, {2, 2, 1}, nullptr);
  const double annulus = M_PI * (0.4 * 0.4 - 0.2 * 0.2);
  const double area = seeds.volume * static_cast<double>(seeds.positions.size());
  EXPECT_NEAR(area / annulus, 1, 5e-3);
  EXPECT_NEAR(seeds.sub_cell_volume * static_cast<double>(seeds.positions.size()) / annulus, 1, 0.01);
  for (const auto& x : seeds.positions) {
    const double r = (x - Vec<2>(0.5, 0.5)).norm();
    ASSERT_TRUE(r > 0.195 && r < 0.405) << r;  // no particle in the hole
  }
  s.as<MeshShape>().section = 0.5;
  try {
    fill_shape<2>(s, g, {2, 2, 1}, nullptr);
    FAIL() << "a plane above the torus must be refused";
  } catch (const GeometryError& e) {
    EXPECT_NE(std::string(e.what()).find("the plane z = 0.5 m misses the mesh"), std::string::npos) << e.what();
  }
  fs::remove_all(dir);
}

// Each bad mesh gets an error naming the file and the problem; an inside-out mesh is repaired with a
// warning and gives the same particles as the right one.
TEST(MeshFill, BadMeshesAreRefusedWithTheFileAndTheProblem) {
  const fs::path dir = mesh_scratch();
  const auto g = grid3(-0.5, 2.5, 0.1);
  const auto expect_error = [&](const fs::path& file, const std::string& problem) {
    const std::string message = fill_error(mesh_shape(file), g);
    EXPECT_NE(message.find(file.string() + ": "), std::string::npos) << message;
    EXPECT_NE(message.find(problem), std::string::npos) << message;
  };
  expect_error(dir / "none.stl", "mesh file not found");
  std::ofstream(dir / "part.3ds") << "x";
  expect_error(dir / "part.3ds", "unsupported mesh format '.3ds' (supported: .stl, .obj, .off, .ply)");
  std::ofstream(dir / "empty.off");
  expect_error(dir / "empty.off", "the mesh file is empty");
  std::ofstream(dir / "garbage.off") << "OFF\n3 1 0\n0 0 zero\n";
  expect_error(dir / "garbage.off", "cannot read the OFF file (corrupt, truncated or not OFF)");

  TriMesh open = mpm::test::cube_mesh();
  open.triangles.pop_back();
  mpm::test::write_off(dir / "open.off", open);
  expect_error(dir / "open.off", "the mesh is open: 3 edges bound a single face");

  // Two cubes sharing an edge: four faces meet at that edge.
  TriMesh two = mpm::test::cube_mesh(), other = mpm::test::cube_mesh();
  for (auto& p : other.points) p = {p[0] + 1, p[1] + 1, p[2]};
  for (auto t : other.triangles) {
    for (auto& v : t) v += 8;
    two.triangles.push_back(t);
  }
  two.points.insert(two.points.end(), other.points.begin(), other.points.end());
  mpm::test::write_off(dir / "edge.off", two);
  expect_error(dir / "edge.off", "the mesh is not manifold");

  // Two overlapping cubes in one file: faces cross.
  for (std::size_t k = 8; k < two.points.size(); ++k)
    two.points[k] = {two.points[k][0] - 0.5, two.points[k][1] - 0.5, two.points[k][2] + 0.25};
  mpm::test::write_off(dir / "overlap.off", two);
  expect_error(dir / "overlap.off", "the mesh intersects itself");

  // Inside out: repaired with a warning.
  TriMesh inverted = mpm::test::sphere_mesh(0.5, {1, 1, 1}, 10, 20);
  mpm::test::write_off(dir / "right.off", inverted);
  for (auto& t : inverted.triangles) std::swap(t[1], t[2]);
  mpm::test::write_off(dir / "inverted.off", inverted);
  std::vector<std::string> warnings;
  const auto a = fill_shape<3>(mesh_shape(dir / "inverted.off"), g, {2, 2, 2}, &warnings);
  const auto b = fill_shape<3>(mesh_shape(dir / "right.off"), g, {2, 2, 2}, nullptr);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("inverted.off: the mesh was inside out"), std::string::npos) << warnings[0];
  EXPECT_EQ(a.positions, b.positions);
  EXPECT_NEAR(a.volume, b.volume, 1e-15);

  // Larger than the grid.
  const std::string outside = fill_error(mesh_shape(dir / "right.off"), grid3(0, 1.2, 0.1));
  EXPECT_NE(outside.find("right.off: lies outside the grid: on axis x it spans [0.5, 1.5] m, the grid [0, 1.2] m"),
            std::string::npos)
      << outside;
  fs::remove_all(dir);
}
