// Shapes through the scene: the loader's keys (mesh, image labels, polygon, domains) and the builder, as a
// user's scene file goes; and the STL cylinder of examples/15_stl_cylinder against the primitive.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numeric>

#include "mpm/app/modules.hpp"
#include "mpm/app/scene_builder.hpp"
#include "mpm/body_shape/primitive_shapes.hpp"
#include "mpm/geometry/file_shapes.hpp"
#include "mpm/geometry/shape_filler.hpp"
#include "mpm/scene/scene_loader.hpp"

namespace fs = std::filesystem;
using namespace mpm;

namespace {

const fs::path source = fs::path(MPM_SOURCE_DIR);

template <int Dim>
double total_volume(const Body<Dim>& b) {
  double v = 0;
  for (Index i = 0; i < b.particles.size(); ++i) v += b.particles.volume0[i];
  return v;
}

std::string scene_2d(const std::string& body, const std::string& solver = "") {
  return "dimension: 2\n"
         "grid: {extent: [1.2, 1.2], cell_size: 0.02}\n"
         "materials: {m: {model: linear_elastic, density: 1000, youngs_modulus: 1.0e6, poisson_ratio: 0.3}}\n"
         "bodies:\n" +
         body + "solver: {cfl: 0.5, end_time: 0.001" + solver + "}\n";
}

}  // namespace

// examples/15_stl_cylinder: the 256-facet STL rod (mm, scaled by 1e-3) fills the same lattice points as
// the primitive cylinder on the example's grid (no lattice point lies between a facet and the circle),
// and its particle volumes sum to the 256-gon prism's volume (float vertices: 1e-6).
TEST(SceneShapes, StlCylinderGivesTheParticlesOfThePrimitive) {
  const GridGeometry<3> grid(Vec<3>(-8e-3, -8e-3, 0), Vec<3>::Constant(0.5e-3), {32, 32, 52});
  app::register_modules();  // geometry's mesh kind
  geometry::MeshShape stl;
  stl.file = (source / "examples" / "15_stl_cylinder" / "cylinder.stl").string();
  stl.scale = 1e-3;
  CylinderShape cylinder;
  cylinder.radius = 3.8e-3;
  cylinder.axis.length = 25.4e-3;
  cylinder.axis.axis = 2;
  const auto a = geometry::fill_shape<3>(make_shape("mesh", stl), grid, {2, 2, 2}, nullptr);
  const auto b = geometry::fill_shape<3>(make_shape("cylinder", cylinder), grid, {2, 2, 2}, nullptr);
  EXPECT_EQ(a.positions.size(), 74664u);
  EXPECT_EQ(a.positions, b.positions);
  const double prism = 0.5 * 256 * 3.8e-3 * 3.8e-3 * std::sin(2 * M_PI / 256) * 25.4e-3;
  EXPECT_NEAR(a.volume * static_cast<double>(a.positions.size()) / prism, 1, 1e-6);
  EXPECT_NEAR(prism / (M_PI * 3.8e-3 * 3.8e-3 * 25.4e-3), 1, 1.1e-4);  // chords: 1 - sin(x)/x, x = 2 pi/256
}

// labels: [50, 100, 200] makes three bodies <name>_<label>, each with the area of its disk of pixels
// (radii 20, 16, 25 pixels of 1 cm: within 1% of pi r^2).
TEST(SceneShapes, ImageLabelsMakeOneBodyEach) {
  app::register_modules();  // geometry's image kind
  const std::string image = (source / "tests" / "data" / "images" / "labels.png").string();
  const auto scene = parse_scene(scene_2d("  - name: grain\n    material: m\n    shape: {image: " + image +
                                          ", pixel_size: 0.01, labels: [50, 100, 200]}\n"),
                                 "labels.yaml");
  ASSERT_EQ(scene.bodies.size(), 3u);
  const auto sim = app::build_simulation<2>(scene);
  const struct {
    const char* name;
    double radius;
  } expected[] = {{"grain_50", 0.2}, {"grain_100", 0.16}, {"grain_200", 0.25}};
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(sim->bodies()[k].name, expected[k].name);
    EXPECT_NEAR(total_volume(sim->bodies()[k]) / (M_PI * std::pow(expected[k].radius, 2)), 1, 0.01) << expected[k].name;
  }
}

