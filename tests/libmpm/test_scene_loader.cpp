/// Tests of the YAML scene loader (scene_loader.hpp), its error reporting (scene_error.hpp) and of
/// Expression. Every file in tests/data/bad_scenes/ is one error path; its first two lines say what the
/// error must contain and on which line it must be reported:
///   # expect: <substring of the message>
///   # line: <1-based line>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>
#include <vector>

#include "mpm/app/modules.hpp"
#include "mpm/body_shape/primitive_shapes.hpp"
#include "mpm/boundary/velocity_face.hpp"
#include "mpm/core/expression.hpp"
#include "mpm/scene/scene_loader.hpp"

namespace {

namespace fs = std::filesystem;

const fs::path data_dir = fs::path(MPM_SOURCE_DIR) / "tests" / "data";

/// The velocity a face of a scene holds in component c (its kind's VelocityFaceSpec), or nothing.
std::optional<std::string> held(const mpm::FaceDescription& face, int c) {
  const auto* spec = std::any_cast<mpm::VelocityFaceSpec>(&face.spec);
  return spec ? spec->velocity[static_cast<std::size_t>(c)] : std::nullopt;
}

// ---------------------------------------------------------------------------------------------------
// Bad scenes: one file per error path.

struct BadScene {
  fs::path file;
  std::string expect;
  int line = 0;
};

std::vector<BadScene> bad_scenes() {
  std::vector<BadScene> scenes;
  for (const auto& entry : fs::directory_iterator(data_dir / "bad_scenes")) {
    if (entry.path().extension() != ".yaml") continue;
#ifndef MPM_WITH_THERMAL  // the thermal module's section and keys are unknown without it
    if (entry.path().filename().string().rfind("thermal_", 0) == 0) continue;
#endif
#ifndef MPM_WITH_CONTACT  // the contact module's section is an unknown key without it
    if (entry.path().filename().string().rfind("contact_", 0) == 0) continue;
#endif
    BadScene scene{entry.path(), "", 0};
    std::ifstream in(entry.path());
    std::string first, second;
    std::getline(in, first);
    std::getline(in, second);
    const std::string expect_tag = "# expect: ", line_tag = "# line: ";
    if (first.rfind(expect_tag, 0) == 0) scene.expect = first.substr(expect_tag.size());
    if (second.rfind(line_tag, 0) == 0) scene.line = std::stoi(second.substr(line_tag.size()));
    scenes.push_back(scene);
  }
  std::sort(scenes.begin(), scenes.end(), [](const auto& a, const auto& b) { return a.file < b.file; });
  return scenes;
}

/// One case per fixture of tests/data/bad_scenes: ctest names them `Bad/Scene.Refused/<fixture>`.
class Scene : public testing::TestWithParam<BadScene> {};

TEST_P(Scene, Refused) {
  const BadScene& scene = GetParam();
  ASSERT_FALSE(scene.expect.empty()) << scene.file << ": first line must be '# expect: ...'";
  ASSERT_GT(scene.line, 0) << scene.file << ": second line must be '# line: N'";
  // CTest runs each case in its own process: the optional modules' models (plasticity, fluids) must be
  // registered here, as the program does, or their fixtures would fail as "unknown material model".
  mpm::app::register_modules();
  try {
    mpm::load_scene(scene.file);
    FAIL() << scene.file << " was accepted; expected an error containing: " << scene.expect;
  } catch (const mpm::SceneError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(scene.expect), std::string::npos) << "message: " << what;
    EXPECT_EQ(e.where.line, scene.line) << "message: " << what;
    EXPECT_GT(e.where.column, 0) << "message: " << what;
    const std::string prefix =
        scene.file.string() + ":" + std::to_string(e.where.line) + ":" + std::to_string(e.where.column) + ": ";
    EXPECT_EQ(what.rfind(prefix, 0), 0u) << "message: " << what;
  }
}

INSTANTIATE_TEST_SUITE_P(Bad, Scene, testing::ValuesIn(bad_scenes()),
                         [](const testing::TestParamInfo<BadScene>& info) { return info.param.file.stem().string(); });

TEST(SceneLoader, HasBadSceneFixtures) { EXPECT_GE(bad_scenes().size(), 50u); }

// ---------------------------------------------------------------------------------------------------
// Errors built in the test.

