// User materials from shared libraries (physics/user_material): the built-in J2 plasticity (physics/plasticity,
// `j2_plasticity`, linear hardening) written as a Fortran VUMAT, a Fortran UMAT and a C plugin
// (examples/25_user_material) against the built-in law, one material point along `mpm material-test`'s paths and
// the Taylor anvil in 1D, 2D (plane strain and axisymmetric) and 3D; the state variables in the output, a restart's
// bits; and every error path (a missing library or symbol, a wrong interface, a subroutine returning NaN or an
// error code) with its message and exit status.
//
// The user laws compute in the corotational frame of the Green-Naghdi rotation R of F = R U; the built-in law updates
// the same un-rotated deviator but turns it into the current frame with Delta R = R_{n+1} R_n^T (physics/README.md).
// Where R is exact in both (2D and 1D: the closed-form rotation about z, or none) the two agree to round-off; in 3D
// the built-in's R comes from Newton iterations stopped at a 1e-3 rad correction (polar_decomposition.hpp), the
// user interfaces' from the same iterations taken to round-off, and the difference is that tolerance's (measured and
// bounded below).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "../apps/restart_support.hpp"
#include "../libmpm/scene_fixture.hpp"
#include "mpm/app/material_test.hpp"
#include "mpm/materials/material_registry.hpp"
#include "mpm/scene/scene_error.hpp"
#include "mpm/user_material/user_material.hpp"

