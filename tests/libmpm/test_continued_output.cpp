// Output a restart continues (io/continued_file.hpp, CsvLog's continuing constructor, PvdCollection::frames),
// the in-memory state archive, and particle files read back (io/particle_file.hpp).
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "mpm/core/state_archive.hpp"
#include "mpm/io/continued_file.hpp"
#include "mpm/io/csv_log.hpp"
#include "mpm/io/particle_file.hpp"
#include "mpm/io/pvd_collection.hpp"
#include "mpm/io/vtk_writer.hpp"

namespace fs = std::filesystem;

namespace {

class ContinuedOutput : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ =
        fs::temp_directory_path() / ("mpm_continued_" + std::string(info->name()) + "_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  static std::string read(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
  }
  static void write(const fs::path& p, const std::string& text) { std::ofstream(p, std::ios::binary) << text; }
  fs::path dir_;
};

TEST_F(ContinuedOutput, ContinueFileCutsTheRowsAfterTheMark) {
  const fs::path file = dir_ / "forces.csv";
  write(file, "time,f\n0.1,1\n");
  const mpm::io::FileMark mark = mpm::io::mark_file(file);
  EXPECT_EQ(mark.bytes, 13u);
  EXPECT_TRUE(mark.path.is_absolute());
  write(file, "time,f\n0.1,1\n0.2,2\n0.3,3\n");  // rows written after the checkpoint
  mpm::io::continue_file(mark, file);
  EXPECT_EQ(read(file), "time,f\n0.1,1\n");
  // A fork into another directory gets the rows up to the mark, and the original file is untouched.
  write(file, "time,f\n0.1,1\n0.2,2\n");
  mpm::io::continue_file(mark, dir_ / "fork" / "forces.csv");
  EXPECT_EQ(read(dir_ / "fork" / "forces.csv"), "time,f\n0.1,1\n");
  EXPECT_EQ(read(file), "time,f\n0.1,1\n0.2,2\n");
  // Nothing written at the checkpoint: the file goes.
  mpm::io::continue_file({file, 0}, file);
  EXPECT_FALSE(fs::exists(file));
  // A file shorter than its mark, or gone, cannot be continued (its rows before the checkpoint are lost).
  write(file, "time");
  EXPECT_THROW(mpm::io::continue_file(mark, file), std::runtime_error);
  fs::remove(file);
  EXPECT_THROW(mpm::io::continue_file(mark, file), std::runtime_error);
}

TEST_F(ContinuedOutput, CsvLogContinuesWithTheSameBytesAsAnUninterruptedOne) {
  const std::vector<std::string> columns{"time", "energy"};
  mpm::io::CsvLog whole(dir_ / "whole.csv", columns);
  mpm::io::CsvLog cut(dir_ / "cut.csv", columns);
  for (const double t : {0.0, 0.1, 1.0 / 3}) {
    whole.append({t, t * t + 1e-17});
    cut.append({t, t * t + 1e-17});
  }
  const mpm::io::FileMark mark = cut.mark();
  cut.append({0.5, 7});  // written after the checkpoint, then the run dies
  mpm::io::CsvLog resumed(dir_ / "cut.csv", columns, mark);
  for (const double t : {0.5, 0.75}) {
    whole.append({t, t * t + 1e-17});
    resumed.append({t, t * t + 1e-17});
  }
  EXPECT_EQ(read(dir_ / "cut.csv"), read(dir_ / "whole.csv"));
  EXPECT_THROW(mpm::io::CsvLog(dir_ / "cut.csv", {"time", "other"}, resumed.mark()), std::runtime_error);
}

TEST_F(ContinuedOutput, CsvLogContinuesATableWithEmptyCells) {
  const std::vector<std::string> columns{"time", "value", "count"};
  mpm::io::CsvLog cut(dir_ / "cut.csv", columns);
  cut.append({0.0, mpm::io::no_data(), 0});
  cut.append({0.1, 2.5, 1});
  mpm::io::CsvLog resumed(dir_ / "cut.csv", columns, cut.mark());
  resumed.append({0.2, mpm::io::no_data(), 0});
  EXPECT_EQ(read(dir_ / "cut.csv"), "time,value,count\n0,,0\n0.10000000000000001,2.5,1\n0.20000000000000001,,0\n");
  // a cell that is neither a number nor empty is still refused
  std::ofstream(dir_ / "bad.csv") << "time,value,count\n0,x,0\n";
  EXPECT_THROW(mpm::io::CsvLog(dir_ / "cut.csv", columns, mpm::io::mark_file(dir_ / "bad.csv")), std::runtime_error);
}

TEST_F(ContinuedOutput, PvdFramesComeBackAsAbsolutePaths) {
  mpm::io::PvdCollection pvd(dir_ / "particles.pvd");
  pvd.add(0.5, dir_ / "frames" / "particles_000001.vtu");
  const auto frames = pvd.frames();
  ASSERT_EQ(frames.size(), 1u);
  EXPECT_EQ(frames[0].first, 0.5);
  EXPECT_EQ(frames[0].second, (dir_ / "frames" / "particles_000001.vtu").lexically_normal());
}