/// The SceneError thrown by parse_scene(text), or a failure.
mpm::SceneError parse_error(const std::string& text) {
  try {
    mpm::parse_scene(text, "inline.yaml");
  } catch (const mpm::SceneError& e) {
    return e;
  }
  ADD_FAILURE() << "scene accepted:\n" << text;
  return mpm::SceneError({}, "", "");
}

const std::string valid_2d = R"(dimension: 2
grid:
  extent: [1, 1]
  cell_size: 0.1
materials:
  rubber: {model: neo_hookean, density: 1000, youngs_modulus: 1.0e6, poisson_ratio: 0.3}
bodies:
  - material: rubber
    shape: {type: disk, center: [0.5, 0.5], radius: 0.2}
solver:
  dt: 1.0e-4
  end_time: 0.1
)";

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

TEST(SceneLoader, ErrorCarriesFileLineColumnAndKey) {
  const auto e = parse_error(replaced(valid_2d, "radius: 0.2", "radius: -0.2"));
  EXPECT_EQ(e.where.file, "inline.yaml");
  EXPECT_EQ(e.where.line, 9);
  EXPECT_EQ(e.where.column, 53);
  EXPECT_EQ(e.key, "bodies[0].shape.radius");
  EXPECT_EQ(e.message, "out of range: must be > 0 m, got -0.2 m");
  EXPECT_STREQ(e.what(), "inline.yaml:9:53: bodies[0].shape.radius: out of range: must be > 0 m, got -0.2 m");
}

TEST(SceneLoader, ErrorInListNamesTheEntry) {
  const auto e = parse_error(replaced(valid_2d, "extent: [1, 1]", "extent: [1, -1]"));
  EXPECT_EQ(e.key, "grid.extent[1]");
  EXPECT_EQ(e.where.line, 3);
  EXPECT_EQ(e.where.column, 15);
}

TEST(SceneLoader, MaterialParameterKeyPath) {
  const auto e = parse_error(replaced(valid_2d, "poisson_ratio: 0.3", "poisson_ratio: 0.7"));
  EXPECT_EQ(e.key, "materials.rubber.poisson_ratio");
  EXPECT_EQ(e.where.line, 6);
  EXPECT_NE(e.message.find("must be in (-1, 0.5)"), std::string::npos) << e.message;
}

TEST(SceneLoader, MissingKeyIsReportedAtItsMap) {
  const auto e = parse_error(replaced(valid_2d, "  end_time: 0.1\n", ""));
  EXPECT_EQ(e.key, "solver.end_time");
  EXPECT_EQ(e.where.line, 11);
  EXPECT_EQ(e.where.column, 3);
}

TEST(SceneLoader, SyntaxErrorHasItsMark) {
  const auto e = parse_error("dimension: 2\ngrid: {extent: [1, 1}\n");
  EXPECT_NE(e.message.find("YAML syntax error"), std::string::npos) << e.what();
  EXPECT_EQ(e.where.line, 2);
  EXPECT_TRUE(e.key.empty());
}

TEST(SceneLoader, EmptyTextAndNonMapAreErrors) {
  EXPECT_NE(parse_error("").message.find("the scene is empty"), std::string::npos);
  EXPECT_NE(parse_error("# nothing\n").message.find("the scene is empty"), std::string::npos);
  const auto e = parse_error("\n\n just a string\n");
  EXPECT_NE(e.message.find("expected a map"), std::string::npos);
  EXPECT_EQ(e.where.line, 3);
}

TEST(SceneLoader, FileNotFoundNamesTheFile) {
  const fs::path missing = data_dir / "no_such_scene.yaml";
  try {
    mpm::load_scene(missing);
    FAIL() << "no error";
  } catch (const mpm::SceneError& e) {
    EXPECT_EQ(e.where.file, missing.string());
    EXPECT_EQ(e.where.line, 0);
    EXPECT_EQ(std::string(e.what()), missing.string() + ": scene file not found");
  }
}

TEST(SceneLoader, DirectoryIsNotAScene) {
  try {
    mpm::load_scene(data_dir);
    FAIL() << "no error";
  } catch (const mpm::SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("is a directory"), std::string::npos);
  }
}