// domains: conforming with cpdi_t3 (a polygon) and cpdi_tet4 (a box): the particles are the CGAL
// elements, their volumes sum to the body's to 1e-10, and they carry their corners.
TEST(SceneShapes, ConformingDomainsThroughTheScene) {
  const auto scene = parse_scene(
      scene_2d("  - material: m\n    domains: conforming\n    shape: {type: polygon, vertices: [[0.1, 0.1], "
               "[0.9, 0.1], [0.9, 0.5], [0.5, 0.9], [0.1, 0.9]]}\n",
               ", shape_function: cpdi_t3"),
      "t3.yaml");
  const auto sim = app::build_simulation<2>(scene);
  const double area = 0.8 * 0.8 - 0.5 * 0.4 * 0.4;
  EXPECT_NEAR(total_volume(sim->bodies()[0]) / area, 1, 1e-10);
  EXPECT_TRUE(sim->bodies()[0].particles.has_field("cpdi_corners"));
  EXPECT_EQ(sim->bodies()[0].domain_corners, 3);

  const auto scene3 = parse_scene(
      "dimension: 3\n"
      "grid: {extent: [1, 1, 1], cell_size: 0.1}\n"
      "materials: {m: {model: linear_elastic, density: 1000, youngs_modulus: 1.0e6, poisson_ratio: 0.3}}\n"
      "bodies: [{material: m, domains: conforming, shape: {type: box, min: [0.2, 0.2, 0.2], max: [0.7, 0.5, 0.6]}}]\n"
      "solver: {cfl: 0.5, end_time: 0.001, shape_function: cpdi_tet4}\n",
      "tet4.yaml");
  const auto sim3 = app::build_simulation<3>(scene3);
  EXPECT_NEAR(total_volume(sim3->bodies()[0]) / (0.5 * 0.3 * 0.4), 1, 1e-10);
  EXPECT_EQ(sim3->bodies()[0].domain_corners, 4);
  // The conforming elements run: 20 steps of the still box (no guard stop, mass conserved).
  const double mass = sim3->energy().mass;
  for (int step = 0; step < 20; ++step) sim3->advance(sim3->next_time_step());
  EXPECT_NEAR(sim3->energy().mass / mass, 1, 1e-12);
}

// A 3D mesh body through the scene: relative file names are taken from the scene file's folder.
TEST(SceneShapes, MeshPathIsRelativeToTheScene) {
  app::register_modules();  // geometry's mesh kind
  const auto scene = parse_scene(
      "dimension: 3\n"
      "grid: {extent: [2, 2, 2], cell_size: 0.1}\n"
      "materials: {m: {model: linear_elastic, density: 1000, youngs_modulus: 1.0e6, poisson_ratio: 0.3}}\n"
      "bodies: [{material: m, shape: {mesh: ../meshes/cube.off, scale: 0.5, rotation: [0, 0, 45], "
      "translation: [1, 0.5, 0.5]}}]\n"
      "solver: {cfl: 0.5, end_time: 0.001}\n",
      (source / "tests" / "data" / "bad_scenes" / "any.yaml").string());
  EXPECT_EQ(scene.bodies[0].shape.as<geometry::MeshShape>().file,
            (source / "tests" / "data" / "meshes" / "cube.off").lexically_normal());
  const auto sim = app::build_simulation<3>(scene);
  EXPECT_NEAR(total_volume(sim->bodies()[0]), 0.125, 1e-14);
}

// A polygon from a text file (corners "x y" or "x, y", comments, blank lines) is the polygon of its corners.
TEST(SceneShapes, PolygonFromAFile) {
  const auto scene =
      parse_scene(scene_2d("  - material: m\n    shape: {type: polygon, file: ../polygons/l_shape.txt}\n"),
                  (source / "tests" / "data" / "bad_scenes" / "any.yaml").string());
  const std::vector<std::array<double, 2>> corners{{0.2, 0.2}, {0.8, 0.2}, {0.8, 0.5},
                                                   {0.5, 0.5}, {0.5, 0.8}, {0.2, 0.8}};
  EXPECT_EQ(scene.bodies[0].shape.as<PolygonShape>().vertices, corners);
  const auto sim = app::build_simulation<2>(scene);
  EXPECT_NEAR(total_volume(sim->bodies()[0]) / 0.27, 1, 1e-12);  // a sum of 2,700 equal volumes
}

// The two geometry examples build as their READMEs say (they need the plasticity module for their
// materials).
TEST(SceneShapes, ExamplesBuildWithTheirParticleCounts) {
  app::register_modules();
  const auto modules = app::compiled_modules();
  if (std::find(modules.begin(), modules.end(), "plasticity") == modules.end())
    GTEST_SKIP() << "the examples' materials need MPM_WITH_PLASTICITY";
  const auto image = load_scene(source / "examples" / "08_image_impact" / "scene.yaml");
  const auto sim = app::build_simulation<2>(image);
  EXPECT_EQ(sim->particle_count(), 7616);
  EXPECT_NEAR(total_volume(sim->bodies()[0]), 480.68e-6, 0.005e-6);  // the selected pixel area, m^2
  const auto rod = load_scene(source / "examples" / "15_stl_cylinder" / "scene.yaml");
  EXPECT_EQ(app::build_simulation<3>(rod)->particle_count(), 74664);
}
