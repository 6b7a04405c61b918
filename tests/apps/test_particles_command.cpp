// `mpm particles` (apps/src/particles_command.cpp): the .vtu it writes is read back with VTK and its
// particle count, volumes and domains are checked against the exact body volume; bad input exits with 2
// and writes nothing. Surface meshes through the program (issue 54): a mesh's repair is reported once however
// many times the program needs the mesh, and a mesh drawn in millimetres read as metres is refused with a hint.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkPointData.h>
#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "run_mpm.hpp"

namespace fs = std::filesystem;

namespace {

using cli::data;

using cli::slurp;

fs::path particles_scratch(const std::string& name) { return cli::scratch("particles_" + name); }

struct Read {
  vtkIdType points = 0, cells = 0;
  double volume_sum = 0;  ///< of the point (or, for domains, cell) field `volume`
};

Read read_vtu(const fs::path& file, bool cell_data) {
  auto reader = vtkSmartPointer<vtkXMLUnstructuredGridReader>::New();
  reader->SetFileName(file.c_str());
  reader->Update();
  vtkUnstructuredGrid* grid = reader->GetOutput();
  Read r;
  r.points = grid->GetNumberOfPoints();
  r.cells = grid->GetNumberOfCells();
  vtkDataArray* volume = cell_data ? grid->GetCellData()->GetArray("volume") : grid->GetPointData()->GetArray("volume");
  if (volume)
    for (vtkIdType i = 0; i < volume->GetNumberOfTuples(); ++i) r.volume_sum += volume->GetComponent(i, 0);
  return r;
}

}  // namespace

// The unit cube mesh, cells of 0.1 m, 2 per axis: 8000 particles of total volume 1 m^3; conforming
// tetrahedra (CPDI-Tet4 domains) also sum to 1 m^3 (1e-10).
TEST(ParticlesCommand, MeshWithLatticeAndConformingDomains) {
  const auto dir = particles_scratch("mesh");
  auto r = cli::mpm(
      "particles " + (data / "meshes" / "cube.off").string() + " --spacing 0.1 -o " + (dir / "cube.vtu").string(), dir);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("8000 particles"), std::string::npos) << r.out;
  Read cube = read_vtu(dir / "cube.vtu", false);
  EXPECT_EQ(cube.points, 8000);
  EXPECT_NEAR(cube.volume_sum, 1, 1e-12);

  r = cli::mpm("particles " + (data / "meshes" / "cube.off").string() + " --spacing 0.25 --domains conforming -o " +
                   (dir / "tets.vtu").string(),
               dir);
  ASSERT_EQ(r.status, 0) << r.err;
  const Read points = read_vtu(dir / "tets.vtu", false);
  const Read cells = read_vtu(dir / "tets_domains.vtu", true);
  EXPECT_GT(points.points, 100);
  EXPECT_EQ(cells.cells, points.points);
  EXPECT_EQ(cells.points, 4 * cells.cells);  // each tetrahedron has its own four corners
  EXPECT_NEAR(points.volume_sum, 1, 1e-10);
  EXPECT_NEAR(cells.volume_sum, 1, 1e-10);
  fs::remove_all(dir);
}

// The disk picture (radius 40 pixels of 1 cm): the particle volumes sum to the selected pixel area, which
// is within 1% of pi 0.4^2 m^2; a 2D section of the cube mesh makes conforming triangles of area 1 m^2.
TEST(ParticlesCommand, ImageAndSection) {
  const auto dir = particles_scratch("image");
  auto r = cli::mpm("particles " + (data / "images" / "disk.png").string() +
                        " --pixel-size 0.01 --threshold 128 --spacing 0.05 --ppc 4 -o " + (dir / "disk.vtu").string(),
                    dir);
  ASSERT_EQ(r.status, 0) << r.err;
  const Read disk = read_vtu(dir / "disk.vtu", false);
  EXPECT_NEAR(disk.volume_sum / (M_PI * 0.16), 1, 0.01);
  r = cli::mpm("particles " + (data / "meshes" / "cube.off").string() +
                   " --section 0.5 --spacing 0.1 --domains conforming -o " + (dir / "section.vtu").string(),
               dir);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NEAR(read_vtu(dir / "section_domains.vtu", true).volume_sum, 1, 1e-10);
  fs::remove_all(dir);
}

// A scene alone: every body as the builder makes it (here the 2D test scene), with its domains when its
// shape function has them.
TEST(ParticlesCommand, SceneBodies) {
  const auto dir = particles_scratch("scene");
  const auto r =
      cli::mpm("particles --scene " + (data / "good_scene_2d.yaml").string() + " -o " + (dir / "p.vtu").string(), dir);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_GT(read_vtu(dir / "p.vtu", false).points, 0);
  fs::remove_all(dir);
}

TEST(ParticlesCommand, BadInputExitsWithTwoAndWritesNothing) {
  const auto dir = particles_scratch("bad");
  const fs::path out = dir / "p.vtu";
  const struct {
    std::string args, message;
  } cases[] = {
      {(data / "meshes" / "open.off").string() + " --spacing 0.1", "open.off: the mesh is open"},
      {(data / "meshes" / "cube.off").string(), "give the grid: --spacing H (cell size, m) or --scene SCENE"},
      {"", "give an input file (mesh or image) or --scene SCENE"},
      {(data / "meshes" / "none.stl").string() + " --spacing 0.1", "none.stl: mesh file not found"},
      {(data / "good_scene_2d.yaml").string() + " --spacing 0.1", "unsupported input format '.yaml'"},
      {(data / "images" / "disk.png").string() + " --spacing 0.1 --threshold 1", "--pixel-size is required"},
      {(data / "images" / "black.png").string() + " --spacing 0.1 --pixel-size 0.01 --threshold 1",
       "black.png: no pixel reaches the threshold 1"},
      {"--scene " + (data / "good_scene_2d.yaml").string() + " --domains scene",
       "--domains: the scene's shape function"},
  };
  for (const auto& c : cases) {
    const auto r = cli::mpm("particles " + c.args + " -o " + out.string(), dir);
    EXPECT_EQ(r.status, 2) << c.args << "\n" << r.err;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << c.args << "\n" << r.err;
    EXPECT_FALSE(fs::exists(out)) << c.args;
  }
  fs::remove_all(dir);
}

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
TEST(ParticlesCommand, InsideOutWarningIsPrintedOnce) {
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
TEST(ParticlesCommand, MeshInMillimetresSaysSo) {
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
