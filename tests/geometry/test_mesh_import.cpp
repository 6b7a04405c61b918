// Reading a surface mesh as a user's file comes (geometry/src/surface_mesh_io.cpp): a broken mesh names where it is
// broken (in the file's coordinates), a file of several shells or OBJ objects says that it merges them and lets a
// scene choose one (`shell`, `object`), and `weld` closes a mesh whose corners were written a little apart. The
// meshes are generated here (test_meshes.hpp), so every expected coordinate and volume is known exactly.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>

#include "mpm/app/modules.hpp"
#include "mpm/app/scene_builder.hpp"
#include "mpm/geometry/geometry_error.hpp"
#include "mpm/geometry/mesh_region.hpp"
#include "mpm/scene/scene_loader.hpp"
#include "test_meshes.hpp"

namespace fs = std::filesystem;
using mpm::geometry::GeometryError;
using mpm::geometry::MeshShape;
using mpm::test::TriMesh;

namespace {

fs::path import_scratch() {
  const fs::path dir = fs::temp_directory_path() / ("mpm_mesh_import_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  return dir;
}

MeshShape import_shape(const fs::path& file) {
  MeshShape shape;
  shape.file = file.string();
  return shape;
}

/// The message of reading `shape` (and the key it names), or "" when it reads.
std::pair<std::string, std::string> import_error(const MeshShape& shape) {
  try {
    std::vector<std::string> warnings;
    mpm::geometry::make_mesh_region(shape, &warnings);
  } catch (const GeometryError& e) {
    return {e.what(), e.key};
  }
  return {"", ""};
}

/// The unit cube's triangles moved by `shift` and scaled by `size` (about the origin first).
TriMesh import_cube(double size, std::array<double, 3> shift) {
  TriMesh m = mpm::test::cube_mesh();
  for (auto& p : m.points)
    for (int d = 0; d < 3; ++d) p[d] = size * p[d] + shift[d];
  return m;
}

/// `a` and `b` in one mesh (b's vertices after a's), as one file of two shells.
TriMesh import_join(TriMesh a, const TriMesh& b) {
  const int offset = static_cast<int>(a.points.size());
  a.points.insert(a.points.end(), b.points.begin(), b.points.end());
  for (auto t : b.triangles) {
    for (auto& v : t) v += offset;
    a.triangles.push_back(t);
  }
  return a;
}

/// An OBJ of named objects (`o NAME`), each a mesh of its own vertices.
void import_write_objects(const fs::path& file, const std::vector<std::pair<std::string, TriMesh>>& objects) {
  std::ofstream out(file);
  out.precision(17);
  int base = 1;
  for (const auto& [name, m] : objects) {
    out << "o " << name << '\n';
    for (const auto& p : m.points) out << "v " << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
    for (const auto& t : m.triangles) out << "f " << t[0] + base << ' ' << t[1] + base << ' ' << t[2] + base << '\n';
    base += static_cast<int>(m.points.size());
  }
}

double import_volume(const MeshShape& shape, std::vector<std::string>* warnings = nullptr) {
  return *mpm::geometry::make_mesh_region(shape, warnings)->exact_volume();
}

/// An ASCII STL of the unit cube whose corners are written with different copies: copy k of a corner shared by m
/// triangles is moved by 1e-7 (cos 2 pi k / m, sin 2 pi k / m, 0), so the copies' mean is the corner itself.
void import_write_gaps_stl(const fs::path& file) {
  const TriMesh cube = mpm::test::cube_mesh();
  std::map<int, int> copies, written;
  for (const auto& t : cube.triangles)
    for (const int v : t) ++copies[v];
  std::ofstream out(file);
  out.precision(17);
  out << "solid gaps\n";
  for (const auto& t : cube.triangles) {
    const auto n = mpm::test::normal(cube, t);
    out << "facet normal " << n[0] << ' ' << n[1] << ' ' << n[2] << "\nouter loop\n";
    for (const int v : t) {
      const double angle = 2 * M_PI * written[v]++ / copies[v];
      const auto& p = cube.points[v];
      out << "vertex " << p[0] + 1e-7 * std::cos(angle) << ' ' << p[1] + 1e-7 * std::sin(angle) << ' ' << p[2] << '\n';
    }
    out << "endloop\nendfacet\n";
  }
  out << "endsolid gaps\n";
}

}  // namespace

// A cube of side 10 (in the file) with one triangle removed: the hole is the triangle (10, 0, 0), (10, 10, 10),
// (10, 0, 10) (cube_mesh's last triangle, corners 1, 7, 5), and the message gives its three edges in the file's
// coordinates even though the shape scales the file by 0.1.
TEST(MeshImport, OpenMeshNamesTheEdgesOfTheHole) {
  const fs::path dir = import_scratch();
  TriMesh open = import_cube(10, {0, 0, 0});
  open.triangles.pop_back();
  mpm::test::write_off(dir / "open.off", open);
  MeshShape shape = import_shape(dir / "open.off");
  shape.scale = 0.1;
  const auto [message, key] = import_error(shape);
  EXPECT_NE(message.find("the mesh is open: 3 edges bound a single face (the surface has a hole), at "),
            std::string::npos)
      << message;
  for (const std::string edge : {"(10, 0, 0)-(10, 10, 10)", "(10, 10, 10)-(10, 0, 10)", "(10, 0, 10)-(10, 0, 0)"})
    EXPECT_TRUE(message.find(edge) != std::string::npos ||
                message.find(edge.substr(edge.find('-') + 1) + "-" + edge.substr(0, edge.find('-'))) !=
                    std::string::npos)
        << edge << " in " << message;
  EXPECT_NE(message.find("(in the file's coordinates)"), std::string::npos) << message;
  EXPECT_NE(message.find("`weld: DISTANCE`"), std::string::npos) << message;
  fs::remove_all(dir);
}

// Two cubes touching along an edge (x = y = 1, z in [0, 1]): four faces share it; at a corner: the corner is named;
// two cubes sharing the face x = 1:
// after the duplicated face is dropped, each of its four edges has three faces. Both name the edges and suggest two
// bodies; the OBJ's objects then give each cube alone (volume 1, the unit cube's).
TEST(MeshImport, NonManifoldMeshNamesTheEdgesAndSuggestsTwoBodies) {
  const fs::path dir = import_scratch();
  mpm::test::write_off(dir / "edge.off", import_join(import_cube(1, {0, 0, 0}), import_cube(1, {1, 1, 0})));
  auto [message, key] = import_error(import_shape(dir / "edge.off"));
  EXPECT_NE(message.find("the mesh is not manifold: 1 edge is shared by more than two faces, at "), std::string::npos)
      << message;
  EXPECT_TRUE(message.find("(1, 1, 0)-(1, 1, 1)") != std::string::npos ||
              message.find("(1, 1, 1)-(1, 1, 0)") != std::string::npos)
      << message;
  EXPECT_NE(message.find("make them two bodies"), std::string::npos) << message;

  // Two cubes touching at the corner (1, 1, 1) only: no edge is shared, the corner is.
  mpm::test::write_off(dir / "corner.off", import_join(import_cube(1, {0, 0, 0}), import_cube(1, {1, 1, 1})));
  std::tie(message, key) = import_error(import_shape(dir / "corner.off"));
  EXPECT_NE(message.find("the mesh is not manifold: faces meet at a single vertex at (1, 1, 1) (in the file's "
                         "coordinates); where two solids touch, make them two bodies"),
            std::string::npos)
      << message;

  const TriMesh a = import_cube(1, {0, 0, 0}), b = import_cube(1, {1, 0, 0});
  mpm::test::write_off(dir / "face.off", import_join(a, b));
  std::tie(message, key) = import_error(import_shape(dir / "face.off"));
  EXPECT_NE(message.find("the mesh is not manifold: 4 edges are shared by more than two faces, at "), std::string::npos)
      << message;
  EXPECT_NE(message.find("make them two bodies"), std::string::npos) << message;
  import_write_objects(dir / "face.obj", {{"cubeA", a}, {"cubeB", b}});
  std::tie(message, key) = import_error(import_shape(dir / "face.obj"));
  EXPECT_NE(message.find("the mesh is not manifold"), std::string::npos) << message;
  MeshShape one = import_shape(dir / "face.obj");
  one.object = "cubeB";
  EXPECT_NEAR(import_volume(one), 1, 1e-14);
  EXPECT_NEAR(mpm::geometry::make_mesh_region(one, nullptr)->bounds().lo[0], 1, 0);
  fs::remove_all(dir);
}

// An STL of two separate cubes (side 1 at the origin, side 2 at x = 3): one body of volume 1 + 8 with a warning
// that names the file and the two shells; `shell: 1` is the second cube alone (volume 8), `shell: 2` is refused.
TEST(MeshImport, SeparateShellsAreSaidToMergeAndOneCanBeChosen) {
  const fs::path dir = import_scratch();
  mpm::test::write_stl_ascii(dir / "two.stl", import_join(import_cube(1, {0, 0, 0}), import_cube(2, {3, 0, 0})));
  std::vector<std::string> warnings;
  EXPECT_NEAR(import_volume(import_shape(dir / "two.stl"), &warnings), 9, 1e-13);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find((dir / "two.stl").string() + ": 2 separate shells were merged into one body"),
            std::string::npos)
      << warnings[0];
  EXPECT_NE(warnings[0].find("`shell: INDEX` (0 to 1)"), std::string::npos) << warnings[0];

