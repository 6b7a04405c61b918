// The `mpm` program as a user meets it: exit statuses, messages naming file:line:column and key, and
// nothing written when the input is bad. Every fixture in tests/data/bad_scenes is run through both
// `mpm check` and `mpm run` (first line "# expect: <message part>", second "# line: N").
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <vtkDataArray.h>
#include <vtkPointData.h>
#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "run_mpm.hpp"

namespace fs = std::filesystem;

namespace {

using cli::block_scene;
using cli::mpm;
using cli::scratch;
using cli::slurp;

using cli::data;

TEST(Cli, HelpAndVersion) {
  const auto dir = scratch("help");
  auto r = mpm("--help", dir);
  EXPECT_EQ(r.status, 0);
  EXPECT_NE(r.out.find("run"), std::string::npos);
  EXPECT_NE(r.out.find("check"), std::string::npos);
  r = mpm("--version", dir);
  EXPECT_EQ(r.status, 0);
  EXPECT_NE(r.out.find("mpm " MPM_VERSION_STRING), std::string::npos) << r.out;
  fs::remove_all(dir);
}

TEST(Cli, BadCommandLineExitsWithTwo) {
  const auto dir = scratch("args");
  EXPECT_EQ(mpm("", dir).status, 2);
  EXPECT_EQ(mpm("frobnicate", dir).status, 2);
  auto r = mpm("run", dir);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("scene"), std::string::npos) << r.err;
  r = mpm("run " + (data / "good_scene_2d.yaml").string() + " --threads 0", dir);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--threads"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("must be > 0, got 0"), std::string::npos) << r.err;  // not a range up to 1.8e308
  EXPECT_LT(r.err.size(), 200u) << r.err;
  r = mpm("run " + (data / "good_scene_2d.yaml").string() + " --rebalance-every -1", dir);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--rebalance-every"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("must be >= 0, got -1"), std::string::npos) << r.err;
  r = mpm("run " + (data / "good_scene_2d.yaml").string() + " --end-time 1e-3x", dir);
  EXPECT_EQ(r.status, 2);
  fs::remove_all(dir);
}

TEST(Cli, MissingSceneFile) {
  const auto dir = scratch("missing");
  const auto r = mpm("check /nonexistent/scene.yaml", dir);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("/nonexistent/scene.yaml"), std::string::npos) << r.err;
  fs::remove_all(dir);
}

TEST(Cli, CheckValidScene) {
  const auto dir = scratch("check");
  const auto r = mpm("check " + (data / "good_scene_2d.yaml").string(), dir);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("valid"), std::string::npos) << r.out;
  fs::remove_all(dir);
}

// `mpm check` names the axisymmetric mode and says what its numbers are per.
TEST(Cli, CheckNamesTheAxisymmetricMode) {
  const auto dir = scratch("check_axisymmetric");
  std::ofstream(dir / "scene.yaml")
      << "dimension: 2\n"
         "grid: {coordinates: axisymmetric, extent: [1, 1], cell_size: 0.1}\n"
         "materials: {m: {model: linear_elastic, density: 1000, youngs_modulus: 1.0e6, poisson_ratio: 0.3}}\n"
         "bodies: [{material: m, shape: {type: disk, center: [0, 0.5], radius: 0.3}}]\n"
         "solver: {cfl: 0.5, end_time: 0.01}\n";
  const auto r = mpm("check " + (dir / "scene.yaml").string(), dir);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("2D axisymmetric (x = r, y = z; masses, energies and forces per full revolution)"),
            std::string::npos)
      << r.out;
  fs::remove_all(dir);
}

#if defined(MPM_WITH_PLASTICITY) && defined(MPM_WITH_FLUIDS)
// Every scene shipped in examples/ is valid (built, not run), so that a change of the scene format cannot
// leave an example behind.
TEST(Cli, EveryExampleSceneIsValid) {
  int checked = 0;
  const auto dir = scratch("examples");  // the command's stdout/stderr files go here, not into examples/
  for (const auto& folder : fs::directory_iterator(fs::path(MPM_SOURCE_DIR) / "examples")) {
    if (!folder.is_directory()) continue;
    for (const auto& entry : fs::directory_iterator(folder.path())) {
      if (entry.path().extension() != ".yaml") continue;
      // a user material needs the library its README builds: tests/user_material checks it with the test-built ones
      if (slurp(entry.path()).find("model: user") != std::string::npos) continue;
      const auto r = mpm("check " + entry.path().string(), dir);
      EXPECT_EQ(r.status, 0) << entry.path() << "\n" << r.err;
      ++checked;
    }
  }
  fs::remove_all(dir);
  EXPECT_GE(checked, 15);
}
#endif

