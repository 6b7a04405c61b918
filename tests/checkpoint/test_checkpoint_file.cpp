// The HDF5 checkpoint file (checkpoint/): every entry comes back with its type, shape and bytes; a damaged file
// (cut short, a flipped byte, empty, not HDF5) is refused with a message naming it; writing is atomic.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>

#include "mpm/checkpoint/checkpoint_file.hpp"
#include "mpm/checkpoint/checksum.hpp"

namespace fs = std::filesystem;
using mpm::checkpoint::CheckpointError;

namespace {

fs::path scratch() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const fs::path dir =
      fs::temp_directory_path() / ("mpm_h5_" + std::string(info->name()) + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string bytes_of(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

mpm::StateArchive sample() {
  mpm::StateArchive a;
  a.put_number("simulation/time", 0.125);
  a.put_integer("simulation/step", 7);
  a.put_text("run/scene_text", "dimension: 2\ngrid: {extent: [1, 1]}\n");
  a.put_text("run/empty", "");
  std::vector<double> x(300);
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = 1.0 / static_cast<double>(i + 3);
  a.put_values<double>("bodies/disk/position", x, 3);
  a.put_values<std::uint32_t>("bodies/disk/id", std::vector<std::uint32_t>{5, 0, 9});
  a.put_values<std::int32_t>("bodies/disk/region", std::vector<std::int32_t>{-1, 2});
  a.put_values<std::int8_t>("run/warned", std::vector<std::int8_t>{1, 0});
  mpm::ArchivedArray opaque;
  opaque.type = mpm::ScalarType::opaque;
  opaque.shape = {2, 3};
  opaque.bytes = {std::byte{1}, std::byte{2}, std::byte{3}, std::byte{4}, std::byte{5}, std::byte{6}};
  a.put("bodies/disk/blob", opaque);
  return a;
}

TEST(CheckpointFile, EveryEntryComesBackExactly) {
  const fs::path dir = scratch();
  const mpm::StateArchive a = sample();
  mpm::checkpoint::write_checkpoint(dir / "c.h5", a);
  const mpm::StateArchive b = mpm::checkpoint::read_checkpoint(dir / "c.h5");
  ASSERT_EQ(b.entries().size(), a.entries().size());
  for (const auto& [name, array] : a.entries()) {
    ASSERT_TRUE(b.contains(name)) << name;
    const auto& got = b.at(name);
    EXPECT_EQ(got.bytes, array.bytes) << name;
    EXPECT_EQ(got.text, array.text) << name;
    // opaque bytes read back as uint8; a text's shape is its length
    EXPECT_EQ(got.type, array.type == mpm::ScalarType::opaque ? mpm::ScalarType::uint8 : array.type) << name;
    EXPECT_EQ(got.shape, array.shape) << name;
  }
  EXPECT_EQ(b.text("run/empty"), "");
  // Written through a temporary beside it: nothing else is left in the directory.
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
  fs::remove_all(dir);
}

TEST(CheckpointFile, DamagedFilesAreRefusedWithTheirName) {
  const fs::path dir = scratch();
  mpm::checkpoint::write_checkpoint(dir / "c.h5", sample());
  const std::string good = bytes_of(dir / "c.h5");
  auto expect_refused = [&](const std::string& content, const std::string& name, const std::string& message) {
    std::ofstream(dir / name, std::ios::binary) << content;
    try {
      mpm::checkpoint::read_checkpoint(dir / name);
      ADD_FAILURE() << name << " was read";
    } catch (const CheckpointError& e) {
      EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
    }
  };
  expect_refused(good.substr(0, good.size() / 2), "truncated.h5", "truncated or damaged");
  expect_refused("", "empty.h5", "the file is empty");
  expect_refused("dimension: 2\n", "text.h5", "not an HDF5 file");
  // A flipped byte inside the positions' values: found by the dataset's checksum.
  std::vector<double> x(300);
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = 1.0 / static_cast<double>(i + 3);
  const std::string needle(reinterpret_cast<const char*>(x.data() + 10), 16);
  const auto at = good.find(needle);
  ASSERT_NE(at, std::string::npos);
  std::string flipped = good;
  flipped[at + 3] = static_cast<char>(flipped[at + 3] ^ 0x10);
  expect_refused(flipped, "flipped.h5", "dataset 'bodies/disk/position' is corrupt");
  EXPECT_THROW(mpm::checkpoint::read_checkpoint(dir / "missing.h5"), CheckpointError);
  fs::remove_all(dir);
}

TEST(CheckpointFile, FilesOfADirectoryNewestFirst) {
  const fs::path dir = scratch();
  for (long long step : {20, 100, 3}) std::ofstream(dir / mpm::checkpoint::checkpoint_name(step)) << "x";
  std::ofstream(dir / ".checkpoint_000000200.h5.tmp-1-0") << "x";  // a write that was killed
  std::ofstream(dir / "notes.txt") << "x";
  const auto files = mpm::checkpoint::checkpoint_files(dir);
  ASSERT_EQ(files.size(), 3u);
  EXPECT_EQ(files[0].filename(), "checkpoint_000000100.h5");
  EXPECT_EQ(files[2].filename(), "checkpoint_000000003.h5");
  fs::remove_all(dir);
}

TEST(Checksum, AnyFlippedByteChangesIt) {
  std::vector<std::byte> data(100);
  for (std::size_t i = 0; i < data.size(); ++i) data[i] = static_cast<std::byte>(i * 7);
  const auto sum = mpm::checkpoint::checksum(data);
  for (std::size_t i = 0; i < data.size(); ++i)
    for (int bit = 0; bit < 8; ++bit) {
      auto changed = data;
      changed[i] ^= static_cast<std::byte>(1 << bit);
      EXPECT_NE(mpm::checkpoint::checksum(changed), sum) << i << " " << bit;
    }
  data.push_back(std::byte{0});  // a trailing zero byte too
  EXPECT_NE(mpm::checkpoint::checksum(data), sum);
  EXPECT_EQ(mpm::checkpoint::checksum_hex("abc").size(), 16u);
}

}  // namespace