namespace {

namespace fs = std::filesystem;
using mpm::Mat3;
using mpm::Real;

std::string plugin(const std::string& name) { return std::string(MPM_USER_MATERIAL_PLUGINS) + "/lib" + name + ".so"; }

/// The interfaces whose J2 plugin this build has (the Fortran ones need a Fortran compiler).
std::vector<std::string> interfaces() {
#ifdef MPM_HAVE_FORTRAN
  return {"vumat", "umat", "c"};
#else
  return {"c"};
#endif
}

std::string j2_plugin(const std::string& interface) {
  return plugin(interface == "c" ? "j2_c" : interface == "umat" ? "j2_umat" : "j2_vumat");
}

/// The built-in J2 (linear hardening) and its user versions: one material each, `builtin` and `user_INTERFACE`.
/// Copper-like constants of the Taylor anvil (examples/16_axisymmetric_taylor) with linear hardening.
std::string j2_materials() {
  const std::string elastic = "density: 8940, youngs_modulus: 115.0e9, poisson_ratio: 0.31";
  std::string text = "materials:\n  builtin: {model: j2_plasticity, " + elastic +
                     ", yield_stress: 200.0e6, hardening_modulus: 1.0e9}\n";
  for (const auto& i : interfaces())
    text += fmt::format(
        "  user_{0}: {{model: user, interface: {0}, library: '{1}', {2}, properties: [115.0e9, 0.31, 200.0e6, 1.0e9], "
        "state_variables: [plastic_strain, plastic_work]}}\n",
        i, j2_plugin(i), elastic);
  return text;
}

/// The largest difference of two tensors relative to the larger of their largest components.
double relative(const Mat3& a, const Mat3& b) {
  return (a - b).cwiseAbs().maxCoeff() / std::max(a.cwiseAbs().maxCoeff(), b.cwiseAbs().maxCoeff());
}

// ---- One material point along the driver's paths (mpm material-test) ----

mpm::app::MaterialTestResult drive(const mpm::SceneDescription& scene, const std::string& material,
                                   const mpm::app::MaterialTestOptions& options) {
  const auto m = mpm::make_material<3>(scene.materials.at(material));
  return mpm::app::run_material_test(*m, options);
}

double field(const mpm::app::MaterialTestResult& r, const mpm::app::MaterialTestRow& row, const std::string& name) {
  const auto it = std::find(r.model_fields.begin(), r.model_fields.end(), name);
  EXPECT_NE(it, r.model_fields.end()) << name;
  return it == r.model_fields.end() ? NAN : row.model_fields.at(static_cast<std::size_t>(it - r.model_fields.begin()));
}

struct PathCase {
  mpm::app::LoadPath path;
  double strain;
  int steps;
  double stress_tolerance;  ///< relative, the largest over every step
};

void compare_along(const PathCase& c) {
  mpm::app::register_modules();
  const auto scene = mpm::parse_scene(
      "dimension: 3\ngrid: {extent: [1, 1, 1], cell_size: 0.5}\n" + j2_materials() +
          "bodies: [{name: b, material: builtin, shape: {type: box, min: [0, 0, 0], max: [0.5, 0.5, 0.5]}}]\n"
          "solver: {scheme: musl, cfl: 0.5, end_time: 1.0e-3}\n",
      "material_point.yaml");
  mpm::app::MaterialTestOptions options;
  options.path = c.path;
  options.strain = c.strain;
  options.steps = c.steps;
  options.duration = 1.0e-3;
  const auto builtin = drive(scene, "builtin", options);
  const double eps_p = field(builtin, builtin.rows.back(), "plastic_strain");
  ASSERT_GT(eps_p, 0.01);  // well into the plastic range
  for (const auto& i : interfaces()) {
    const auto user = drive(scene, "user_" + i, options);
    ASSERT_EQ(user.rows.size(), builtin.rows.size());
    double stress = 0, plastic = 0;
    for (std::size_t k = 1; k < user.rows.size(); ++k) {
      stress = std::max(stress, relative(user.rows[k].stress, builtin.rows[k].stress));
      plastic = std::max(plastic, std::abs(field(user, user.rows[k], "plastic_strain") -
                                           field(builtin, builtin.rows[k], "plastic_strain")) /
                                      eps_p);
    }
    std::cout << fmt::format("{:>6}: stress {:.2e}, plastic strain {:.2e} (eps_p = {:.4f})\n", i, stress, plastic,
                             eps_p);
    EXPECT_LT(stress, c.stress_tolerance) << i;
    EXPECT_LT(plastic, c.stress_tolerance) << i;
  }
}

// Uniaxial strain: F = diag(lambda, 1, 1), no rotation (R = 1 in both laws): the same arithmetic up to the order of a
// few sums, so agreement to round-off. Measured: 4.0e-16 (stress), 8.8e-15 (plastic strain).
TEST(UserMaterialPoint, UniaxialStrainMatchesTheBuiltInJ2) {
  compare_along({mpm::app::LoadPath::uniaxial_strain, 0.05, 500, 1e-12});
}

// Simple shear to gamma = 0.5 (the material turns by 14 degrees): the built-in's 3D polar rotation stops its Newton
// iterations at a 1e-3 rad correction, the user interfaces' at round-off; from a warm start a step's correction is
// about 2.5e-4 rad and what it leaves is below 4e-12 (measured on this path), and the normal stress sigma_yy is held
// at 0 by the driver's Newton iterations (residual 1e-12 of the stress). Measured: 2.7e-13 (stress), 1.2e-15
// (plastic strain).
TEST(UserMaterialPoint, SimpleShearMatchesTheBuiltInJ2) {
  compare_along({mpm::app::LoadPath::simple_shear, 0.5, 1000, 1e-10});
}

// ---- The Taylor anvil: the built-in J2 and each user version in the same scene, 1D, 2D, axisymmetric, 3D ----

struct SceneCase {
  std::string name;
  std::string text;  ///< with @MATERIAL@
  double tolerance;
};

/// Copper rod at 190 m/s onto a rigid frictionless wall (examples/16_axisymmetric_taylor, coarse), with linear
/// hardening J2; 15 us of the impact.
std::vector<SceneCase> taylor_cases() {
  const std::string solver = "solver: {scheme: musl, shape_function: cubic_bspline, cfl: 0.5, end_time: 1.5e-5}\n";
  return {
      {"bar_1d",
       "dimension: 1\ngrid: {extent: [0.026], cell_size: 0.0005, boundary: {x_min: slip}}\n" + j2_materials() +
           "bodies: [{name: rod, material: @MATERIAL@, shape: {type: box, min: [0], max: [25.4e-3]}, "
           "particles_per_cell: 2, velocity: [-190]}]\n" +
           solver,
       1e-11},
      {"plane_strain",
       "dimension: 2\ngrid: {origin: [-0.008, 0], extent: [0.016, 0.026], cell_size: 0.001, boundary: {y_min: "
       "slip}}\n" +
           j2_materials() +
           "bodies: [{name: rod, material: @MATERIAL@, shape: {type: box, min: [-3.8e-3, 0], max: [3.8e-3, 25.4e-3]}, "
           "particles_per_cell: 2, velocity: [0, -190]}]\n" +
           solver,
       1e-10},
      {"axisymmetric",
       "dimension: 2\ngrid: {coordinates: axisymmetric, extent: [0.008, 0.026], cell_size: 0.0005, boundary: {y_min: "
       "slip}}\n" +
           j2_materials() +
           "bodies: [{name: rod, material: @MATERIAL@, shape: {type: box, min: [0, 0], max: [3.8e-3, 25.4e-3]}, "
           "particles_per_cell: 2, velocity: [0, -190]}]\n" +
           solver,
       1e-10},
      {"rod_3d",
       "dimension: 3\ngrid: {origin: [-0.006, -0.006, 0], extent: [0.012, 0.012, 0.026], cell_size: 0.001, boundary: "
       "{z_min: slip}}\n" +
           j2_materials() +
           "bodies: [{name: rod, material: @MATERIAL@, shape: {type: cylinder, center: [0, 0, 0], radius: 3.8e-3, "
           "length: 25.4e-3, axis: z}, particles_per_cell: 1, velocity: [0, 0, -190]}]\n" +
           solver,
       1e-10},
  };
}

template <int Dim>
void compare_scene(const SceneCase& c) {
  auto run = [&](const std::string& material) {
    auto sim =
        mpm::test::simulation_from_yaml<Dim>(mpm::test::fill(c.text, {{"MATERIAL", material}}), c.name + ".yaml");
    sim->run();
    return sim;
  };
  const auto builtin = run("builtin");
  const auto& pb = builtin->bodies().at(0).particles;
  std::vector<double> eps_b;
  builtin->bodies().at(0).material->append_output("plastic_strain", pb, eps_b);
  const double eps_max = *std::max_element(eps_b.begin(), eps_b.end());
  ASSERT_GT(eps_max, 0.05) << c.name;
  double stress_max = 0;
  for (mpm::Index k = 0; k < pb.size(); ++k)
    stress_max = std::max(stress_max, pb.stress[k].full().cwiseAbs().maxCoeff());
  for (const auto& i : interfaces()) {
    const auto user = run("user_" + i);
    const auto& pu = user->bodies().at(0).particles;
    ASSERT_EQ(pu.size(), pb.size());
    ASSERT_EQ(user->step(), builtin->step()) << i;
    std::vector<double> eps_u;
    ASSERT_TRUE(user->bodies().at(0).material->append_output("plastic_strain", pu, eps_u));
    std::map<std::uint32_t, mpm::Index> at;  // by id: the sort by cell may order them differently
    for (mpm::Index k = 0; k < pu.size(); ++k) at[pu.id[k]] = k;
    double position = 0, stress = 0, plastic = 0;
    for (mpm::Index k = 0; k < pb.size(); ++k) {
      const mpm::Index u = at.at(pb.id[k]);
      position = std::max(position, (pu.x[u] - pb.x[k]).cwiseAbs().maxCoeff() / 25.4e-3);
      stress = std::max(stress, (pu.stress[u].full() - pb.stress[k].full()).cwiseAbs().maxCoeff() / stress_max);
      plastic = std::max(plastic,
                         std::abs(eps_u[static_cast<std::size_t>(u)] - eps_b[static_cast<std::size_t>(k)]) / eps_max);
    }
    std::cout << fmt::format(
        "{:>12} {:>6}: {} steps, position {:.2e}, stress {:.2e}, plastic strain {:.2e} "
        "(max eps_p {:.3f})\n",
        c.name, i, user->step(), position, stress, plastic, eps_max);
    EXPECT_LT(position, c.tolerance) << c.name << " " << i;
    EXPECT_LT(stress, c.tolerance) << c.name << " " << i;
    EXPECT_LT(plastic, c.tolerance) << c.name << " " << i;
  }
}

TEST(UserMaterialScene, TaylorBar1DMatchesTheBuiltInJ2) { compare_scene<1>(taylor_cases()[0]); }
TEST(UserMaterialScene, TaylorPlaneStrainMatchesTheBuiltInJ2) { compare_scene<2>(taylor_cases()[1]); }
TEST(UserMaterialScene, TaylorAxisymmetricMatchesTheBuiltInJ2) { compare_scene<2>(taylor_cases()[2]); }
TEST(UserMaterialScene, Taylor3DMatchesTheBuiltInJ2) { compare_scene<3>(taylor_cases()[3]); }

// ---- Through the program: output fields, a restart's bits, and the errors ----

/// A 2D block of user material `material` (keys after `model: user`) thrown at a wall.
std::string block_scene(const std::string& material_keys, const std::string& output_fields = "velocity, stress") {
  return "dimension: 2\n"
         "grid: {origin: [0, 0], extent: [0.02, 0.02], cell_size: 0.001, boundary: {y_min: slip}}\n"
         "materials:\n"
         "  steel: {model: user, density: 8940, youngs_modulus: 115.0e9, poisson_ratio: 0.31, " +
         material_keys +
         "}\n"
         "bodies: [{name: block, material: steel, shape: {type: box, min: [0.005, 0], max: [0.015, 0.01]}, velocity: "
         "[0, -150]}]\n"
         "solver: {scheme: musl, cfl: 0.5, end_time: 4.0e-6}\n"
         "output:\n"
         "  interval: 1.0e-6\n"
         "  fields: [" +
         output_fields + "]\n";
}

const std::string j2_c_keys = "interface: c, library: '" + plugin("j2_c") +
                              "', properties: [115.0e9, 0.31, 200.0e6, 1.0e9], state_variables: [eqps, work]";

TEST(UserMaterialRun, StateVariablesAreOutputFields) {
  const fs::path dir = cli::scratch("user_material_output");
  std::ofstream(dir / "scene.yaml") << block_scene(j2_c_keys, "velocity, stress, eqps, work");
  const cli::Result r = cli::mpm("run " + (dir / "scene.yaml").string() + " -o " + (dir / "out").string(), dir);
  ASSERT_EQ(r.status, 0) << r.err;
  std::string last;
  for (const auto& e : fs::directory_iterator(dir / "out"))
    if (e.path().extension() == ".vtu") last = std::max(last, e.path().string());
  const std::string vtu = cli::slurp(last);
  EXPECT_NE(vtu.find("Name=\"eqps\""), std::string::npos);
  EXPECT_NE(vtu.find("Name=\"work\""), std::string::npos);
  // the energy audit books the plugin's inelastic energy as dissipated (plastic_work column)
  const std::string energy = cli::slurp(dir / "out" / "energy.csv");
  EXPECT_NE(energy.find("plastic_work"), std::string::npos);
  fs::remove_all(dir);
}

// The example (examples/25_user_material/scene.yaml) with each plugin the tests built in place of the library its
// README builds beside it: three steps, a clean exit.
TEST(UserMaterialRun, TheExampleRunsWithEachPlugin) {
  const std::string example = cli::slurp(fs::path(MPM_SOURCE_DIR) / "examples" / "25_user_material" / "scene.yaml");
  const std::string given = "library: libj2_vumat.so", interface = "interface: vumat";
  ASSERT_NE(example.find(given), std::string::npos);
  ASSERT_NE(example.find(interface), std::string::npos);
  for (const auto& i : interfaces()) {
    std::string scene = example;
    scene.replace(scene.find(given), given.size(), "library: '" + j2_plugin(i) + "'");
    scene.replace(scene.find(interface), interface.size(), "interface: " + i);
    const fs::path dir = cli::scratch("user_material_example_" + i);
    std::ofstream(dir / "scene.yaml") << scene;
    const cli::Result r =
        cli::mpm("run " + (dir / "scene.yaml").string() + " --steps 3 -o " + (dir / "out").string(), dir);
    EXPECT_EQ(r.status, 0) << i << "\n" << r.err;
    EXPECT_NE(r.out.find("done: 3 steps"), std::string::npos) << i << "\n" << r.out;
    if (!::testing::Test::HasFailure()) fs::remove_all(dir);
  }
}

// A checkpoint holds the state variables (fields sdv1, sdv2) and the interface's per-point record bit for bit: the
// interrupted run reaches the bits of the uninterrupted one (tests/apps/test_restart.cpp).
TEST(UserMaterialRun, InterruptedRunReachesTheSameBits) {
  std::string scene = block_scene(j2_c_keys, "velocity, stress, eqps, work");
  scene.replace(scene.find("end_time: 4.0e-6"), 16, "end_time: 8.0e-6");
  restart_support::check_interrupted_run_reaches_the_same_bits(
      {"user_material_c", scene + restart_support::checkpoint_at(4.0e-6)});
}

// ---- mpm material-test --check: objectivity and the UMAT's tangent, each catching a broken plugin ----

/// `mpm material-test --check` on material `name` (keys after `model: user`, or a whole entry) along simple shear.
cli::Result material_check(const std::string& test, const std::string& material,
                           const std::string& path = "simple_shear") {
  const fs::path dir = cli::scratch("user_material_check_" + test);
  std::ofstream(dir / "scene.yaml")
      << "dimension: 3\ngrid: {extent: [1, 1, 1], cell_size: 0.5}\n"
         "materials:\n  m: " +
             material +
             "\nbodies: [{name: b, material: m, shape: {type: box, min: [0, 0, 0], "
             "max: [0.5, 0.5, 0.5]}}]\nsolver: {scheme: musl, cfl: 0.5, end_time: 1.0e-3}\n";
  cli::Result r = cli::mpm("material-test --scene " + (dir / "scene.yaml").string() + " --material m --path " + path +
                               " --strain 0.3 --steps 200 --duration 1e-3 --check -o " + (dir / "path.csv").string(),
                           dir);
  if (!::testing::Test::HasFailure()) fs::remove_all(dir);
  return r;
}

const std::string j2_properties =
    "density: 8940, youngs_modulus: 115.0e9, poisson_ratio: 0.31, "
    "properties: [115.0e9, 0.31, 200.0e6, 1.0e9], state_variables: 2";

TEST(UserMaterialCheck, TheJ2PluginsPass) {
  for (const auto& i : interfaces()) {
    const cli::Result r = material_check(
        "j2_" + i, "{model: user, interface: " + i + ", library: '" + j2_plugin(i) + "', " + j2_properties + "}");
    std::cout << i << ":\n" << r.err;
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.err.find("check: objectivity"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(i == "umat" ? "check: tangent (DDSDDE against finite differences of STRESS, 200 steps)"
                                     : "check: tangent: not applicable"),
              std::string::npos)
        << r.err;
    EXPECT_EQ(r.err.find("FAILED"), std::string::npos) << r.err;
  }
}

TEST(UserMaterialCheck, TheBuiltInJ2IsObjective) {
  const cli::Result r = material_check("builtin",
                                       "{model: j2_plasticity, density: 8940, youngs_modulus: 115.0e9, "
                                       "poisson_ratio: 0.31, yield_stress: 200.0e6, hardening_modulus: 1.0e9}");
  std::cout << r.err;
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("): passed"), std::string::npos) << r.err;
}

