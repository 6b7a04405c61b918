// The plausibility warnings of a built scene (apps/plausibility.hpp): each rule fires on the slip it is for, with
// the key and the likely unit, and stays silent on the correct scene; no example scene trips one; `mpm check` and
// `mpm run` print them as warnings, never as errors.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "../libmpm/scene_fixture.hpp"
#include "mpm/app/plausibility.hpp"
#include "mpm/app/scene_builder.hpp"
#include "run_mpm.hpp"

namespace {

namespace fs = std::filesystem;
using mpm::test::fill;

/// The plausibility warnings of the 2D scene `yaml`, joined by newlines.
std::string warnings_of(const std::string& yaml) {
  const auto sim = mpm::test::simulation_from_yaml<2>(yaml, "scene.yaml");
  const auto scene = mpm::parse_scene(yaml, "scene.yaml");
  std::string text;
  for (const auto& w : mpm::app::plausibility_warnings<2>(scene, *sim)) text += w + "\n";
  return text;
}

/// One body of @MATERIAL@ (a disk of radius 0.2 m at rest in a unit box of 0.05 m cells) to @END@ s.
const std::string one_disk = R"(dimension: 2
grid: {origin: [0, 0], extent: [1, 1], cell_size: 0.05}
materials:
  steel: @MATERIAL@
bodies:
  - {name: disk, material: steel, shape: {type: disk, center: [0.5, 0.5], radius: 0.2}}
solver: {cfl: 0.5, end_time: @END@}
)";

std::string disk_of(const std::string& material, const std::string& end = "1.0e-3") {
  return fill(one_disk, {{"MATERIAL", material}, {"END", end}});
}

std::string elastic(const std::string& density, const std::string& modulus = "2.0e11") {
  return "{model: linear_elastic, density: " + density + ", youngs_modulus: " + modulus + ", poisson_ratio: 0.3}";
}

// Rule 1 -----------------------------------------------------------------------------------------------------------

TEST(Plausibility, ASolidDensityInGramsPerCubicCentimetreNamesTheUnit) {
  const std::string w = warnings_of(disk_of(elastic("7.83")));
  EXPECT_NE(w.find("scene.yaml:4:"), std::string::npos) << w;  // at the density, in the line of the material
  EXPECT_NE(w.find("materials.steel.density: density 7.83 kg/m^3 is far below any solid's"), std::string::npos) << w;
  EXPECT_NE(w.find("g/cm^3? (7830 kg/m^3: write `7.83 g/cm^3`)"), std::string::npos) << w;
}

TEST(Plausibility, ASolidDensityInTonnesPerCubicMillimetreNamesTheUnit) {
  const std::string w = warnings_of(disk_of(elastic("7.83e-9", "2.1e5")));  // the mm-t-s system's density and MPa
  EXPECT_NE(w.find("t/mm^3? (7830 kg/m^3"), std::string::npos) << w;
}

TEST(Plausibility, ASolidDenserThanOsmiumWarns) {
  const std::string w = warnings_of(disk_of(elastic("7.83e6")));
  EXPECT_NE(w.find("density 7830000 kg/m^3 is above any solid's"), std::string::npos) << w;
  EXPECT_NE(w.find("g/m^3? (7830 kg/m^3"), std::string::npos) << w;
}

TEST(Plausibility, SteelAFoamAndAConsistentlyScaledSolidAreSilent) {
  EXPECT_EQ(warnings_of(disk_of(elastic("7830"))), "");
  // 10 kg/m^3 beside 5 kPa (examples/03): waves at 22 m/s, a foam or a scene in scaled units.
  EXPECT_EQ(warnings_of(disk_of(elastic("10", "5.0e3"), "1.0")), "");
}

#ifdef MPM_WITH_FLUIDS
TEST(Plausibility, LiquidAndGasDensitiesHaveTheirOwnRanges) {
  const std::string water = "{model: newtonian_fluid, density: @RHO@, bulk_modulus: 2.2e9}";
  const std::string air = "{model: ideal_gas, density: @RHO@, initial_pressure: 101325}";
  const std::string wet = warnings_of(disk_of(fill(water, {{"RHO", "1"}})));
  EXPECT_NE(wet.find("density 1 kg/m^3 is outside any liquid's"), std::string::npos) << wet;
  EXPECT_NE(wet.find("g/cm^3? (1000 kg/m^3"), std::string::npos) << wet;
  EXPECT_EQ(warnings_of(disk_of(fill(water, {{"RHO", "1000"}}))), "");
  const std::string thin = warnings_of(disk_of(fill(air, {{"RHO", "0.0012"}}), "1.0e-4"));
  EXPECT_NE(thin.find("density 0.0012 kg/m^3 is outside what a gas has"), std::string::npos) << thin;
  EXPECT_NE(thin.find("g/cm^3? (1.2 kg/m^3"), std::string::npos) << thin;
  EXPECT_EQ(warnings_of(disk_of(fill(air, {{"RHO", "1.2"}}), "1.0e-4")), "");
}
#endif