TEST(Cli, EveryBadSceneIsRefusedAndNothingIsWritten) {
  int checked = 0;
  // bad_scenes: refused by the loader; bad_built_scenes: valid YAML refused when the simulation is built.
  std::vector<fs::path> files;
  for (const char* folder : {"bad_scenes", "bad_built_scenes"})
    for (const auto& entry : fs::directory_iterator(data / folder)) {
#ifndef MPM_WITH_PLASTICITY  // fixtures of the plasticity module's models, unknown without it
      if (entry.path().filename().string().rfind("plasticity_", 0) == 0 ||
          entry.path().filename() == "output_temperature_without_specific_heat.yaml")
        continue;
#endif
#ifndef MPM_WITH_THERMAL  // fixtures of the thermal module (section and material keys), unknown without it
      if (entry.path().filename().string().rfind("thermal_", 0) == 0) continue;
#endif
#ifndef MPM_WITH_CONTACT  // fixtures of the contact module's section, an unknown key without it
      if (entry.path().filename().string().rfind("contact_", 0) == 0) continue;
#endif
#ifndef MPM_WITH_FLUIDS  // fixtures of the fluids module's models
      if (entry.path().filename().string().rfind("fluids_", 0) == 0) continue;
#endif
#ifndef MPM_WITH_SOILS  // fixtures of the soils module's models
      if (entry.path().filename().string().rfind("soils_", 0) == 0) continue;
#endif
#ifndef MPM_WITH_IMPLICIT  // fixtures of the implicit module's scheme, unknown without it
      if (entry.path().filename().string().rfind("implicit_", 0) == 0) continue;
#endif
#ifndef MPM_WITH_CONTACT  // the implicit scheme refusing a contact section needs the section to exist
      if (entry.path().filename() == "implicit_contact.yaml") continue;
#endif
#ifndef MPM_WITH_THERMAL
      if (entry.path().filename() == "implicit_thermal.yaml") continue;
#endif
#ifndef MPM_WITH_CONTACT  // the incompressible fluid refusing a contact section needs the section to exist
      if (entry.path().filename() == "fluids_incompressible_fluid_contact.yaml") continue;
#endif
      files.push_back(entry.path());
    }
  for (const auto& file : files) {
    std::ifstream in(file);
    std::string expect_line, line_line;
    std::getline(in, expect_line);
    std::getline(in, line_line);
    ASSERT_EQ(expect_line.rfind("# expect: ", 0), 0u) << file;
    const std::string expect = expect_line.substr(10);
    const std::string location =
        file.string() + ":" + (line_line.rfind("# line: ", 0) == 0 ? line_line.substr(8) + ":" : "");
    const auto dir = scratch("bad");
    for (const std::string command : {"check", "run"}) {
      const fs::path out = dir / "out";
      // `check` has no -o option (and writes nothing): run it without. (It was also started with -o before, a
      // third process per fixture whose result went unread.)
      const auto rc = command == "check" ? mpm("check " + file.string(), dir)
                                         : mpm("run " + file.string() + " -o " + out.string(), dir);
      EXPECT_EQ(rc.status, 2) << command << " " << file << "\n" << rc.err;
      EXPECT_NE(rc.err.find(expect), std::string::npos) << command << " " << file << "\n" << rc.err;
      EXPECT_NE(rc.err.find(location), std::string::npos) << command << " " << file << "\n" << rc.err;
      EXPECT_FALSE(fs::exists(out)) << "output written for a bad scene: " << file;
    }
    fs::remove_all(dir);
    ++checked;
  }
  EXPECT_GE(checked, 50);
}

TEST(Cli, UnstableFixedTimeStepIsRefusedWithTheBound) {
  const auto dir = scratch("dt");
  std::ofstream(dir / "scene.yaml") << block_scene("dt: 0.1, end_time: 1", "[0, 0]");
  const auto r = mpm("run " + (dir / "scene.yaml").string() + " -o " + (dir / "out").string(), dir);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("scene.yaml:5:14:"), std::string::npos) << r.err;  // the line and column of `dt`
  EXPECT_NE(r.err.find("solver.dt"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("stable time step 0.0136277"), std::string::npos) << r.err;  // h/c = 0.05/3.669
  EXPECT_FALSE(fs::exists(dir / "out"));
  fs::remove_all(dir);
}