TEST(UserMaterialCheck, CatchesALawThatIsNotObjective) {
  const cli::Result r =
      material_check("non_objective", "{model: user, interface: c, library: '" + plugin("non_objective_c") +
                                          "', density: 8940, youngs_modulus: 115.0e9, poisson_ratio: "
                                          "0.31, properties: [115.0e9, 0.31]}");
  std::cout << r.err;
  EXPECT_EQ(r.status, 3) << r.err;
  EXPECT_NE(r.err.find("check: objectivity (the path with a rigid rotation superposed, principal stresses): largest "
                       "difference"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("FAILED"), std::string::npos) << r.err;
}

TEST(UserMaterialCheck, CatchesAWrongUmatTangent) {
  const cli::Result r =
      material_check("bad_tangent", "{model: user, interface: umat, library: '" + plugin("bad_tangent_umat") +
                                        "', density: 8940, youngs_modulus: 115.0e9, poisson_ratio: "
                                        "0.31, properties: [115.0e9, 0.31]}");
  std::cout << r.err;
  EXPECT_EQ(r.status, 3) << r.err;
  EXPECT_NE(r.err.find("check: objectivity"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("DDSDDE(4, 4)"), std::string::npos) << r.err;  // the first shear entry
  EXPECT_NE(r.err.find("): FAILED"), std::string::npos) << r.err;
}

struct BadCase {
  std::string name;
  std::string keys;     ///< after `model: user`
  std::string command;  ///< check or run
  int status;
  std::vector<std::string> messages;
};

void PrintTo(const BadCase& c, std::ostream* os) { *os << c.name; }

class UserMaterialBad : public ::testing::TestWithParam<BadCase> {};

TEST_P(UserMaterialBad, IsRefusedWithItsMessage) {
  const BadCase& c = GetParam();
  const fs::path dir = cli::scratch("user_material_" + c.name);
  std::ofstream(dir / "scene.yaml") << block_scene(c.keys);
  const cli::Result r = cli::mpm(
      c.command + " " + (dir / "scene.yaml").string() + (c.command == "run" ? " -o " + (dir / "out").string() : ""),
      dir);
  EXPECT_EQ(r.status, c.status) << r.err;
  for (const auto& m : c.messages)
    EXPECT_NE(r.err.find(m), std::string::npos) << "expected '" << m << "' in\n" << r.err;
  fs::remove_all(dir);
}

std::vector<BadCase> bad_cases() {
  const std::string props = ", properties: [115.0e9, 0.31, 200.0e6, 1.0e9], state_variables: 2";
  std::vector<BadCase> cases{
      {"missing_library",
       "library: no_such_plugin.so, interface: c" + props,
       "check",
       2,
       {"scene.yaml:", "materials.steel.library", "library file '", "no_such_plugin.so' not found",
        "(relative to the scene file)"}},
      {"not_a_library",
       "library: scene.yaml, interface: c" + props,
       "check",
       2,
       {"materials.steel.library", "material 'steel' (interface c): cannot load the library", "scene.yaml"}},
      {"missing_symbol",
       "library: '" + plugin("j2_c") + "', interface: c, symbol: j2_update" + props,
       "check",
       2,
       {"materials.steel.symbol", "has no symbol 'j2_update'", "libj2_c.so"}},
      {"old_abi",
       "library: '" + plugin("old_abi_c") + "', interface: c" + props,
       "check",
       2,
       {"materials.steel.library", "was built for version 2 of the C interface; this program has version 1"}},
      {"wave_speed_and_elastic_constants",
       "library: '" + plugin("j2_c") + "', interface: c, wave_speed: 4000" + props,
       "check",
       2,
       {"materials.steel.wave_speed",
        "give either youngs_modulus and poisson_ratio or wave_speed for the time step, not both"}},
      {"bad_state_name",
       "library: '" + plugin("j2_c") + "', interface: c, state_variables: [velocity]",
       "check",
       2,
       {"materials.steel.state_variables", "state variable name 'velocity' is already an output field"}},
      {"nan",
       "library: '" + plugin("nan_c") + "', interface: c, properties: [1.0e-6]",
       "run",
       1,
       {"error: material 'steel' (model user, interface c, symbol 'mpm_user_material_update' of library '",
        "libnan_c.so'): the subroutine returned a stress that is not finite", "at particle "}},
      {"error_code",
       "library: '" + plugin("error_c") + "', interface: c",
       "run",
       1,
       {"error: material 'steel' (model user, interface c", "liberror_c.so'",
        "the update returned error code 2: expected 3 properties, got 0", "at particle "}},
  };
#ifdef MPM_HAVE_FORTRAN
  cases.push_back({"wrong_interface",
                   "library: '" + plugin("j2_vumat") + "', interface: c" + props,
                   "check",
                   2,
                   {"materials.steel.library", "has no symbol 'mpm_user_material_update'", "libj2_vumat.so"}});
  cases.push_back({"vumat_library_as_umat",
                   "library: '" + plugin("j2_vumat") + "', interface: umat" + props,
                   "check",
                   2,
                   {"materials.steel.library", "has no symbol 'umat_'"}});
#endif
  return cases;
}

INSTANTIATE_TEST_SUITE_P(Cases, UserMaterialBad, ::testing::ValuesIn(bad_cases()),
                         [](const ::testing::TestParamInfo<BadCase>& info) { return info.param.name; });

}  // namespace