// Rule 2 -----------------------------------------------------------------------------------------------------------

#ifdef MPM_WITH_PLASTICITY
std::string j2(const std::string& modulus, const std::string& yield, const std::string& density = "7830") {
  return "{model: j2_plasticity, density: " + density + ", youngs_modulus: " + modulus +
         ", poisson_ratio: 0.3, yield_stress: " + yield + "}";
}

TEST(Plausibility, AYieldStressAboveTheModulusNamesTheModulusUnit) {
  const std::string w = warnings_of(disk_of(j2("200.0e3", "792e6")));
  EXPECT_NE(w.find("materials.steel.youngs_modulus: a yield stress (7.92e+08 Pa) above the Young's modulus (200000 "
                   "Pa): the material can never yield"),
            std::string::npos)
      << w;
  EXPECT_NE(w.find("MPa? (200000 MPa = 2e+11 Pa: write `200000 MPa`)"), std::string::npos) << w;
  EXPECT_EQ(w.find("far below"), std::string::npos) << w;  // one warning for one slip
}

TEST(Plausibility, AnElasticPlasticModulusInGigapascalsWrittenAsPascalsWarns) {
  const std::string w = warnings_of(disk_of(j2("200", "0.5")));
  EXPECT_NE(w.find("materials.steel.youngs_modulus: the Young's modulus (200 Pa) is far below any elastic-plastic"),
            std::string::npos)
      << w;
  EXPECT_NE(w.find("GPa? (2e+11 Pa: write `200 GPa`)"), std::string::npos) << w;
}

TEST(Plausibility, SteelAndAConsistentlyScaledMetalAreSilent) {
  EXPECT_EQ(warnings_of(disk_of(j2("200.0e9", "792e6"))), "");
  // examples/18's units: density 8.824, moduli about 100 (the whole scene scaled).
  EXPECT_EQ(warnings_of(disk_of("{model: hencky_j2, density: 8.824, bulk_modulus: 133.3, shear_modulus: 43.3, "
                                "yield_stress: 10}",
                                "1.0")),
            "");
}
#endif

// Rule 3 -----------------------------------------------------------------------------------------------------------

/// Two bodies of elastic steel, shapes @A@ and @B@, particles per cell @PA@ and @PB@.
const std::string two_bodies = R"(dimension: 2
grid: {origin: [0, 0], extent: [1, 1], cell_size: 0.05}
materials:
  steel: {model: linear_elastic, density: 7830, youngs_modulus: 2.0e11, poisson_ratio: 0.3}
bodies:
  - {name: a, material: steel, shape: @A@, particles_per_cell: @PA@}
  - {name: b, material: steel, shape: @B@, particles_per_cell: @PB@}
solver: {cfl: 0.5, end_time: 1.0e-3}
)";

std::string two(const std::string& a, const std::string& b, const std::string& pa = "2", const std::string& pb = "2") {
  return warnings_of(fill(two_bodies, {{"A", a}, {"B", b}, {"PA", pa}, {"PB", pb}}));
}

TEST(Plausibility, OverlappingBodiesAreNamedWithTheCount) {
  // Two boxes on the same lattice sharing a strip 0.05 m wide: 2 columns of 12 particles of 'a' (0.025 m spacing)
  // lie on particles of 'b'.
  const std::string w =
      two("{type: box, min: [0.2, 0.2], max: [0.5, 0.5]}", "{type: box, min: [0.45, 0.2], max: [0.8, 0.5]}");
  EXPECT_NE(w.find("scene.yaml:7:5: bodies[1]: bodies 'a' and 'b' overlap at t = 0: 24 of the 144 particles of 'a'"),
            std::string::npos)
      << w;
  // Two disks, one inside the other's half.
  const std::string disks =
      two("{type: disk, center: [0.4, 0.5], radius: 0.2}", "{type: disk, center: [0.55, 0.5], radius: 0.2}", "2", "3");
  EXPECT_NE(disks.find("bodies 'a' and 'b' overlap at t = 0"), std::string::npos) << disks;
}

TEST(Plausibility, BodiesThatTouchAreSilent) {
  EXPECT_EQ(two("{type: box, min: [0.2, 0.2], max: [0.5, 0.5]}", "{type: box, min: [0.5, 0.2], max: [0.8, 0.5]}"), "");
  EXPECT_EQ(
      two("{type: box, min: [0.2, 0.2], max: [0.5, 0.5]}", "{type: box, min: [0.5, 0.2], max: [0.8, 0.5]}", "2", "3"),
      "");
  // Tangent disks, and a disk resting on a box.
  EXPECT_EQ(
      two("{type: disk, center: [0.3, 0.5], radius: 0.2}", "{type: disk, center: [0.7, 0.5], radius: 0.2}", "4", "3"),
      "");
  EXPECT_EQ(
      two("{type: disk, center: [0.5, 0.5], radius: 0.2}", "{type: box, min: [0.1, 0.1], max: [0.9, 0.3]}", "3", "2"),
      "");
}