// All finite values in a .vtu (the stability guard promises no NaN in any output file).
bool all_finite(const fs::path& vtu) {
  auto reader = vtkSmartPointer<vtkXMLUnstructuredGridReader>::New();
  reader->SetFileName(vtu.c_str());
  reader->Update();
  auto* grid = reader->GetOutput();
  if (grid->GetNumberOfPoints() == 0) return false;
  for (int a = 0; a < grid->GetPointData()->GetNumberOfArrays(); ++a) {
    auto* array = grid->GetPointData()->GetArray(a);
    for (vtkIdType i = 0; i < array->GetNumberOfTuples() * array->GetNumberOfComponents(); ++i)
      if (!std::isfinite(array->GetComponent(i / array->GetNumberOfComponents(), i % array->GetNumberOfComponents())))
        return false;
  }
  return true;
}

TEST(Cli, RunWritesParaViewSeriesAndEnergyLog) {
  const auto dir = scratch("run");
  std::ofstream(dir / "scene.yaml") << block_scene("cfl: 0.5, end_time: 0.2", "[0.1, \"0.2*x\"]");
  const auto r = mpm("run " + (dir / "scene.yaml").string() + " -o " + (dir / "out").string() + " --threads 2", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("particle-updates/s"), std::string::npos) << r.out;  // the summary
  EXPECT_NE(r.out.find("relative energy change"), std::string::npos) << r.out;
  const std::string pvd = slurp(dir / "out" / "particles.pvd");
  EXPECT_NE(pvd.find("particles_000004.vtu"), std::string::npos) << pvd;  // t = 0, 0.05, ..., 0.2
  EXPECT_TRUE(all_finite(dir / "out" / "particles_000004.vtu"));
  const std::string energy = slurp(dir / "out" / "energy.csv");
  EXPECT_EQ(energy.rfind("time,step,kinetic_energy,strain_energy", 0), 0u) << energy;
  EXPECT_EQ(std::count(energy.begin(), energy.end(), '\n'), 6);  // header + 5 frames
  for (const auto& e : fs::directory_iterator(dir / "out"))
    EXPECT_EQ(e.path().filename().string().find(".tmp"), std::string::npos) << "temporary left: " << e.path();
  fs::remove_all(dir);
}