  MeshShape second = import_shape(dir / "two.stl");
  second.shell = 1;
  warnings.clear();
  EXPECT_NEAR(import_volume(second, &warnings), 8, 1e-13);
  EXPECT_TRUE(warnings.empty());
  second.shell = 2;
  const auto [message, key] = import_error(second);
  EXPECT_NE(message.find("two.stl: shell 2 does not exist: the mesh has 2 separate shells (0 to 1)"), std::string::npos)
      << message;
  EXPECT_EQ(key, "shell");

  // One cube alone: one shell, no warning.
  mpm::test::write_stl_ascii(dir / "one.stl", import_cube(1, {0, 0, 0}));
  warnings.clear();
  EXPECT_NEAR(import_volume(import_shape(dir / "one.stl"), &warnings), 1, 1e-14);
  EXPECT_TRUE(warnings.empty()) << warnings.front();
  fs::remove_all(dir);
}

// An OBJ of three objects (two cubes and a torus): one body with a warning naming them; `object: tube` is the torus
// alone, with the volume of its polyhedron (divergence theorem, test_meshes.hpp); an unknown name lists the file's.
TEST(MeshImport, NamedObjectsAreSaidToMergeAndOneCanBeChosen) {
  const fs::path dir = import_scratch();
  const TriMesh tube = mpm::test::torus_mesh(1, 0.25, {10, 0, 0}, 24, 12);
  import_write_objects(dir / "parts.obj",
                       {{"cubeA", import_cube(1, {0, 0, 0})}, {"cubeB", import_cube(1, {3, 0, 0})}, {"tube", tube}});
  std::vector<std::string> warnings;
  const double all = import_volume(import_shape(dir / "parts.obj"), &warnings);
  EXPECT_NEAR(all, 2 + mpm::test::polyhedron_volume(tube), 1e-12);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("parts.obj: 3 separate shells (objects cubeA, cubeB, tube) were merged into one body"),
            std::string::npos)
      << warnings[0];
  EXPECT_NE(warnings[0].find("or `object: NAME`"), std::string::npos) << warnings[0];

  MeshShape shape = import_shape(dir / "parts.obj");
  shape.object = "tube";
  warnings.clear();
  EXPECT_NEAR(import_volume(shape, &warnings) / mpm::test::polyhedron_volume(tube), 1, 1e-12);
  EXPECT_TRUE(warnings.empty());
  shape.object = "cubeC";
  auto [message, key] = import_error(shape);
  EXPECT_NE(message.find("parts.obj: no object 'cubeC' in the file; its objects: cubeA, cubeB, tube"),
            std::string::npos)
      << message;
  EXPECT_EQ(key, "object");

  mpm::test::write_obj(dir / "plain.obj", import_cube(1, {0, 0, 0}));
  MeshShape plain = import_shape(dir / "plain.obj");
  plain.object = "cubeA";
  std::tie(message, key) = import_error(plain);
  EXPECT_NE(message.find("object 'cubeA': the file names no object"), std::string::npos) << message;
  fs::remove_all(dir);
}

