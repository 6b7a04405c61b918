// Surface meshes through the `mpm` program (issue 54): a mesh's repair is reported once however many times the
// program needs the mesh (the memory estimate, the fill, the conforming domains, the certificate), and a mesh drawn
// in millimetres read as metres is refused with a hint naming the `scale` option and key.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "run_mpm.hpp"

namespace fs = std::filesystem;

namespace {

std::size_t occurrences_in(const std::string& text, const std::string& part) {
  std::size_t n = 0;
  for (std::size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) ++n;
  return n;
}

/// A 3D scene of one body from `shape` on the grid [0, 2]^3 m of cells `cell` m.
std::string mesh_cli_scene(const std::string& shape, const std::string& solver_extra = "") {
  return "dimension: 3\n"
         "grid: {extent: [2, 2, 2], cell_size: 0.25}\n"
         "materials: {steel: {model: linear_elastic, density: 7800, youngs_modulus: 2.0e11, poisson_ratio: 0.3}}\n"
         "bodies: [{name: part, material: steel, shape: " +
         shape +
         "}]\n"
         "solver: {cfl: 0.5, end_time: 1.0e-6" +
         solver_extra + "}\n";
}

}  // namespace

// tests/data/meshes/inverted.off is the unit cube turned inside out: reading it reverses its faces with a warning.
// `mpm particles` asked for its region and then filled it (two reads, two warnings); a scene with conforming domains
// read it for the lattice and again for the tetrahedra. Each run now says it once.
TEST(MeshImportCli, InsideOutWarningIsPrintedOnce) {
  const auto dir = cli::scratch("mesh_inside_out");
  const std::string mesh = (cli::data / "meshes" / "inverted.off").string();
  auto r = cli::mpm("particles " + mesh + " --spacing 0.25 -o " + (dir / "p.vtu").string(), dir);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(occurrences_in(r.err, "the mesh was inside out"), 1u) << r.err;
  r = cli::mpm("particles " + mesh + " --spacing 0.25 --domains conforming -o " + (dir / "c.vtu").string(), dir);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(occurrences_in(r.err, "the mesh was inside out"), 1u) << r.err;

  std::ofstream(dir / "scene.yaml") << mesh_cli_scene("{mesh: " + mesh + "}, domains: conforming",
                                                      ", shape_function: cpdi_tet4");
  for (const std::string command : {"check", "run"}) {
    r = cli::mpm(
        command + " " + (dir / "scene.yaml").string() + (command == "run" ? " -o " + (dir / "out").string() : ""), dir);
    ASSERT_EQ(r.status, 0) << command << "\n" << r.err;
    EXPECT_EQ(occurrences_in(r.err + r.out, "the mesh was inside out"), 1u) << command << "\n" << r.err << r.out;
  }
  fs::remove_all(dir);
}

// tests/data/meshes/cube_100mm.off is a cube of 100 mm drawn in millimetres. Read as metres with cells of 2 mm it
// would be (100 / 0.002)^3 x 8 = 1e15 particles; the refusal says that its coordinates look like millimetres and
// names --scale, which makes it 1e6 particles (and the scene's `scale` key: tests/data/bad_built_scenes/
// mesh_in_millimetres.yaml). With --scale 0.001 it is filled: (0.1 / 0.002 x 2)^3 = 1e6 particles.
TEST(MeshImportCli, MeshInMillimetresSaysSo) {
  const auto dir = cli::scratch("mesh_mm");
  const std::string mesh = (cli::data / "meshes" / "cube_100mm.off").string();
  auto r = cli::mpm("particles " + mesh + " --spacing 0.002 -o " + (dir / "p.vtu").string(), dir);
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("The input spans 100 x 100 x 100 m: if its coordinates are millimetres, --scale 0.001 (in a "
                       "scene, the shape's `scale: 1.0e-3`) makes it fit"),
            std::string::npos)
      << r.err;
  EXPECT_FALSE(fs::exists(dir / "p.vtu"));
  r = cli::mpm("particles " + mesh + " --spacing 0.002 --scale 0.001 -o " + (dir / "p.vtu").string(), dir);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find(": 1000000 particles"), std::string::npos) << r.out;
  fs::remove_all(dir);
}
