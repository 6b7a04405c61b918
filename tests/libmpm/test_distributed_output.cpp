// The output of a distributed run on one process (docs/distributed.md, "Output of a distributed run"): a
// SerialCommunicator writes the very files of no communicator; the .pvtu summary reads back with its pieces as
// one data set; and, with a stand-in communicator whose other ranks fail or succeed as told, one rank of a larger
// run writes only its piece and throws when any rank failed. The MPI runs are tests/distributed/.
#include <gtest/gtest.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLPUnstructuredGridReader.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <stdexcept>
#include <string>

#include "mpm/io/collective_write.hpp"
#include "mpm/io/pvtu_writer.hpp"
#include "mpm/output/output_writer.hpp"
#include "mpm/parallel/communicator.hpp"
#include "scene_fixture.hpp"

namespace mpm {
namespace {

namespace fs = std::filesystem;

const std::string block_scene =
    "dimension: 2\n"
    "grid: {origin: [0, 0], extent: [1, 1], cell_size: 0.125}\n"
    "materials: {m: {model: linear_elastic, density: 1000, youngs_modulus: 1.0e5, poisson_ratio: 0.3}}\n"
    "bodies: [{material: m, shape: {type: box, min: [0.25, 0.25], max: [0.75, 0.5]}, velocity: [\"x\", \"-y\"]}]\n"
    "solver: {scheme: usl, shape_function: cpgimp, cfl: 0.5, end_time: 1}\n"
    "output: {fields: [velocity, stress, domains]}\n";

std::map<std::string, std::string> files_of(const fs::path& dir) {
  std::map<std::string, std::string> files;
  for (const auto& entry : fs::recursive_directory_iterator(dir)) {
    if (!entry.is_regular_file()) continue;
    std::ifstream in(entry.path(), std::ios::binary);
    files[fs::relative(entry.path(), dir).string()] =
        std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  return files;
}

fs::path fresh_directory(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / name;
  fs::remove_all(dir);
  return dir;
}

// Null and a one-rank communicator: the same files, byte for byte, and the names of a one-process run (no .pvtu).
TEST(DistributedOutput, SerialCommunicatorWritesTheFilesOfNoCommunicator) {
  auto sim = test::simulation_from_yaml<2>(block_scene);
  const fs::path plain = fresh_directory("mpm_distributed_output_plain");
  const fs::path serial = fresh_directory("mpm_distributed_output_serial");
  SerialCommunicator one;
  const std::vector<std::string> fields = {"velocity", "stress", "domains"};
  OutputWriter<2> a(plain, "p", fields, true, 0);
  OutputWriter<2> b(serial, "p", fields, true, 0, nullptr, &one);
  for (auto* w : {&a, &b}) w->set_field_data({{{"scene", "block <&> \"quoted\""}}, {{"threads", 1}}});
  for (int frame = 0; frame < 3; ++frame) {
    if (frame > 0) sim->advance(sim->next_time_step());
    a.write(*sim);
    b.write(*sim);
  }
  const auto expected = files_of(plain);
  const auto written = files_of(serial);
  ASSERT_EQ(expected.size(), 13u);  // 3 frames x (particles, domains, grid), 3 .pvd, energy.csv
  EXPECT_TRUE(expected.count("p_000002.vtu") && expected.count("p_domains_000002.vtu") &&
              expected.count("p_grid_000002.vti") && expected.count("energy.csv"));
  ASSERT_EQ(written.size(), expected.size());
  for (const auto& [name, bytes] : expected) {
    ASSERT_TRUE(written.count(name)) << name;
    EXPECT_TRUE(written.at(name) == bytes) << name << " differs";
  }
  fs::remove_all(plain);
  fs::remove_all(serial);
}

io::FieldArray field(const std::string& name, int components, std::vector<double> values,
                     std::vector<std::string> component_names = {}) {
  return {name, components, std::move(values), std::move(component_names)};
}

// Three pieces, the middle one empty, and their summary: one data set with every point in piece order, every
// array with its components and component names, the pieces' field data.
TEST(DistributedOutput, PvtuReadsBackThePiecesAsOneDataSet) {
  const fs::path dir = fresh_directory("mpm_distributed_output_pvtu");
  fs::create_directories(dir);
  const fs::path pvtu = dir / "p_000004.pvtu";
  EXPECT_EQ(io::pvtu_piece_path(pvtu, 2), dir / "p_000004" / "p_000004_2.vtu");
  const std::vector<std::size_t> counts = {3, 0, 2};
  io::PvtuSummary summary;
  double next_id = 0;
  for (int rank = 0; rank < 3; ++rank) {
    io::PointCloud cloud;
    std::vector<double> stress, velocity, id;
    for (std::size_t i = 0; i < counts[rank]; ++i) {
      for (const double x : {next_id, 2 * next_id, 0.0}) cloud.points.push_back(x);
      for (int c = 0; c < 6; ++c) stress.push_back(10 * next_id + c);
      for (int c = 0; c < 3; ++c) velocity.push_back(-next_id - 0.5 * c);
      id.push_back(next_id++);
    }
    cloud.fields = {field("stress", 6, stress), field("velocity", 3, velocity, io::cylindrical_component_names(3)),
                    field("id", 1, id)};
    cloud.field_data.numbers = {{"TIME", 0.25}, {"step", 7}};
    const fs::path piece = io::pvtu_piece_path(pvtu, rank);
    fs::create_directories(piece.parent_path());
    io::write_vtu(piece, cloud);
    summary.point_fields = cloud.fields;
    summary.pieces.push_back(piece);
  }
  summary.field_data.numbers = {{"TIME", 0.25}, {"step", 7}};
  summary.field_data.text = {{"scene", "a <b> & 'c'\n"}};
  io::write_pvtu(pvtu, summary);
  const std::string text = files_of(dir).at("p_000004.pvtu");
  EXPECT_NE(text.find("<Piece Source=\"p_000004/p_000004_1.vtu\"/>"), std::string::npos) << text;

  vtkNew<vtkXMLPUnstructuredGridReader> reader;
  reader->SetFileName(pvtu.c_str());
  reader->Update();
  vtkUnstructuredGrid* grid = reader->GetOutput();
  ASSERT_EQ(grid->GetNumberOfPoints(), 5);
  vtkDataArray* stress = grid->GetPointData()->GetArray("stress");
  vtkDataArray* velocity = grid->GetPointData()->GetArray("velocity");
  vtkDataArray* id = grid->GetPointData()->GetArray("id");
  ASSERT_TRUE(stress && velocity && id);
  EXPECT_EQ(stress->GetNumberOfComponents(), 6);
  EXPECT_STREQ(stress->GetComponentName(3), "XY");
  EXPECT_STREQ(velocity->GetComponentName(2), "theta");
  for (vtkIdType i = 0; i < 5; ++i) {
    EXPECT_EQ(id->GetComponent(i, 0), static_cast<double>(i));
    EXPECT_EQ(stress->GetComponent(i, 5), 10.0 * i + 5);
    EXPECT_EQ(velocity->GetComponent(i, 1), -i - 0.5);
    EXPECT_EQ(grid->GetPoint(i)[1], 2.0 * i);
  }
  vtkDataArray* time = grid->GetFieldData()->GetArray("TIME");
  ASSERT_TRUE(time);
  EXPECT_EQ(time->GetComponent(0, 0), 0.25);

  summary.pieces.clear();
  EXPECT_THROW(io::write_pvtu(dir / "none.pvtu", summary), std::invalid_argument);
  summary.pieces = {io::pvtu_piece_path(pvtu, 0)};
  summary.point_fields.push_back(field("id", 1, {}));
  EXPECT_THROW(io::write_pvtu(dir / "twice.pvtu", summary), std::invalid_argument);
  EXPECT_FALSE(fs::exists(dir / "none.pvtu") || fs::exists(dir / "twice.pvtu"));
  fs::remove_all(dir);
}

/// One rank of a run of `size`, in one process: the reductions see this rank's value and, as the other ranks',
/// `others_failing_rank` (size(): none fails).
class StandInCommunicator final : public Communicator {
 public:
  StandInCommunicator(int rank, int size) : others_failing_rank(size), rank_(rank), size_(size) {}
  int rank() const override { return rank_; }
  int size() const override { return size_; }
  void sum(std::span<ExactSum>) override {}
  void max(std::span<double>) override {}
  void min(std::span<double> values) override {
    ++reductions;
    values[0] = std::min(values[0], static_cast<double>(others_failing_rank));
  }
  bool any(bool flag) override { return flag || others_failing_rank < size_; }
  void sum(std::span<std::int64_t>) override {}
  void exchange(std::span<const Outgoing>, std::span<const Incoming>) override {}
  std::vector<std::vector<std::byte>> all_to_all(std::vector<std::vector<std::byte>> out) override { return out; }
  void broadcast(std::vector<std::byte>&, int) override {}
  void barrier() override {}
  [[noreturn]] void abort(int) override { throw std::logic_error("abort"); }
  int others_failing_rank;
  int reductions = 0;

 private:
  int rank_, size_;
};

TEST(DistributedOutput, CollectiveWriteFailsOnEveryRankWhenOneFails) {
  StandInCommunicator comm(1, 3);
  io::write_collectively(&comm, "nothing", [] {});
  EXPECT_EQ(comm.reductions, 1);
  try {  // this rank fails: its own message
    io::write_collectively(&comm, "frame 2", [] { throw std::runtime_error("disk full"); });
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "frame 2 failed on rank 1: disk full");
  }
  comm.others_failing_rank = 2;  // another rank fails: this one stops too and names it
  try {
    io::write_collectively(&comm, "frame 2", [] {});
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "frame 2 failed on rank 2 (its message is in that rank's output); rank 1 stops too");
  }
  EXPECT_EQ(comm.reductions, 3);
  // One process: the write's own exception, no reduction.
  SerialCommunicator one;
  EXPECT_THROW(io::write_collectively(&one, "x", [] { throw std::out_of_range("x"); }), std::out_of_range);
  EXPECT_THROW(io::write_collectively(nullptr, "x", [] { throw std::out_of_range("x"); }), std::out_of_range);
}

// Rank 1 of 2 writes its pieces only (rank 0 writes the .pvtu, the .pvd files and energy.csv); when the other
// rank fails, its write throws and the frame is not counted. Its part of a checkpoint is the output schedule only.
// (A grid output is gathered on rank 0: ctest distributed_example_10_heat_plate_np3.)
TEST(DistributedOutput, ANonZeroRankWritesItsPieceOnly) {
  auto sim = test::simulation_from_yaml<2>(block_scene);
  const fs::path dir = fresh_directory("mpm_distributed_output_rank1");
  StandInCommunicator comm(1, 2);
  OutputWriter<2> writer(dir, "p", {"velocity", "domains"}, false, 0, nullptr, &comm);
  writer.write(*sim);
  const auto files = files_of(dir);
  ASSERT_EQ(files.size(), 2u);
  EXPECT_TRUE(files.count("p_000000/p_000000_1.vtu"));
  EXPECT_TRUE(files.count("p_domains_000000/p_domains_000000_1.vtu"));
  EXPECT_EQ(writer.frames(), 1);
  sim->advance(sim->next_time_step());
  comm.others_failing_rank = 0;
  EXPECT_THROW(writer.write(*sim), std::runtime_error);
  EXPECT_EQ(writer.frames(), 1);
  // A checkpoint: this rank keeps the schedule; the files' marks are rank 0's (it writes the checkpoint).
  StateArchive archive;
  writer.save_state(archive);
  EXPECT_EQ(archive.integer("output/frame"), 1);
  EXPECT_FALSE(archive.contains("output/energy/bytes"));
  EXPECT_FALSE(archive.contains("output/particles_pvd/times"));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace mpm