// An ASCII STL of the unit cube whose corners are written with different copies, 1e-7 apart (import_write_gaps_stl).
// Without `weld` no two triangles share a corner
// and the mesh is refused as open; with `weld: 1e-6` the copies merge into their mean, which is the corner itself
// (the displacements sum to zero), so the volume is the clean cube's, 1, to round-off (asked: 1e-9).
TEST(MeshImport, WeldClosesAMeshWhoseCornersWereWrittenApart) {
  const fs::path dir = import_scratch();
  import_write_gaps_stl(dir / "gaps.stl");
  MeshShape shape = import_shape(dir / "gaps.stl");
  const auto [message, key] = import_error(shape);
  EXPECT_NE(message.find("gaps.stl: the mesh is open: 36 edges bound a single face"), std::string::npos) << message;

  shape.weld = 1e-6;
  std::vector<std::string> warnings;
  const auto region = mpm::geometry::make_mesh_region(shape, &warnings);
  EXPECT_NEAR(*region->exact_volume(), 1, 1e-9);
  EXPECT_TRUE(warnings.empty()) << warnings.front();
  EXPECT_NEAR(region->bounds().hi[0], 1, 1e-12);

  // A tolerance above the cube's edge merges all eight corners: nothing of positive area is left.
  shape.weld = 2;
  EXPECT_NE(import_error(shape).first.find("gaps.stl: the mesh has no face of positive area"), std::string::npos);
  fs::remove_all(dir);
}