// Rule 4 -----------------------------------------------------------------------------------------------------------

TEST(Plausibility, AnEndTimeBeforeAnyWaveCrossesACellWarns) {
  const std::string w = warnings_of(disk_of(elastic("7830"), "2.5e-8"));
  EXPECT_NE(w.find("solver.end_time: end_time = 2.5e-08 s ends before any wave crosses a cell (0.05 m) or 1 % of a "
                   "body"),
            std::string::npos)
      << w;
}

TEST(Plausibility, AnEndTimeOfMoreThanAHundredThousandCrossingsWarns) {
  // c = sqrt(E (1 - nu) / ((1 + nu)(1 - 2 nu)) / rho) = 5864 m/s across the particles' 0.375 m and a spacing,
  // 0.4 m: 6.82e-5 s; 25 s is 3.66e5 crossings.
  const std::string w = warnings_of(disk_of(elastic("7830"), "25"));
  EXPECT_NE(w.find("solver.end_time: end_time = 25 s is 3.66e+05 times the 6.82e-05 s a wave takes to cross body "
                   "'disk'"),
            std::string::npos)
      << w;
  EXPECT_NE(w.find("write `end_time: 25 us`"), std::string::npos) << w;
}

TEST(Plausibility, TheEndTimeIsNotBlamedForAMaterialsSlip) {
  // 7.83 kg/m^3 beside 2e11 Pa: waves at 1.85e5 m/s cross the disk 1.2e7 times in 25 s; the density is named, the end
  // time is not.
  const std::string w = warnings_of(disk_of(elastic("7.83"), "25"));
  EXPECT_NE(w.find("materials.steel.density"), std::string::npos) << w;
  EXPECT_EQ(w.find("solver.end_time"), std::string::npos) << w;
}

TEST(Plausibility, AnEndTimeOfAFewCrossingsIsSilent) {
  EXPECT_EQ(warnings_of(disk_of(elastic("7830"), "1.0e-4")), "");
  EXPECT_EQ(warnings_of(disk_of(elastic("7830"), "5.0")), "");  // 7.3e4 crossings
}

// Every example, every good scene of the tests ------------------------------------------------------------------------

TEST(Plausibility, NoExampleSceneWarns) {
  mpm::app::register_modules();
  int scenes = 0;
  std::vector<fs::path> files{cli::data / "good_scene_2d.yaml", cli::data / "good_scene_3d.yaml"};
  for (const auto& dir : fs::directory_iterator(fs::path(MPM_SOURCE_DIR) / "examples"))
    if (dir.is_directory())
      for (const auto& file : fs::directory_iterator(dir.path()))
        // a user material needs the library its README builds (tests/user_material runs it with the test-built ones)
        if (file.path().extension() == ".yaml" && cli::slurp(file.path()).find("model: user") == std::string::npos)
          files.push_back(file.path());
  for (const auto& file : files) {
    const auto scene = mpm::load_scene(file);
    std::vector<std::string> warnings;
    switch (scene.dimension) {
      case 1:
        warnings = mpm::app::plausibility_warnings<1>(scene, *mpm::app::build_simulation<1>(scene));
        break;
      case 2:
        warnings = mpm::app::plausibility_warnings<2>(scene, *mpm::app::build_simulation<2>(scene));
        break;
      default:
        warnings = mpm::app::plausibility_warnings<3>(scene, *mpm::app::build_simulation<3>(scene));
    }
    for (const auto& w : warnings) ADD_FAILURE() << w;
    ++scenes;
  }
  EXPECT_GT(scenes, 30);
}

// The program --------------------------------------------------------------------------------------------------------

TEST(Plausibility, CheckAndRunPrintTheWarningsAndCarryOn) {
  const auto dir = cli::scratch("plausibility");
  const fs::path scene = dir / "scene.yaml";
  std::ofstream(scene) << disk_of(elastic("7.83"), "2.0e-5");
  const auto check = cli::mpm("check " + scene.string(), dir);
  EXPECT_EQ(check.status, 0) << check.err;
  // warnings on standard error, the report on standard output (README, "Output streams")
  EXPECT_NE(check.err.find("warning: " + scene.string() + ":4:"), std::string::npos) << check.err;
  EXPECT_NE(check.err.find("g/cm^3? (7830 kg/m^3"), std::string::npos) << check.err;
  const auto run = cli::mpm("run " + scene.string() + " --steps 1 -o " + (dir / "out").string(), dir);
  EXPECT_EQ(run.status, 0) << run.err;
  EXPECT_NE(run.err.find("g/cm^3? (7830 kg/m^3"), std::string::npos) << run.out << run.err;
  fs::remove_all(dir);
}

}  // namespace
