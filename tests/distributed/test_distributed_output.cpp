// The output of a distributed run (docs/distributed.md, "Output of a distributed run"), started by ctest under
// `mpirun -np K` (K = 1, 2, 3) with the directory to write as argument; check_distributed_output.py then reads
// the files back with VTK. Every rank builds the same block of particles and, for each frame, keeps only its
// share (rank r of K holds the ids i with i % K == r; with K >= 3 the last rank holds none, so that an empty
// piece is written): the Simulation a rank of the distributed engine will hold. Rank 0 also writes the whole
// block with a one-process writer (DIR/serial) as the reference the .pvtu files must read back to.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "mpm/distributed/mpi_communicator.hpp"
#include "mpm/io/pvtu_writer.hpp"
#include "mpm/output/output_writer.hpp"
#include "run_on_every_rank.hpp"
#include "scene_fixture.hpp"

namespace {

namespace fs = std::filesystem;
using mpm::OutputWriter;
using mpm::Simulation;

mpm::distributed::MpiCommunicator* world = nullptr;
fs::path root;  // argv[1]

const std::string block_scene =
    "dimension: 2\n"
    "grid: {origin: [0, 0], extent: [1, 1], cell_size: 0.0625}\n"
    "materials: {m: {model: linear_elastic, density: 1000, youngs_modulus: 1.0e5, poisson_ratio: 0.3}}\n"
    "bodies: [{material: m, shape: {type: box, min: [0.25, 0.25], max: [0.75, 0.5]}, velocity: [\"x\", \"-y\"]},\n"
    "         {material: m, shape: {type: box, min: [0.25, 0.625], max: [0.5, 0.75]}}]\n"
    "solver: {scheme: usl, shape_function: cpgimp, cfl: 0.5, end_time: 1}\n";
const std::vector<std::string> fields = {"velocity", "stress", "mass", "deformation_gradient", "body", "domains"};

int owner(std::uint32_t id, int size) {
  return size >= 3 ? static_cast<int>(id % static_cast<std::uint32_t>(size - 1))
                   : static_cast<int>(id % static_cast<std::uint32_t>(size));
}

/// Writes a frame of this rank's share of `sim` (the other particles are put back afterwards, also on failure).
void write_share(OutputWriter<2>& writer, Simulation<2>& sim) {
  std::vector<mpm::ParticleSet<2>> whole;
  for (auto& body : sim.bodies()) {
    whole.push_back(body.particles);
    std::vector<mpm::Index> mine;
    for (mpm::Index i = 0; i < body.particles.size(); ++i)
      if (owner(body.particles.id[i], world->size()) == world->rank()) mine.push_back(i);
    body.particles.gather(mine);
  }
  auto restore = [&] {
    for (std::size_t b = 0; b < whole.size(); ++b) sim.bodies()[b].particles = whole[b];
  };
  try {
    writer.write(sim);
  } catch (...) {
    restore();
    throw;
  }
  restore();
}

std::string text_of(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Three frames of the moving block: pieces, .pvtu, .pvd, energy.csv (read back by check_distributed_output.py).
TEST(DistributedOutput, ThreeFramesOfPiecesAndTheirSummaries) {
  auto sim = mpm::test::simulation_from_yaml<2>(block_scene);
  OutputWriter<2> writer(root / "run", "particles", fields, false, 0, nullptr, world);
  writer.set_field_data({{{"scene", "block.yaml"}}, {{"ranks", world->size()}}});
  std::unique_ptr<OutputWriter<2>> serial;
  if (world->rank() == 0) {
    serial = std::make_unique<OutputWriter<2>>(root / "serial", "particles", fields, false, 0);
    serial->set_field_data({{{"scene", "block.yaml"}}, {{"ranks", world->size()}}});
  }
  for (int frame = 0; frame < 3; ++frame) {
    if (frame > 0) sim->advance(sim->next_time_step());
    write_share(writer, *sim);
    if (serial) serial->write(*sim);
  }
  EXPECT_EQ(writer.frames(), 3);
  world->barrier();
  const bool pieces = world->size() > 1;
  for (int frame = 0; frame < 3 && pieces; ++frame) {
    const fs::path pvtu = root / "run" / fmt::format("particles_{:06d}.pvtu", frame);
    EXPECT_TRUE(fs::exists(mpm::io::pvtu_piece_path(pvtu, world->rank()))) << frame;
    EXPECT_EQ(fs::exists(pvtu), true);
  }
  if (world->rank() == 0) {
    EXPECT_TRUE(fs::exists(root / "run" / "energy.csv"));
  }
}

// Frame 2 cannot be written on rank 1 (its piece's name is taken by a directory): every rank's write throws, the
// .pvd files end at frame 1, frame 2 has no .pvtu and energy.csv no row for it.
TEST(DistributedOutput, AnUnwritablePieceOnOneRankStopsEveryRank) {
  if (world->size() < 2) GTEST_SKIP() << "needs two ranks";
  auto sim = mpm::test::simulation_from_yaml<2>(block_scene);
  const fs::path dir = root / "fault";
  OutputWriter<2> writer(dir, "particles", fields, false, 0, nullptr, world);
  for (int frame = 0; frame < 2; ++frame) {
    if (frame > 0) sim->advance(sim->next_time_step());
    write_share(writer, *sim);
  }
  sim->advance(sim->next_time_step());
  if (world->rank() == 1) fs::create_directories(mpm::io::pvtu_piece_path(dir / "particles_000002.pvtu", 1));
  world->barrier();
  try {
    write_share(writer, *sim);
    ADD_FAILURE() << "rank " << world->rank() << ": no exception";
  } catch (const std::runtime_error& e) {
    std::fprintf(stderr, "rank %d: %s\n", world->rank(), e.what());
  }
  EXPECT_EQ(writer.frames(), 2);
  world->barrier();
  if (world->rank() == 0) {
    const std::string pvd = text_of(dir / "particles.pvd");
    EXPECT_NE(pvd.find("particles_000001.pvtu"), std::string::npos) << pvd;
    EXPECT_EQ(pvd.find("particles_000002"), std::string::npos) << pvd;
    EXPECT_EQ(text_of(dir / "particles_domains.pvd").find("particles_domains_000002"), std::string::npos);
    EXPECT_FALSE(fs::exists(dir / "particles_000002.pvtu"));
    EXPECT_FALSE(fs::exists(dir / "particles_domains_000002.pvtu"));
    const std::string energy = text_of(dir / "energy.csv");
    EXPECT_EQ(std::count(energy.begin(), energy.end(), '\n'), 3) << energy;  // the header and frames 0, 1
  }
}

// The output directory cannot be created on rank 1 (a file is in its way): every rank's constructor throws.
TEST(DistributedOutput, AnUncreatableDirectoryOnOneRankStopsEveryRank) {
  if (world->size() < 2) GTEST_SKIP() << "needs two ranks";
  fs::path dir = root / "unmade";
  if (world->rank() == 1) {
    std::ofstream(root / "a_file") << "in the way\n";
    dir = root / "a_file" / "unmade";
  }
  try {
    OutputWriter<2> writer(dir, "particles", fields, false, 0, nullptr, world);
    ADD_FAILURE() << "rank " << world->rank() << ": no exception";
  } catch (const std::runtime_error& e) {
    std::fprintf(stderr, "rank %d: %s\n", world->rank(), e.what());
  }
}

}  // namespace

int main(int argc, char** argv) {
  mpm::distributed::MpiCommunicator communicator(&argc, &argv);
  world = &communicator;
  ::testing::InitGoogleTest(&argc, argv);
  if (argc != 2) {
    std::fprintf(stderr, "usage: test_distributed_output DIRECTORY\n");
    return 2;
  }
  root = argv[1];
  if (communicator.rank() == 0) fs::create_directories(root);
  communicator.barrier();
  return mpm::test::run_on_every_rank(communicator);
}
