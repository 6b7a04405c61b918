// Checkpoints a restart cannot continue (exit status 2, a message naming the file, nothing overwritten): a
// missing, empty, non-HDF5, truncated or corrupted (one flipped byte) file; one of another program version; one
// of another scene; a directory without a valid checkpoint. And a checkpoint directory that cannot be written,
// refused before the first step. The empty and non-HDF5 files are fixtures (data/bad_checkpoints/); the
// others are made here from a checkpoint of a real run.
#include <gtest/gtest.h>

#include <fstream>

#include "restart_support.hpp"

namespace {

using namespace restart_support;

const fs::path fixtures = fs::path(MPM_SOURCE_DIR) / "tests" / "data" / "bad_checkpoints";

class BadCheckpoint : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = scratch("bad_checkpoint");
    std::ofstream(dir_ / "scene.yaml") << two_disks().scene;
    const Result r = cli::mpm("run " + (dir_ / "scene.yaml").string() + " -o " + (dir_ / "out").string(), dir_);
    ASSERT_EQ(r.status, 0) << r.err;
    const auto steps = checkpoint_steps(dir_ / "out" / "checkpoints");
    ASSERT_FALSE(steps.empty());
    good_ = dir_ / "out" / "checkpoints" / mpm::checkpoint::checkpoint_name(steps[0]);
    for (const auto& f : output_files(dir_ / "out")) before_[f] = slurp(dir_ / "out" / f);
  }
  void TearDown() override {
    if (!HasFailure()) fs::remove_all(dir_);
  }
  /// A restart from `from` is refused with status 2 and `message`, and leaves the output as it was.
  void expect_refused(const fs::path& from, const std::string& message, const std::string& scene = "scene.yaml") {
    const Result r = cli::mpm(
        "run " + (dir_ / scene).string() + " -o " + (dir_ / "out").string() + " --restart " + from.string(), dir_);
    EXPECT_EQ(r.status, 2) << from << "\n" << r.err;
    EXPECT_NE(r.err.find(message), std::string::npos) << from << "\n" << r.err;
    std::map<std::string, std::string> after;
    for (const auto& f : output_files(dir_ / "out")) after[f] = slurp(dir_ / "out" / f);
    EXPECT_TRUE(after == before_) << "the output changed after refusing " << from;
  }
  fs::path dir_, good_;
  std::map<std::string, std::string> before_;
};

TEST_F(BadCheckpoint, MissingEmptyOrNotHdf5) {
  expect_refused(dir_ / "nothing.h5", "nothing.h5: no such checkpoint file");
  expect_refused(fixtures / "empty.h5", "empty.h5: the file is empty, not a checkpoint");
  expect_refused(fixtures / "not_hdf5.h5", "not_hdf5.h5: not an HDF5 file");
}

TEST_F(BadCheckpoint, TruncatedOrWithAFlippedByte) {
  const std::string bytes = slurp(good_);
  std::ofstream(dir_ / "truncated.h5", std::ios::binary) << bytes.substr(0, bytes.size() * 2 / 3);
  expect_refused(dir_ / "truncated.h5", "truncated.h5: cannot open it as HDF5 (truncated or damaged");
  // One bit of one particle's position (the first 8 bytes of the dataset, found by its value).
  const auto archive = mpm::checkpoint::read_checkpoint(good_);
  const auto& x = archive.at("bodies/lower_left/position").bytes;
  const std::string needle(reinterpret_cast<const char*>(x.data()), 16);
  const auto at = bytes.find(needle);
  ASSERT_NE(at, std::string::npos);
  std::string flipped = bytes;
  flipped[at + 5] = static_cast<char>(flipped[at + 5] ^ 0x01);
  std::ofstream(dir_ / "flipped.h5", std::ios::binary) << flipped;
  expect_refused(dir_ / "flipped.h5", "flipped.h5: dataset 'bodies/lower_left/position' is corrupt");
}