TEST(SceneLoader, ErrorFormatWithoutParts) {
  EXPECT_STREQ(mpm::SceneError({"a.yaml", 0, 0}, "", "boom").what(), "a.yaml: boom");
  EXPECT_STREQ(mpm::SceneError({"a.yaml", 0, 0}, "grid", "boom").what(), "a.yaml: grid: boom");
  EXPECT_STREQ(mpm::SceneError({"a.yaml", 3, 7}, "", "boom").what(), "a.yaml:3:7: boom");
  EXPECT_STREQ(mpm::SceneError({"a.yaml", 3, 7}, "grid.extent", "boom").what(), "a.yaml:3:7: grid.extent: boom");
}

// ---------------------------------------------------------------------------------------------------
// Valid scenes.

TEST(SceneLoader, Good2D) {
  const fs::path file = data_dir / "good_scene_2d.yaml";
  const mpm::SceneDescription s = mpm::load_scene(file);
  EXPECT_EQ(s.file, file.string());
  EXPECT_EQ(s.dimension, 2);

  const auto& g = s.grid;
  EXPECT_EQ(g.origin, (std::array<double, 3>{-0.5, 0, 0}));
  EXPECT_EQ(g.extent, (std::array<double, 3>{2, 1, 0}));
  EXPECT_EQ(g.cell_size, (std::array<double, 3>{0.1, 0.05, 0}));
  EXPECT_EQ(g.cells, (std::array<int, 3>{20, 20, 1}));
  // x_min fixed: both in-plane components 0.
  EXPECT_EQ(held(g.boundary[0], 0), std::optional<std::string>("0"));
  EXPECT_EQ(held(g.boundary[0], 1), std::optional<std::string>("0"));
  EXPECT_FALSE(held(g.boundary[0], 2));
  EXPECT_EQ(g.boundary[0].where.line, 8);
  // x_max slip: only the normal (x) component.
  EXPECT_EQ(held(g.boundary[1], 0), std::optional<std::string>("0"));
  EXPECT_FALSE(held(g.boundary[1], 1));
  // y_min prescribed: x free, y = 0.1 sin(t).
  EXPECT_FALSE(held(g.boundary[2], 0));
  EXPECT_EQ(held(g.boundary[2], 1), std::optional<std::string>("0.1*sin(t)"));
  // y_max free, z faces untouched.
  for (int face = 3; face < 6; ++face)
    for (int c = 0; c < 3; ++c) EXPECT_FALSE(held(g.boundary[face], c)) << face << " " << c;
  EXPECT_EQ(g.boundary[3].where.line, 11);
  EXPECT_EQ(g.boundary[4].where.line, 0);

  ASSERT_EQ(s.materials.size(), 2u);
  const auto& rubber = s.materials.at("rubber");
  EXPECT_EQ(rubber.name, "rubber");
  EXPECT_EQ(rubber.model, "neo_hookean");
  EXPECT_EQ(rubber.parameters.at("density"), 1000);
  EXPECT_EQ(rubber.parameters.at("youngs_modulus"), 1.0e6);
  EXPECT_EQ(rubber.parameters.at("poisson_ratio"), 0.3);
  EXPECT_EQ(rubber.where.line, 13);
  EXPECT_EQ(rubber.where.file, file.string());
  const auto& steel = s.materials.at("steel");
  EXPECT_EQ(steel.model, "linear_elastic");
  EXPECT_EQ(steel.parameters.at("youngs_modulus"), 2.0e11);
  EXPECT_EQ(steel.where.line, 18);

  ASSERT_EQ(s.bodies.size(), 2u);
  const auto& block = s.bodies[0];
  EXPECT_EQ(block.name, "block");
  EXPECT_EQ(block.material, "rubber");
  EXPECT_EQ(block.shape.kind, "box");
  EXPECT_EQ(block.shape.as<mpm::BoxShape>().min, (std::array<double, 3>{0.1, 0.1, 0}));
  EXPECT_EQ(block.shape.as<mpm::BoxShape>().max, (std::array<double, 3>{0.5, 0.3, 0}));
  EXPECT_EQ(block.particles_per_cell, (std::array<int, 3>{2, 3, 1}));
  EXPECT_EQ(block.velocity, (std::array<std::string, 3>{"0.1", "0.2*x", "0"}));
  EXPECT_EQ(block.where.line, 24);
  const auto& disk = s.bodies[1];
  EXPECT_EQ(disk.name, "body1");  // default name from the list index
  EXPECT_EQ(disk.material, "steel");
  EXPECT_EQ(disk.shape.kind, "disk");
  EXPECT_EQ(disk.shape.as<mpm::BallShape>().center, (std::array<double, 3>{1.0, 0.5, 0}));
  EXPECT_EQ(disk.shape.as<mpm::BallShape>().radius, 0.2);
  EXPECT_EQ(disk.particles_per_cell, (std::array<int, 3>{4, 4, 1}));
  EXPECT_EQ(disk.velocity, (std::array<std::string, 3>{"0", "0", "0"}));
  EXPECT_EQ(disk.where.line, 29);

  const auto& solver = s.solver;
  EXPECT_EQ(solver.scheme, "usl");
  EXPECT_EQ(solver.shape_function, "cubic_bspline");
  EXPECT_EQ(solver.flip_fraction, 0.95);
  EXPECT_FALSE(solver.dt);
  EXPECT_EQ(solver.cfl, std::optional<double>(0.4));
  EXPECT_EQ(solver.dt_where.line, 39);
  EXPECT_EQ(solver.end_time, 0.5);
  EXPECT_EQ(solver.mass_cutoff, 1.0e-10);
  EXPECT_EQ(solver.gravity, (std::array<double, 3>{0, -9.81, 0}));
  EXPECT_EQ(solver.snapshot_interval, 10);
  EXPECT_EQ(solver.sort_interval, 50);

  const auto& out = s.output;
  EXPECT_EQ(out.directory, "results");
  EXPECT_EQ(out.prefix, "drop");
  EXPECT_EQ(out.interval, 0.01);
  EXPECT_EQ(out.fields, (std::vector<std::string>{"velocity", "stress", "von_mises_stress"}));
  EXPECT_TRUE(out.grid);
  EXPECT_EQ(out.where.line, 46);
}