TEST(StateArchive, EntriesKeepTypeShapeAndBytes) {
  mpm::StateArchive a;
  a.put_number("simulation/time", 0.1);
  a.put_integer("simulation/step", 42);
  a.put_text("run/scene", "dimension: 2\n");
  const std::vector<std::uint32_t> ids{3, 1, 2};
  a.put_values<std::uint32_t>("bodies/disk/id", ids);
  const std::vector<double> x{1, 2, 3, 4, 5, 6};
  a.put_values<double>("bodies/disk/position", x, 2);
  a.put_values<double>("bodies/plate/position", x, 3);
  EXPECT_EQ(a.number("simulation/time"), 0.1);
  EXPECT_EQ(a.integer("simulation/step"), 42);
  EXPECT_EQ(a.text("run/scene"), "dimension: 2\n");
  EXPECT_EQ(a.values<std::uint32_t>("bodies/disk/id"), ids);
  EXPECT_EQ(a.at("bodies/disk/position").shape, (std::vector<std::uint64_t>{3, 2}));
  EXPECT_EQ(a.children("bodies/"), (std::vector<std::string>{"disk", "plate"}));
  EXPECT_EQ(a.children("bodies/disk/"), (std::vector<std::string>{"id", "position"}));
  EXPECT_EQ(a.bytes(), 8u + 8u + 13u + 12u + 48u + 48u);
  EXPECT_THROW(a.values<double>("bodies/disk/id"), mpm::ArchiveError);  // another type
  EXPECT_THROW(a.number("simulation/missing"), mpm::ArchiveError);
  mpm::ArchivedArray bad;
  bad.shape = {2};
  bad.bytes.resize(3);
  EXPECT_THROW(a.put("bad", bad), std::invalid_argument);
}

TEST_F(ContinuedOutput, ParticleFilesFromVtuAndCsv) {
  mpm::io::PointCloud cloud;
  cloud.points = {0.1, 0.2, 0, 0.3, 0.4, 0};
  cloud.fields = {{"volume", 1, {1e-4, 2e-4}}, {"velocity", 3, {1, 2, 0, 3, 4, 0}}};
  mpm::io::write_vtu(dir_ / "p.vtu", cloud);
  const auto vtu = mpm::io::read_particle_file(dir_ / "p.vtu");
  EXPECT_EQ(vtu.cloud.points, cloud.points);
  ASSERT_NE(vtu.field("velocity"), nullptr);
  EXPECT_EQ(vtu.field("velocity")->values, cloud.fields[1].values);
  EXPECT_EQ(vtu.row(1), (dir_ / "p.vtu").string() + ": point 1");

  write(dir_ / "p.csv",
        "x,y,volume,velocity_x,velocity_y,stress_xx,stress_yy,stress_zz,stress_xy,stress_yz,stress_xz\n"
        "0.1,0.2,1e-4,1,2,-1,-2,-3,0.5,0,0\n"
        "\n"
        "0.3,+0.4,2e-4,3,4,0,0,0,0,0,0\n");
  const auto csv = mpm::io::read_particle_file(dir_ / "p.csv");
  EXPECT_EQ(csv.cloud.points, cloud.points);
  EXPECT_EQ(csv.field("volume")->values, cloud.fields[0].values);
  ASSERT_NE(csv.field("velocity"), nullptr);
  EXPECT_EQ(csv.field("velocity")->components, 3);
  EXPECT_EQ(csv.field("velocity")->values, cloud.fields[1].values);
  EXPECT_EQ(csv.field("stress")->components, 6);
  EXPECT_EQ(csv.field("stress")->values[3], 0.5);
  EXPECT_EQ(csv.row(1), (dir_ / "p.csv").string() + ":4");  // the blank line counts

  write(dir_ / "nan.csv", "x,y,volume\n0.1,0.2,nan\n");
  try {
    mpm::io::read_particle_file(dir_ / "nan.csv");
    FAIL() << "a NaN volume was read";
  } catch (const mpm::io::ParticleFileError& e) {
    EXPECT_NE(std::string(e.what()).find("nan.csv:2: column 'volume'"), std::string::npos) << e.what();
  }
  write(dir_ / "short.csv", "x,y,volume\n0.1,0.2\n");
  EXPECT_THROW(mpm::io::read_particle_file(dir_ / "short.csv"), mpm::io::ParticleFileError);
  write(dir_ / "nox.csv", "a,b\n1,2\n");
  EXPECT_THROW(mpm::io::read_particle_file(dir_ / "nox.csv"), mpm::io::ParticleFileError);
  write(dir_ / "not.vtu", "hello");
  EXPECT_THROW(mpm::io::read_particle_file(dir_ / "not.vtu"), mpm::io::ParticleFileError);
}

}  // namespace
