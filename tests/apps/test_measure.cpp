// What users measure, through the program: histories written with units (per-body energies summing to
// energy.csv), self-describing output (the field data of every .vtu, view.py), `mpm diff` and the command line
// of `mpm verify` (its numbers are checked in verification/test_verify.cpp).
#include <gtest/gtest.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkSmartPointer.h>
#include <vtkStringArray.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "../libmpm/two_disks_scene.hpp"
#include "run_mpm.hpp"

namespace fs = std::filesystem;

namespace {

using cli::mpm;
using cli::scratch;
using cli::slurp;

/// Two elastic disks colliding under gravity above a fixed floor, with histories.
const std::string disks = mpm::test::two_disks_scene(R"(    - {name: energy_a, type: energy, body: a}
    - {name: energy_b, type: energy, body: b}
    - {name: front, type: extent, body: a, axis: x}
    - {name: corner, type: probe, box: {min: [0.9, 0.9], max: [1.0, 1.0]}, fields: [velocity]}
)");

struct Csv {
  std::vector<std::string> columns;
  std::vector<std::vector<double>> rows;
  double at(std::size_t row, const std::string& column) const {
    for (std::size_t k = 0; k < columns.size(); ++k)
      if (columns[k] == column) return rows[row][k];
    ADD_FAILURE() << "no column " << column;
    return 0;
  }
};

Csv read_csv(const fs::path& file) {
  Csv csv;
  std::ifstream in(file);
  std::string line, cell;
  std::getline(in, line);
  std::stringstream header(line);
  while (std::getline(header, cell, ',')) csv.columns.push_back(cell);
  while (std::getline(in, line)) {
    std::stringstream s(line);
    std::vector<double> row;
    while (std::getline(s, cell, ',')) row.push_back(std::stod(cell));
    csv.rows.push_back(row);
  }
  return csv;
}

TEST(Histories, WrittenWithUnitsAndBodiesSumToEnergyCsv) {
  const auto dir = scratch("histories");
  std::ofstream(dir / "disks.yaml") << disks;
  const auto r = mpm("run " + (dir / "disks.yaml").string() + " -o " + (dir / "out").string(), dir);
  ASSERT_EQ(r.status, 0) << r.err;
  // The empty region is warned about, once, naming the history.
  EXPECT_NE(r.err.find("warning: output.histories[3]: history 'corner': no particle"), std::string::npos) << r.err;
  const Csv a = read_csv(dir / "out" / "energy_a.csv"), b = read_csv(dir / "out" / "energy_b.csv"),
            all = read_csv(dir / "out" / "energy.csv");
  EXPECT_EQ(a.columns[0], "time [s]");
  EXPECT_EQ(a.columns[2], "kinetic_energy [J/m]");
  ASSERT_EQ(a.rows.size(), all.rows.size());  // one row per frame: 0, 0.01, ..., 0.1
  EXPECT_EQ(a.rows.size(), 11u);
  for (std::size_t k = 0; k < a.rows.size(); ++k) {
    EXPECT_EQ(a.rows[k][0], all.rows[k][0]);
    for (const auto& [history, audit] : std::vector<std::pair<std::string, std::string>>{
             {"kinetic_energy [J/m]", "kinetic_energy"},
             {"strain_energy [J/m]", "strain_energy"},
             {"gravity_potential_energy [J/m]", "gravity_potential_energy"},
             {"total_energy [J/m]", "total_energy"},
             {"momentum_x [kg m/s/m]", "momentum_x"},
             {"mass [kg/m]", "mass"}}) {
      const double sum = a.at(k, history) + b.at(k, history), expected = all.at(k, audit);
      EXPECT_NEAR(sum, expected, 1e-13 * (std::abs(expected) + std::abs(a.at(k, history)))) << history << " row " << k;
    }
  }
  EXPECT_GT(all.at(10, "strain_energy"), 0);  // the disks have met
  const Csv front = read_csv(dir / "out" / "front.csv");
  EXPECT_EQ(front.columns,
            (std::vector<std::string>{"time [s]", "step", "x_min [m]", "x_max [m]", "x_span [m]", "count [-]"}));
  EXPECT_GT(front.at(10, "x_max [m]"), front.at(0, "x_max [m]") + 0.05);
  // The empty region writes no data, empty cells, and its count (never a 0 that reads like a measurement).
  std::ifstream corner(dir / "out" / "corner.csv");
  std::string line;
  std::getline(corner, line);
  std::getline(corner, line);
  EXPECT_EQ(line, "0,0,,,,,,,0");  // time, step, the mean, min and max of velocity_x and _y, count
  // `check` builds the histories too: the same warning, on standard error (its report on standard output).
  const auto c = mpm("check " + (dir / "disks.yaml").string(), dir);
  EXPECT_EQ(c.status, 0);
  EXPECT_EQ(c.err.rfind("warning: ", 0), 0u) << c.err;
  EXPECT_NE(c.err.find("history 'corner': no particle"), std::string::npos) << c.err;
  EXPECT_NE(c.out.find(": valid."), std::string::npos) << c.out;
  EXPECT_EQ(c.out.find("warning"), std::string::npos) << c.out;
  fs::remove_all(dir);
}

vtkSmartPointer<vtkUnstructuredGrid> read_vtu(const fs::path& file) {
  auto reader = vtkSmartPointer<vtkXMLUnstructuredGridReader>::New();
  reader->SetFileName(file.c_str());
  reader->Update();
  return reader->GetOutput();
}

std::string text_of(vtkFieldData* data, const char* name) {
  auto* a = vtkStringArray::SafeDownCast(data->GetAbstractArray(name));
  return a ? a->GetValue(0) : "(missing)";
}
double number_of(vtkFieldData* data, const char* name) {
  auto* a = vtkDoubleArray::SafeDownCast(data->GetAbstractArray(name));
  return a ? a->GetValue(0) : std::nan("");
}

TEST(SelfDescribingOutput, FieldDataAndViewScript) {
  const auto dir = scratch("describe");
  std::ofstream(dir / "disks.yaml") << disks;
  const auto r = mpm(
      "run " + (dir / "disks.yaml").string() + " -o " + (dir / "out").string() + " --threads 1 --end-time 0.05", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  for (const auto& [file, time] :
       std::vector<std::pair<std::string, double>>{{"particles_000000.vtu", 0.0}, {"particles_000005.vtu", 0.05}}) {
    auto grid = read_vtu(dir / "out" / file);
    vtkFieldData* data = grid->GetFieldData();
    EXPECT_EQ(text_of(data, "scene"), disks) << file;
    EXPECT_EQ(text_of(data, "scene_file"), (dir / "disks.yaml").string());
    EXPECT_EQ(text_of(data, "program"), std::string("mpm ") + MPM_VERSION_STRING);
    EXPECT_NE(text_of(data, "commit"), "(missing)");
    EXPECT_FALSE(text_of(data, "commit").empty());
    EXPECT_NE(text_of(data, "overrides").find("solver.end_time: 0.05"), std::string::npos)
        << text_of(data, "overrides");
    EXPECT_EQ(number_of(data, "threads"), 1.0);
    EXPECT_EQ(number_of(data, "ranks"), 1.0);
    EXPECT_NEAR(number_of(data, "TIME"), time, 1e-9) << file;
    EXPECT_GE(number_of(data, "step"), time > 0 ? 1.0 : 0.0);
  }
  // view.py: valid Python that opens the series by a path relative to itself and colours by von Mises.
  // (pvpython is not installed here: the script is compiled, not run.)
  const std::string view = slurp(dir / "out" / "view.py");
  EXPECT_NE(view.find("os.path.join(here, \"particles.pvd\")"), std::string::npos) << view;
  EXPECT_NE(view.find("(\"POINTS\", \"von_mises_stress\")"), std::string::npos);
  EXPECT_NE(view.find("GaussianRadius = 0.0125"), std::string::npos);  // half of 0.05 / 2
  EXPECT_NE(view.find("InteractionMode = \"2D\""), std::string::npos);
  if (fs::exists("/usr/bin/python3")) {
    EXPECT_EQ(std::system(("/usr/bin/python3 -m py_compile " + (dir / "out" / "view.py").string()).c_str()), 0);
  }
  fs::remove_all(dir);
}

TEST(Diff, EqualForAnyThreadCountDifferentWhenTheSceneChanges) {
  const auto dir = scratch("diff");
  std::ofstream(dir / "disks.yaml") << disks;
  std::string faster = disks;
  faster.replace(faster.find("velocity: [1, 0.2]"), 18, "velocity: [1.1, 0.2]");
  std::ofstream(dir / "faster.yaml") << faster;
  const std::string scene = (dir / "disks.yaml").string();
  ASSERT_EQ(mpm("run " + scene + " --threads 1 -o " + (dir / "one").string(), dir).status, 0);
  ASSERT_EQ(mpm("run " + scene + " --threads 2 -o " + (dir / "two").string(), dir).status, 0);
  ASSERT_EQ(mpm("run " + (dir / "faster.yaml").string() + " -o " + (dir / "faster").string(), dir).status, 0);
  const auto same = mpm("diff " + (dir / "one").string() + " " + (dir / "two").string(), dir);
  EXPECT_EQ(same.status, 0) << same.out << same.err;  // bit-identical for any thread count
  EXPECT_NE(same.out.find("equal:"), std::string::npos) << same.out;
  const auto changed = mpm("diff " + (dir / "one").string() + " " + (dir / "faster").string(), dir);
  EXPECT_EQ(changed.status, 1) << changed.out << changed.err;
  EXPECT_NE(changed.out.find("velocity"), std::string::npos) << changed.out;
  EXPECT_NE(changed.out.find("energy_a.csv"), std::string::npos) << changed.out;
  EXPECT_NE(changed.out.find("different:"), std::string::npos) << changed.out;
  // A loose enough tolerance accepts it (the largest difference is in the stress, about 3e4 Pa; a relative
  // tolerance does not do, as the total momentum_x of run one is 0 up to round-off).
  EXPECT_EQ(mpm("diff " + (dir / "one").string() + " " + (dir / "faster").string() + " --tolerance 1", dir).status, 1);
  // The faster disks take shorter steps (the CFL step counts |v|), so their frames fall on other step times: only
  // the first is at the same time. Paired within half the output interval (--time-tolerance 0.5), every frame
  // meets its counterpart.
  const auto loose = mpm("diff " + (dir / "one").string() + " " + (dir / "faster").string() + " --absolute 1e6", dir);
  EXPECT_EQ(loose.status, 1) << loose.out;
  EXPECT_NE(loose.out.find("particles.pvd: in A only, t = "), std::string::npos) << loose.out;
  EXPECT_EQ(
      mpm("diff " + (dir / "one").string() + " " + (dir / "faster").string() + " --absolute 1e6 --time-tolerance 0.5",
          dir)
          .status,
      0);
  const auto missing = mpm("diff " + (dir / "one").string() + " " + (dir / "nowhere").string(), dir);
  EXPECT_EQ(missing.status, 2);
  EXPECT_NE(missing.err.find("is not a directory"), std::string::npos) << missing.err;
  fs::remove_all(dir);
}

// Frames are paired by time, not by number: a run writing every 0.01 s and one writing every 0.0125 s of the same
// scene (the same steps) meet at t = 0, 0.05 and 0.1 s, where they are equal; the other times are named as having
// no partner. By number, frame 1 (t = 0.01 s) met frame 1 (t = 0.0125 s) and the velocities "differed".
TEST(Diff, PairsFramesByTimeAndNamesTheTimesWithoutAPartner) {
  const auto dir = scratch("diff_by_time");
  std::ofstream(dir / "every_10ms.yaml") << disks;
  std::string coarser = disks;
  coarser.replace(coarser.find("interval: 0.01\n"), 15, "interval: 0.0125\n");
  std::ofstream(dir / "every_12.5ms.yaml") << coarser;
  ASSERT_EQ(mpm("run " + (dir / "every_10ms.yaml").string() + " -o " + (dir / "a").string(), dir).status, 0);
  ASSERT_EQ(mpm("run " + (dir / "every_12.5ms.yaml").string() + " -o " + (dir / "b").string(), dir).status, 0);
  const auto r = mpm("diff " + (dir / "a").string() + " " + (dir / "b").string(), dir);
  EXPECT_EQ(r.status, 1) << r.out << r.err;  // the runs hold other times: not equal
  // 11 frames against 9, 3 of them at common times
  EXPECT_NE(r.out.find("(8 times of A and 6 of B without a partner: below)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("particles.pvd: in A only, t = "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("particles.pvd: in B only, t = "), std::string::npos) << r.out;
  // every field of the common frames, and of energy.csv's common rows, is equal: its row ends in "-"
  std::istringstream lines(r.out);
  int rows = 0;
  for (std::string line; std::getline(lines, line);) {
    if (!(line.starts_with("particles.pvd ") || line.starts_with("energy.csv ")) || line.find("(times)") != line.npos)
      continue;
    ++rows;
    EXPECT_TRUE(line.ends_with(" -")) << line;
  }
  EXPECT_GE(rows, 6) << r.out;  // (time), (coordinates), velocity, stress, ... and energy.csv's columns
  EXPECT_NE(r.out.find("velocity"), std::string::npos) << r.out;
  // the first time of A without a partner: its frame after t = 0.01 s (the first step past it)
  EXPECT_NE(r.out.find("in A only, t = 0.01"), std::string::npos) << r.out;
  const auto negative = mpm("diff " + (dir / "a").string() + " " + (dir / "b").string() + " --time-tolerance -1", dir);
  EXPECT_EQ(negative.status, 2);
  EXPECT_NE(negative.err.find("--time-tolerance: must be >= 0, got -1"), std::string::npos) << negative.err;
  fs::remove_all(dir);
}

// A table's wall-time columns (the implicit scheme's solver.csv: wall_seconds and its parts, named *_seconds) are
// not results: mpm diff skips them and compares every other column.
TEST(Diff, SkipsTheWallTimeColumn) {
  const auto dir = scratch("diff_wall");
  for (const char* run : {"a", "b", "c"}) fs::create_directories(dir / run);
  const std::string header = "step,newton_iterations,wall_seconds,residual_seconds\n";
  std::ofstream(dir / "a" / "solver.csv") << header << "1,4,0.0123,0.01\n2,5,0.0456,0.04\n";
  std::ofstream(dir / "b" / "solver.csv") << header << "1,4,0.0987,0.09\n2,5,0.0654,0.06\n";
  std::ofstream(dir / "c" / "solver.csv") << header << "1,4,0.0123,0.01\n2,6,0.0456,0.04\n";
  const auto same = mpm("diff " + (dir / "a").string() + " " + (dir / "b").string(), dir);
  EXPECT_EQ(same.status, 0) << same.out << same.err;
  const auto other = mpm("diff " + (dir / "a").string() + " " + (dir / "c").string(), dir);
  EXPECT_EQ(other.status, 1) << other.out << other.err;
  EXPECT_NE(other.out.find("newton_iterations"), std::string::npos) << other.out;
  fs::remove_all(dir);
}

TEST(Diff, ComparesCellsWithNoData) {
  const auto dir = scratch("diff_no_data");
  for (const char* run : {"a", "b", "c"}) fs::create_directories(dir / run);
  const std::string header = "time [s],step,x [m],count [-]\n";
  std::ofstream(dir / "a" / "tip.csv") << header << "0,0,0.5,1\n0.1,10,,0\n0.2,20,,\n";
  std::ofstream(dir / "b" / "tip.csv") << header << "0,0,0.5,1\n0.1,10,,0\n0.2,20,,\n";
  std::ofstream(dir / "c" / "tip.csv") << header << "0,0,0.5,1\n0.1,10,0,0\n0.2,20,,0\n";
  const auto same = mpm("diff " + (dir / "a").string() + " " + (dir / "b").string(), dir);
  EXPECT_EQ(same.status, 0) << same.out << same.err;
  const auto other = mpm("diff " + (dir / "a").string() + " " + (dir / "c").string(), dir);
  EXPECT_EQ(other.status, 1) << other.out << other.err;
  EXPECT_NE(other.out.find("(no data in A)"), std::string::npos) << other.out;
  EXPECT_NE(other.out.find("count"), std::string::npos) << other.out;  // the last cell, empty in A, 0 in C
  fs::remove_all(dir);
}

TEST(VerifyCommand, AQuantityWithNoDataIsRefused) {
  const auto dir = scratch("verify_no_data");
  std::ofstream(dir / "disks.yaml") << disks;
  const auto r = mpm("verify " + (dir / "disks.yaml").string() +
                         " --refine 2 --order 1 --quantity "
                         "corner.velocity_x_mean -o " +
                         (dir / "v").string(),
                     dir);
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("--quantity corner.velocity_x_mean: history 'corner' has no data at t = 0.1 s"),
            std::string::npos)
      << r.err;
  fs::remove_all(dir);
}

TEST(VerifyCommand, BadQuantitiesAreRefusedBeforeAnyRun) {
  const auto dir = scratch("verify_bad");
  std::ofstream(dir / "disks.yaml") << disks;
  const std::string scene = (dir / "disks.yaml").string();
  struct Case {
    std::string args, message;
  };
  for (const auto& c : std::vector<Case>{
           {"--quantity floor.force_y", "the scene has no history 'floor'; its histories: energy_a, energy_b"},
           {"--quantity front.x_maximum",
            "history 'front' has no column 'x_maximum'; its columns: x_min, x_max, x_span, count"},
           {"--quantity front", "expected HISTORY.COLUMN[@TIME]"},
           {"--quantity front.x_max@0.5", "t = 0.5 s is after the scene's end_time 0.1 s"},
           {"--quantity front.x_max@0.05:0.01", "the start must come before the end"},
           {"--refine 2 --quantity front.x_max", "two runs give no observed order; give --order P"},
           {"--ratio 1 --quantity front.x_max", "the refinement ratio must be > 1"}}) {
    const auto r = mpm("verify " + scene + " " + c.args + " -o " + (dir / "v").string(), dir);
    EXPECT_EQ(r.status, 2) << c.args << "\n" << r.err;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << c.args << "\n" << r.err;
    EXPECT_FALSE(fs::exists(dir / "v" / "verify.md")) << c.args;
  }
  fs::remove_all(dir);
}

TEST(VerifyCommand, WritesTheReportAndThePlot) {
  const auto dir = scratch("verify");
  std::string scene = disks;  // shorter, coarser: three quick runs
  scene.replace(scene.find("end_time: 0.1"), 13, "end_time: 0.02");
  scene.replace(scene.find("cell_size: 0.05"), 15, "cell_size: 0.1");
  std::ofstream(dir / "disks.yaml") << scene;
  const auto r =
      mpm("verify " + (dir / "disks.yaml").string() + " --quantity front.x_max@0:0.02 -o " + (dir / "v").string(), dir);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("front.x_max@0:0.02: "), std::string::npos) << r.out;
  const std::string md = slurp(dir / "v" / "verify.md");
  EXPECT_NE(md.find("| 3 | 40 × 40 | 0.025 |"), std::string::npos) << md;
  EXPECT_NE(md.find("the change from t = 0 s to t = 0.02 s"), std::string::npos) << md;
  EXPECT_TRUE(fs::exists(dir / "v" / "verify_runs.csv"));
  EXPECT_TRUE(fs::exists(dir / "v" / "run_1" / "front.csv"));
  if (fs::exists("/usr/bin/python3") &&
      std::system("/usr/bin/python3 -c 'import matplotlib' > /dev/null 2>&1") == 0) {  // Debian's python3-matplotlib
    EXPECT_TRUE(fs::exists(dir / "v" / "verify.png")) << slurp(dir / "v" / "plot_verify.log");
    EXPECT_NE(md.find("![value against h"), std::string::npos);
  }
  // --finest: the scene (10 x 10 cells of 0.1 m) is the last run, the others coarser by 2 and 4 (rounded to
  // whole cells per axis: 3 x 3 and 5 x 5).
  const auto f = mpm("verify " + (dir / "disks.yaml").string() + " --finest --no-plot --quantity front.x_max -o " +
                         (dir / "f").string(),
                     dir);
  ASSERT_EQ(f.status, 0) << f.err;
  const std::string finest = slurp(dir / "f" / "verify.md");
  EXPECT_NE(finest.find("| 1 | 3 × 3 |"), std::string::npos) << finest;
  EXPECT_NE(finest.find("| 2 | 5 × 5 | 0.2 |"), std::string::npos) << finest;
  EXPECT_NE(finest.find("| 3 | 10 × 10 | 0.1 |"), std::string::npos) << finest;
  EXPECT_NE(finest.find("--finest"), std::string::npos) << finest;
  fs::remove_all(dir);
}

}  // namespace