TEST(SceneLoader, Good3D) {
  const mpm::SceneDescription s = mpm::load_scene(data_dir / "good_scene_3d.yaml");
  EXPECT_EQ(s.dimension, 3);
  EXPECT_EQ(s.grid.origin, (std::array<double, 3>{0, 0, 0}));
  EXPECT_EQ(s.grid.extent, (std::array<double, 3>{1, 1, 2}));
  EXPECT_EQ(s.grid.cell_size, (std::array<double, 3>{0.25, 0.25, 0.25}));
  EXPECT_EQ(s.grid.cells, (std::array<int, 3>{4, 4, 8}));
  // z_min fixed: all three components.
  for (int c = 0; c < 3; ++c) EXPECT_EQ(held(s.grid.boundary[4], c), std::optional<std::string>("0"));
  // x_min and x_max slip: x only.
  for (int face : {0, 1}) {
    EXPECT_EQ(held(s.grid.boundary[face], 0), std::optional<std::string>("0"));
    EXPECT_FALSE(held(s.grid.boundary[face], 1));
    EXPECT_FALSE(held(s.grid.boundary[face], 2));
  }
  for (int face : {2, 3, 5})
    for (int c = 0; c < 3; ++c) EXPECT_FALSE(held(s.grid.boundary[face], c));

  ASSERT_EQ(s.bodies.size(), 2u);
  const auto& ball = s.bodies[0];
  EXPECT_EQ(ball.shape.kind, "sphere");
  EXPECT_EQ(ball.shape.as<mpm::BallShape>().center, (std::array<double, 3>{0.5, 0.5, 1.5}));
  EXPECT_EQ(ball.shape.as<mpm::BallShape>().radius, 0.25);
  EXPECT_EQ(ball.particles_per_cell, (std::array<int, 3>{2, 2, 2}));
  EXPECT_EQ(ball.velocity, (std::array<std::string, 3>{"0", "0", "-1 - 0.5*z"}));
  const auto& pillar = s.bodies[1];
  EXPECT_EQ(pillar.shape.kind, "cylinder");
  EXPECT_EQ(pillar.shape.as<mpm::CylinderShape>().axis.axis, 2);
  EXPECT_EQ(pillar.shape.as<mpm::CylinderShape>().axis.length, 0.75);
  EXPECT_EQ(pillar.shape.as<mpm::CylinderShape>().radius, 0.2);
  EXPECT_EQ(pillar.particles_per_cell, (std::array<int, 3>{1, 2, 3}));

  // Defaults.
  EXPECT_EQ(s.solver.scheme, "musl");
  EXPECT_EQ(s.solver.shape_function, "linear");
  EXPECT_EQ(s.solver.flip_fraction, 1.0);
  EXPECT_EQ(s.solver.dt, std::optional<double>(1.0e-5));
  EXPECT_FALSE(s.solver.cfl);
  EXPECT_EQ(s.solver.dt_where.line, 26);
  EXPECT_EQ(s.solver.mass_cutoff, 1e-12);
  EXPECT_EQ(s.solver.gravity, (std::array<double, 3>{0, 0, -9.81}));
  EXPECT_EQ(s.solver.snapshot_interval, 20);
  EXPECT_EQ(s.solver.sort_interval, 20);
  EXPECT_EQ(s.output.directory, "output");
  EXPECT_EQ(s.output.prefix, "particles");
  EXPECT_EQ(s.output.interval, 0);
  EXPECT_EQ(s.output.fields, (std::vector<std::string>{"velocity", "stress", "mass", "volume", "body"}));
  EXPECT_FALSE(s.output.grid);
  EXPECT_EQ(s.output.where.line, 0);
}