TEST_F(BadCheckpoint, OfAnotherProgramVersion) {
  auto archive = mpm::checkpoint::read_checkpoint(good_);
  archive.put_text("run/program_version", "0.0.1");
  mpm::checkpoint::write_checkpoint(dir_ / "old.h5", archive);
  expect_refused(dir_ / "old.h5",
                 "old.h5: written by mpm 0.0.1 (checkpoint format 1); this is mpm " + std::string(MPM_VERSION_STRING));
}

TEST_F(BadCheckpoint, OfAnotherScene) {
  const std::string scene = two_disks().scene;
  const std::string lower_left = scene.substr(
      scene.find("  - {name: lower_left"), scene.find("  - {name: upper_right") - scene.find("  - {name: lower_left"));
  const std::string other = replaced(with_bodies(scene, lower_left), "cell_size: 0.05", "cell_size: 0.025");
  std::ofstream(dir_ / "other.yaml") << other;
  expect_refused(good_, "grid.cell_size: 0.05 in the checkpoint, 0.025 now", "other.yaml");
  expect_refused(good_, "bodies: ", "other.yaml");  // a body less: the list differs
}

TEST_F(BadCheckpoint, DirectoryWithoutAValidCheckpoint) {
  fs::create_directories(dir_ / "none");
  expect_refused(dir_ / "none", "none: no valid checkpoint in this directory");
  fs::copy_file(fixtures / "empty.h5", dir_ / "none" / mpm::checkpoint::checkpoint_name(5));
  expect_refused(dir_ / "none", mpm::checkpoint::checkpoint_name(5) + ": the file is empty");
}

TEST(CheckpointDirectory, UnwritableIsRefusedBeforeTheFirstStep) {
  const fs::path dir = scratch("checkpoint_unwritable");
  std::ofstream(dir / "scene.yaml") << with_checkpoint(
      two_disks().scene, "  checkpoint: {interval: 0.2, directory: /dev/null/checkpoints}\n");
  const Result r = cli::mpm("run " + (dir / "scene.yaml").string() + " -o " + (dir / "out").string(), dir);
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find((dir / "scene.yaml").string() + ":11:15: output.checkpoint: cannot write checkpoints to the "
                                                       "directory '/dev/null/checkpoints'"),
            std::string::npos)
      << r.err;
  EXPECT_FALSE(fs::exists(dir / "out"));  // refused before anything was written
  if (!HasFailure()) fs::remove_all(dir);
}

}  // namespace

namespace {

using namespace restart_support;

// `mpm checkpoint FILE`: what a checkpoint holds, with every checksum checked; a damaged one is refused.
TEST(CheckpointCommand, DescribesAGoodCheckpointAndRefusesADamagedOne) {
  const fs::path dir = scratch("checkpoint_command");
  std::ofstream(dir / "scene.yaml") << two_disks().scene;
  ASSERT_EQ(cli::mpm("run " + (dir / "scene.yaml").string() + " -o " + (dir / "out").string(), dir).status, 0);
  const fs::path file = dir / "out" / "checkpoints" / mpm::checkpoint::checkpoint_name(100);
  const Result r = cli::mpm("checkpoint " + file.string(), dir);
  EXPECT_EQ(r.status, 0) << r.err;
  for (const std::string part : {"every checksum matches", "time: 0.2", "step 100, 2D",
                                 "body lower_left: 112 particles; fields: ", "body upper_right: 112 particles",
                                 "stress (float64 x 4)", "id (uint32)", "output: 5 frames written"})
    EXPECT_NE(r.out.find(part), std::string::npos) << part << "\n" << r.out;
  std::string bytes = slurp(file);
  bytes.resize(bytes.size() / 2);
  std::ofstream(dir / "half.h5", std::ios::binary) << bytes;
  const Result bad = cli::mpm("checkpoint " + (dir / "half.h5").string(), dir);
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.err.find("half.h5: cannot open it as HDF5"), std::string::npos) << bad.err;
  if (!HasFailure()) fs::remove_all(dir);
}

}  // namespace
