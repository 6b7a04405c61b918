// `mpm material-test` (apps/src/material_test_command.cpp, material_test.cpp): every registered material model runs
// every path through the program, the CSV has the columns and rows it announces, and every bad input (unknown
// material, unknown path, bad CSV rows with file:line, a rigid material, a stress a material cannot carry) exits
// with 2, says why, and leaves no output file behind. The soil models' numbers are checked in
// tests/physics/test_soils.cpp through the driver's library function.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "mpm/app/modules.hpp"
#include "mpm/materials/material_registry.hpp"
#include "run_mpm.hpp"

namespace fs = std::filesystem;

namespace {

/// One material per registered model (the optional modules' when compiled in), named after its model.
std::string scene_with_every_model() {
  std::string materials =
      "  linear_elastic: {model: linear_elastic, density: 1000, youngs_modulus: 1.0e7, poisson_ratio: 0.3}\n"
      "  neo_hookean: {model: neo_hookean, density: 1000, youngs_modulus: 1.0e6, poisson_ratio: 0.45}\n"
      "  rigid: {model: rigid, density: 1000}\n";
#ifdef MPM_WITH_PLASTICITY
  materials +=
      "  j2_plasticity: {model: j2_plasticity, density: 7800, youngs_modulus: 200.0e9, poisson_ratio: 0.3, "
      "yield_stress: 300.0e6}\n"
      "  johnson_cook: {model: johnson_cook, density: 8930, youngs_modulus: 115.0e9, poisson_ratio: 0.31, "
      "yield_stress: 90.0e6, hardening_coefficient: 292.0e6, hardening_exponent: 0.31, damage_d1: 0.54}\n"
      "  hencky_j2: {model: hencky_j2, density: 8930, bulk_modulus: 130.0e9, shear_modulus: 43.3e9, yield_stress: "
      "400.0e6}\n";
#endif
#ifdef MPM_WITH_FLUIDS
  materials +=
      "  newtonian_fluid: {model: newtonian_fluid, density: 1000, bulk_modulus: 2.0e6}\n"
      "  ideal_gas: {model: ideal_gas, density: 1.2, initial_pressure: 1.0e5}\n"
      "  incompressible_fluid: {model: incompressible_fluid, density: 1000, viscosity: 1.0e-3}\n";
#endif
#ifdef MPM_WITH_SOILS
  materials +=
      "  drucker_prager: {model: drucker_prager, density: 1800, youngs_modulus: 50.0e6, poisson_ratio: 0.3, "
      "friction_angle: 30 deg, dilation_angle: 10 deg, cohesion: 5.0e3}\n"
      "  mohr_coulomb: {model: mohr_coulomb, density: 1800, youngs_modulus: 50.0e6, poisson_ratio: 0.3, "
      "friction_angle: 30 deg, dilation_angle: 10 deg, cohesion: 5.0e3}\n"
      "  mu_i: {model: mu_i, density: 1470, youngs_modulus: 50.0e6, poisson_ratio: 0.3, mu_s: 0.38, mu_2: 0.64, "
      "I_0: 0.279, grain_diameter: 0.5e-3, grain_density: 2450}\n";
#endif
  return "dimension: 2\n"
         "grid: {extent: [1, 1], cell_size: 0.1}\n"
         "materials:\n" +
         materials +
         "bodies: [{material: linear_elastic, shape: {type: box, min: [0.1, 0.1], max: [0.5, 0.3]}}]\n"
         "solver: {cfl: 0.5, end_time: 1.0e-4}\n";
}

struct Scratch {
  fs::path dir, scene;
  explicit Scratch(const std::string& name) : dir(cli::scratch("material_test_" + name)), scene(dir / "scene.yaml") {
    std::ofstream(scene) << scene_with_every_model();
  }
  cli::Result run(const std::string& args) const {
    return cli::mpm("material-test --scene " + scene.string() + " " + args, dir);
  }
  fs::path write(const std::string& name, const std::string& text) const {
    std::ofstream(dir / name) << text;
    return dir / name;
  }
};

/// The lines of a CSV text.
std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

/// Every value of every data row is a finite number, and each row has as many as the header.
void expect_finite_table(const std::string& csv, const std::string& what) {
  const auto rows = lines(csv);
  ASSERT_GE(rows.size(), 2u) << what;
  const auto columns = std::count(rows[0].begin(), rows[0].end(), ',') + 1;
  for (std::size_t i = 1; i < rows.size(); ++i) {
    std::istringstream cells(rows[i]);
    long count = 0;
    for (std::string cell; std::getline(cells, cell, ',');) {
      ++count;
      EXPECT_TRUE(std::isfinite(std::stod(cell))) << what << " row " << i << ": " << rows[i];
    }
    EXPECT_EQ(count, columns) << what << " row " << i;
  }
}

// Every registered model (but rigid, which has no stress) along every path: a complete finite table of
// 1 + 10 (consolidation) + 20 rows; the soils and the plastic models announce their plastic strain.
TEST(MaterialTest, EveryModelAlongEveryPath) {
  mpm::app::register_modules();
  const Scratch s("every");
  const fs::path csv = s.write("stretch.csv",
                               "time,F11,F12,F13,F21,F22,F23,F31,F32,F33\n"
                               "0,1,0,0,0,1,0,0,0,1\n"
                               "0.5,0.99,0.01,0,0,1,0,0,0,1\n"
                               "1.0,0.98,0.02,0,0,1.001,0,0,0,1\n");
  for (const std::string& model : mpm::material_model_names()) {
    if (model == "rigid") continue;
    if (model == "user") continue;          // a law from a shared library: tests/user_material drives its plugins
    if (model == "incompressible_fluid") {  // a constraint of the flow, not a law of the point: refused
      const auto r = s.run("--material " + model + " --path uniaxial_strain");
      EXPECT_EQ(r.status, 2) << r.err;
      EXPECT_NE(r.err.find("material 'incompressible_fluid' (model incompressible_fluid) keeps its volume"),
                std::string::npos)
          << r.err;
      continue;
    }
    for (const std::string path :
         {"uniaxial_strain", "triaxial_compression", "triaxial_extension", "simple_shear", "cyclic_shear"}) {
      const auto r = s.run("--material " + model + " --path " + path +
                           " --steps 20 --strain 0.01 --confining-pressure 1000 --amplitude 0.005 --cycles 2");
      ASSERT_EQ(r.status, 0) << model << " " << path << ": " << r.err;
      expect_finite_table(r.out, model + " " + path);
      EXPECT_EQ(lines(r.out).size(), 1u + 1 + 10 + 20) << model << " " << path;
      EXPECT_EQ(lines(r.out)[0].rfind("time,strain_xx,", 0), 0u) << r.out.substr(0, 200);
      if (model == "drucker_prager" || model == "mohr_coulomb" || model == "mu_i" || model == "j2_plasticity") {
        EXPECT_NE(lines(r.out)[0].find(",plastic_strain"), std::string::npos) << model;
      }
    }
    const auto r = s.run("--material " + model + " --path deformation_csv --csv " + csv.string());
    ASSERT_EQ(r.status, 0) << model << " deformation_csv: " << r.err;
    expect_finite_table(r.out, model + " deformation_csv");
    EXPECT_EQ(lines(r.out).size(), 1u + 1 + 2) << model;  // the row at t = 0 is the start, F = I
  }
}

// -o writes the same table as stdout, whole.
TEST(MaterialTest, OutputFileHoldsTheTable) {
  mpm::app::register_modules();
  const Scratch s("file");
  const auto to_stdout = s.run("--material linear_elastic --path uniaxial_strain --steps 5");
  ASSERT_EQ(to_stdout.status, 0) << to_stdout.err;
  const auto to_file =
      s.run("--material linear_elastic --path uniaxial_strain --steps 5 -o " + (s.dir / "path.csv").string());
  ASSERT_EQ(to_file.status, 0) << to_file.err;
  EXPECT_TRUE(to_file.out.empty());
  EXPECT_EQ(cli::slurp(s.dir / "path.csv"), to_stdout.out);
}

// --plot draws the path with matplotlib, or warns that it could not: the CSV is written either way.
TEST(MaterialTest, PlotOrWarning) {
  mpm::app::register_modules();
  const Scratch s("plot");
  const fs::path png = s.dir / "path.png";
  const auto r = s.run("--material linear_elastic --path cyclic_shear --steps 40 --plot " + png.string());
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(lines(r.out).size(), 42u);
  EXPECT_TRUE(fs::exists(png) || r.err.find("warning: no plot") != std::string::npos) << r.err;
}

/// Runs a bad command: exit 2, the message on stderr, nothing on stdout and no output file.
void expect_refused(const Scratch& s, const std::string& args, const std::string& message) {
  const fs::path output = s.dir / "refused.csv";
  const auto r = s.run(args + " -o " + output.string());
  EXPECT_EQ(r.status, 2) << args << "\n" << r.err;
  EXPECT_NE(r.err.find(message), std::string::npos) << "expected: " << message << "\ngot: " << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
  EXPECT_FALSE(fs::exists(output)) << args;
}

TEST(MaterialTest, UnknownMaterialAndPath) {
  mpm::app::register_modules();
  const Scratch s("names");
  expect_refused(s, "--material linear_elastc", "no material 'linear_elastc' in ");
  expect_refused(s, "--material linear_elastc", "(did you mean 'linear_elastic'?)");
  expect_refused(s, "--material linear_elastic --path triaxial", "unknown path 'triaxial'");
  expect_refused(s, "--material linear_elastic --path triaxial", "valid paths: uniaxial_strain, triaxial_compression");
  expect_refused(s, "--material rigid", "material 'rigid' is rigid (model rigid): it has no stress");
  expect_refused(s, "--material linear_elastic --path deformation_csv", "path deformation_csv needs --csv FILE");
  expect_refused(s, "--material linear_elastic --steps 0", "--steps >= 1");
}

TEST(MaterialTest, BadDeformationRowsNameFileAndLine) {
  mpm::app::register_modules();
  const Scratch s("csv");
  const std::string header = "time,F11,F12,F13,F21,F22,F23,F31,F32,F33\n";
  const auto refused = [&](const std::string& name, const std::string& rows, const std::string& message) {
    const fs::path file = s.write(name, header + rows);
    expect_refused(s, "--material linear_elastic --path deformation_csv --csv " + file.string(),
                   file.string() + ":" + message);
  };
  refused("word.csv", "0.1,1,0,0,0,1,0,0,0,1\n0.2,1,0,zero,0,1,0,0,0,1\n", "3: 'zero' is not a number");
  refused("short.csv", "# a comment\n0.1,1,0,0,0,1,0,0,0\n", "3: expected 10 values");
  refused("time.csv", "0.1,1,0,0,0,1,0,0,0,1\n0.1,1,0,0,0,1,0,0,0,1\n", "3: time 0.1 s does not increase");
  refused("inverted.csv", "0.1,-1,0,0,0,1,0,0,0,1\n", "2: det F = -1 is not positive");
  refused("start.csv", "0,2,0,0,0,1,0,0,0,1\n", "2: the path starts from F = I at t = 0");
  const fs::path empty = s.write("empty.csv", header);
  expect_refused(s, "--material linear_elastic --path deformation_csv --csv " + empty.string(),
                 empty.string() + ": no deformation rows");
  expect_refused(s, "--material linear_elastic --path deformation_csv --csv " + (s.dir / "missing.csv").string(),
                 "missing.csv: cannot open");
}

#ifdef MPM_WITH_FLUIDS
// A stress the material cannot carry: an ideal gas keeps a positive pressure at any volume, so lateral stresses held
// at zero (triaxial compression without confinement) are out of its reach: refused with the time of the step.
TEST(MaterialTest, StressOutOfReachIsRefused) {
  mpm::app::register_modules();
  const Scratch s("reach");
  expect_refused(s, "--material ideal_gas --path triaxial_compression --steps 5",
                 "the stress-controlled step at t = 0.2 s did not converge");
}
#endif

TEST(MaterialTest, BadSceneIsRefused) {
  mpm::app::register_modules();
  const Scratch s("scene");
  const fs::path bad = s.write("bad.yaml", "dimension: 2\nmaterials: {m: {model: linear_elastic}}\n");
  const auto r = cli::mpm("material-test --scene " + bad.string() + " --material m", s.dir);
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find(bad.string() + ":"), std::string::npos) << r.err;
}

}  // namespace