TEST(SceneLoader, OneDimensionalPadsUnusedAxes) {
  const auto s = mpm::parse_scene(R"(dimension: 1
grid: {origin: [1], extent: [2], cell_size: 0.5, boundary: {x_min: fixed, x_max: slip}}
materials: {bar: {model: linear_elastic, density: 1, youngs_modulus: 1, poisson_ratio: 0}}
bodies: [{material: bar, shape: {type: box, min: [1], max: [3]}, velocity: ["x - 1"]}]
solver: {cfl: 1, end_time: 1, gravity: [-1]}
)",
                                  "one.yaml");
  EXPECT_EQ(s.grid.origin, (std::array<double, 3>{1, 0, 0}));
  EXPECT_EQ(s.grid.extent, (std::array<double, 3>{2, 0, 0}));
  EXPECT_EQ(s.grid.cell_size, (std::array<double, 3>{0.5, 0, 0}));
  EXPECT_EQ(s.grid.cells, (std::array<int, 3>{4, 1, 1}));
  EXPECT_EQ(held(s.grid.boundary[0], 0), std::optional<std::string>("0"));
  EXPECT_FALSE(held(s.grid.boundary[0], 1));
  EXPECT_EQ(held(s.grid.boundary[1], 0), std::optional<std::string>("0"));
  EXPECT_EQ(s.bodies[0].name, "body0");
  EXPECT_EQ(s.bodies[0].particles_per_cell, (std::array<int, 3>{2, 1, 1}));
  EXPECT_EQ(s.bodies[0].velocity, (std::array<std::string, 3>{"x - 1", "0", "0"}));
  EXPECT_EQ(s.solver.cfl, std::optional<double>(1.0));
  EXPECT_EQ(s.solver.gravity, (std::array<double, 3>{-1, 0, 0}));
}

TEST(SceneLoader, CellCountToleratesRoundOff) {
  // 0.3 / 0.1 = 2.9999999999999996 in floating point.
  const auto s = mpm::parse_scene(replaced(replaced(valid_2d, "extent: [1, 1]", "extent: [0.3, 0.7]"),
                                           "center: [0.5, 0.5], radius: 0.2", "center: [0.15, 0.35], radius: 0.1"),
                                  "roundoff.yaml");
  EXPECT_EQ(s.grid.cells, (std::array<int, 3>{3, 7, 1}));
}

TEST(SceneLoader, BodyTouchingTheGridBoundaryIsInside) {
  EXPECT_NO_THROW(mpm::parse_scene(replaced(valid_2d, "radius: 0.2", "radius: 0.5"), "touch.yaml"));
}

TEST(SceneLoader, VelocityNumbersBecomeExpressionText) {
  const auto s =
      mpm::parse_scene(replaced(valid_2d, "radius: 0.2}", "radius: 0.2}\n    velocity: [1.0e6, -0.50]"), "v.yaml");
  EXPECT_EQ(s.bodies[0].velocity[0], "1000000");
  EXPECT_EQ(s.bodies[0].velocity[1], "-0.5");
  EXPECT_DOUBLE_EQ(mpm::Expression(s.bodies[0].velocity[0])(0, 0, 0, 0), 1.0e6);
}

TEST(SceneLoader, BoundaryNumbersBecomeExpressionText) {
  const auto s = mpm::parse_scene(
      replaced(valid_2d, "  cell_size: 0.1\n", "  cell_size: 0.1\n  boundary: {y_max: {velocity: [0.25, free]}}\n"),
      "b.yaml");
  EXPECT_EQ(held(s.grid.boundary[3], 0), std::optional<std::string>("0.25"));
  EXPECT_FALSE(held(s.grid.boundary[3], 1));
}