// `mpm run --profile` prints the time per phase after the summary (on stdout), for any scene.
TEST(Cli, ProfilePrintsTheTimePerPhase) {
  const auto dir = scratch("profile");
  std::ofstream(dir / "scene.yaml") << block_scene("cfl: 0.5, end_time: 0.1", "[0.1, \"0.2*x\"]");
  const auto r = mpm("run " + (dir / "scene.yaml").string() + " -o " + (dir / "out").string() + " --profile", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  const auto table = r.out.find("profile (wall time per phase");
  ASSERT_NE(table, std::string::npos) << r.out;
  for (const char* row :
       {"\nP2G ", "\ngrid update ", "\nG2P ", "\nstress update ", "\noutput ", "\nother ", "\ntotal "})
    EXPECT_NE(r.out.find(row, table), std::string::npos) << row << " in " << r.out;
  const auto plain = mpm("run " + (dir / "scene.yaml").string() + " -o " + (dir / "out2").string(), dir);
  EXPECT_EQ(plain.out.find("profile (wall time per phase"), std::string::npos) << plain.out;
  fs::remove_all(dir);
}

// The streams, as Unix tools have them (README.md, "Output streams"): a command's result on stdout, what it says on
// the way on stderr. The block at rest with end_time 1e6 s: about 3.7e7 steps, the warning of step_estimate.hpp.
std::string block_for_a_million_seconds(const fs::path& dir) {
  std::ofstream(dir / "scene.yaml") << block_scene("cfl: 0.5, end_time: 1.0e6", "[0, 0]");
  return (dir / "scene.yaml").string();
}

// `mpm run`: the summary alone on stdout (`mpm run SCENE > summary.txt` keeps it), the warning on stderr; both
// streams into one file (`> log 2>&1`, as bench/ and scripts/ capture a run) keep the log first, the summary last.
TEST(Cli, RunPrintsTheSummaryOnStdoutAndTheLogOnStderr) {
  const auto dir = scratch("streams_run");
  const std::string scene = block_for_a_million_seconds(dir);
  const std::string run = "run " + scene + " --steps 2 --profile -o " + (dir / "out").string();
  const auto r = mpm(run, dir);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out.rfind("energy sentinel: ", 0), 0u) << r.out;  // the summary's first line: nothing before it
  EXPECT_NE(r.out.find("\ndone: 2 steps to t = "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\nprofile (wall time per phase"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("warning"), std::string::npos) << r.out;
  EXPECT_NE(r.err.find("warning: " + scene + ":5:"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("solver.end_time: about"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("done:"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("profile"), std::string::npos) << r.err;
  const fs::path both = dir / "both";
  const std::string command = std::string(MPM_EXECUTABLE) + " " + run + " > " + both.string() + " 2>&1 < /dev/null";
  ASSERT_EQ(std::system(command.c_str()), 0);
  const std::string log = slurp(both);
  const auto warning = log.find("warning: "), done = log.find("done: 2 steps");
  ASSERT_NE(warning, std::string::npos) << log;
  ASSERT_NE(done, std::string::npos) << log;
  EXPECT_LT(warning, done) << log;
  fs::remove_all(dir);
}

// `mpm check`: the report on stdout, its warnings on stderr.
TEST(Cli, CheckPrintsTheReportOnStdoutAndTheWarningsOnStderr) {
  const auto dir = scratch("streams_check");
  const std::string scene = block_for_a_million_seconds(dir);
  const auto r = mpm("check " + scene, dir);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out.rfind(scene + ": valid. 2D", 0), 0u) << r.out;
  EXPECT_NE(r.out.find("\nmemory: about "), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("warning"), std::string::npos) << r.out;
  EXPECT_NE(r.err.find("warning: " + scene + ":5:"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("solver.end_time: about"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("valid."), std::string::npos) << r.err;
  fs::remove_all(dir);
}

TEST(Cli, StabilityGuardStopsTheRunAndWritesTheLastGoodState) {
  const auto dir = scratch("guard");
  // The block is thrown at 20 m/s through the +x face: it leaves the grid within 0.02 s.
  std::ofstream(dir / "scene.yaml") << block_scene("cfl: 0.5, end_time: 1", "[20, 0]");
  const auto r = mpm("run " + (dir / "scene.yaml").string() + " -o " + (dir / "out").string(), dir);
  EXPECT_EQ(r.status, 3) << r.err;
  EXPECT_NE(r.err.find("stability guard: step "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("body 'block', particle "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("field 'position'"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("last good state"), std::string::npos) << r.err;
  EXPECT_TRUE(all_finite(dir / "out" / "particles_000001.vtu"));  // frame 0 at t = 0, frame 1 = last good
  const std::string pvd = slurp(dir / "out" / "particles.pvd");
  EXPECT_NE(pvd.find("particles_000001.vtu"), std::string::npos) << pvd;
  fs::remove_all(dir);
}

#ifdef MPM_WITH_THERMAL
TEST(Cli, ThermalSceneSaysWhichTimeStepBoundGovernsAndWritesTheHeat) {
  // examples/10_heat_plate: the diffusion bound governs and the log says so; the energy log has the thermal
  // energy, the particle files the temperature and heat flux, the grid files the nodal temperature.
  const auto dir = scratch("thermal");
  const auto scene = fs::path(MPM_SOURCE_DIR) / "examples" / "10_heat_plate" / "plate.yaml";
  const auto check = mpm("check " + scene.string(), dir);
  EXPECT_EQ(check.status, 0) << check.err;
  EXPECT_NE(check.out.find("heat conduction (diffusion bound"), std::string::npos) << check.out;
  const auto r = mpm("run " + scene.string() + " -o " + (dir / "out").string(), dir);
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string& log = r.err;  // the time-step note is the run's log, not its summary
  EXPECT_NE(log.find("time step: 0.0005 s, stable bound 0.000625 s governed by heat conduction"), std::string::npos)
      << log;
  std::ifstream energy(dir / "out" / "energy.csv");
  std::string header;
  std::getline(energy, header);
  EXPECT_NE(header.find("plastic_work,thermal_energy"), std::string::npos) << header;
  EXPECT_TRUE(fs::exists(dir / "out" / "particles_grid_000005.vti"));
  fs::remove_all(dir);
}
#endif

}  // namespace