// The keys through a scene: `object: cubeB` and `shell: 0` of tests/data/meshes/two_cubes.obj (unit cubes at x in
// [2, 3] and [0, 1]) and `weld: 1.0e-6` of the gapped cube STL (moved to x = 3 by `translation`) each make one body
// of volume 1 (the particles share the mesh's volume) on the lattice of the unit cube: (1 / 0.25 x 2)^3 = 512
// particles, inside the x range of its cube.
TEST(MeshImport, ObjectShellAndWeldFromAScene) {
  const fs::path dir = import_scratch();
  import_write_gaps_stl(dir / "gaps.stl");
  mpm::app::register_modules();
  const std::string obj = (fs::path(MPM_SOURCE_DIR) / "tests" / "data" / "meshes" / "two_cubes.obj").string();
  const auto scene = mpm::parse_scene(
      "dimension: 3\n"
      "grid: {extent: [4, 2, 2], cell_size: 0.25}\n"
      "materials: {m: {model: linear_elastic, density: 1000, youngs_modulus: 1.0e6, poisson_ratio: 0.3}}\n"
      "bodies:\n"
      "  - {name: b, material: m, shape: {mesh: " +
          obj +
          ", object: cubeB}}\n"
          "  - {name: a, material: m, shape: {mesh: " +
          obj +
          ", shell: 0}}\n"
          "  - {name: w, material: m, shape: {mesh: " +
          (dir / "gaps.stl").string() +
          ", weld: 1.0e-6, translation: [3, 0, 0]}}\n"
          "solver: {cfl: 0.5, end_time: 0.001}\n",
      (dir / "scene.yaml").string());
  const auto sim = mpm::app::build_simulation<3>(scene);
  const double lower[3] = {2, 0, 3};
  ASSERT_EQ(sim->bodies().size(), 3u);
  for (const auto& body : sim->bodies()) {
    const auto k = static_cast<std::size_t>(body.index);
    EXPECT_EQ(body.particles.size(), 512) << body.name;
    double volume = 0, x_min = 1e9, x_max = -1e9;
    for (mpm::Index i = 0; i < body.particles.size(); ++i) {
      volume += body.particles.volume0[i];
      x_min = std::min(x_min, body.particles.x[i][0]);
      x_max = std::max(x_max, body.particles.x[i][0]);
    }
    EXPECT_NEAR(volume, 1, 1e-9) << body.name;
    EXPECT_GT(x_min, lower[k]) << body.name;
    EXPECT_LT(x_max, lower[k] + 1) << body.name;
  }
  fs::remove_all(dir);
}