TEST(SceneLoader, YamlAliasesWork) {
  const auto s = mpm::parse_scene(
      replaced(replaced(valid_2d, "cell_size: 0.1", "cell_size: &h 0.1"), "dt: 1.0e-4", "dt: *h"), "alias.yaml");
  EXPECT_EQ(s.solver.dt, std::optional<double>(0.1));
}

// ---------------------------------------------------------------------------------------------------
// Expression.

TEST(Expression, Constant) {
  const mpm::Expression e("2*_pi");
  EXPECT_TRUE(e.is_constant());
  EXPECT_DOUBLE_EQ(e.constant_value(), 2 * std::numbers::pi);
  EXPECT_DOUBLE_EQ(e(1, 2, 3, 4), 2 * std::numbers::pi);
  EXPECT_EQ(e.text(), "2*_pi");
}

TEST(Expression, DependsOnPosition) {
  const mpm::Expression e("0.2*x + y - 3*z");
  EXPECT_FALSE(e.is_constant());
  EXPECT_DOUBLE_EQ(e(1, 2, 3, 100), 0.2 + 2 - 9);
  EXPECT_DOUBLE_EQ(e(-5, 0, 0, 0), -1);
  const double p[3] = {1, 1, 1};
  EXPECT_DOUBLE_EQ(e.evaluate(p, 7), -1.8);
}

TEST(Expression, DependsOnTime) {
  const mpm::Expression e("0.1*sin(t) + cos(2*t)", {"t"});
  EXPECT_FALSE(e.is_constant());
  for (double t : {0.0, 0.3, 1.7, 10.0}) EXPECT_NEAR(e(9, 9, 9, t), 0.1 * std::sin(t) + std::cos(2 * t), 1e-14) << t;
}

TEST(Expression, RepeatedEvaluation) {
  const mpm::Expression e("x*x");
  double sum = 0;
  for (int i = 0; i < 1000; ++i) sum += e(i, 0, 0, 0);
  EXPECT_DOUBLE_EQ(sum, 999.0 * 1000.0 * 1999.0 / 6.0);
}

TEST(Expression, SyntaxErrorThrows) {
  EXPECT_THROW(mpm::Expression("sin(t"), std::invalid_argument);
  EXPECT_THROW(mpm::Expression("0.2*"), std::invalid_argument);
  EXPECT_THROW(mpm::Expression(""), std::invalid_argument);
  EXPECT_THROW(mpm::Expression("1, 2"), std::invalid_argument);
  try {
    mpm::Expression bad("2 +* x");
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("2 +* x"), std::string::npos) << e.what();
  }
}

TEST(Expression, UnknownVariableThrows) {
  EXPECT_THROW(mpm::Expression("w + 1"), std::invalid_argument);
  EXPECT_THROW(mpm::Expression("x + t", {"t"}), std::invalid_argument);
  EXPECT_THROW(mpm::Expression("t", {"x", "y", "z"}), std::invalid_argument);
  EXPECT_THROW(mpm::Expression("1", {"w"}), std::invalid_argument);
  EXPECT_NO_THROW(mpm::Expression("x + y + z", {"x", "y", "z"}));
}

TEST(Expression, CopyAndMoveKeepWorking) {
  mpm::Expression a("x + 10*t");
  mpm::Expression b(a);
  EXPECT_DOUBLE_EQ(b(1, 0, 0, 2), 21);
  mpm::Expression c(std::move(a));
  EXPECT_DOUBLE_EQ(c(2, 0, 0, 2), 22);
  mpm::Expression d("0");
  d = b;
  EXPECT_DOUBLE_EQ(d(3, 0, 0, 2), 23);
  EXPECT_DOUBLE_EQ(b(1, 0, 0, 2), 21);  // the copy does not share variables with d
  std::vector<mpm::Expression> many;
  for (int i = 0; i < 20; ++i) many.emplace_back("x + " + std::to_string(i));
  for (int i = 0; i < 20; ++i) EXPECT_DOUBLE_EQ(many[i](1, 0, 0, 0), 1 + i);
  d = std::move(c);
  EXPECT_DOUBLE_EQ(d(0, 0, 0, 1), 10);
}

}  // namespace
