// Bodies seeded from particle files (`shape: {particles: FILE}`): a run seeded from the first frame of its own
// output reproduces that run bit for bit (the frame holds positions, volumes, velocities, stresses, masses and
// ids, which is the whole initial state); a CSV seeds a body with the velocities it gives.
#include <gtest/gtest.h>

#include <fstream>

#include "restart_support.hpp"

namespace {

using namespace restart_support;

TEST(ParticleFileBody, SeededFromItsOwnFirstFrameReproducesTheRun) {
  const fs::path dir = scratch("particle_file_own_frame");
  const std::string scene = replaced(with_checkpoint(two_disks().scene, ""), "fields: [velocity, stress, body]",
                                     "fields: [velocity, stress, mass, volume, body]");
  std::ofstream(dir / "original.yaml") << scene;
  ASSERT_EQ(cli::mpm("run " + (dir / "original.yaml").string() + " -o " + (dir / "original").string(), dir).status, 0);
  const std::string frame = (dir / "original" / "particles_000000.vtu").string();
  const std::string seeded = with_bodies(
      scene, "  - {name: lower_left, material: elastic, shape: {particles: " + frame + ", body: 0}}\n" +
                 "  - {name: upper_right, material: elastic, shape: {particles: " + frame + ", body: 1}}\n");
  std::ofstream(dir / "seeded.yaml") << seeded;
  const Result r = cli::mpm("run " + (dir / "seeded.yaml").string() + " -o " + (dir / "seeded").string(), dir);
  ASSERT_EQ(r.status, 0) << r.err;
  const auto files = output_files(dir / "original");
  EXPECT_EQ(output_files(dir / "seeded"), files);
  EXPECT_GE(files.size(), 10u);
  expect_same_files(dir / "original", dir / "seeded");
  if (!HasFailure()) fs::remove_all(dir);
}

TEST(ParticleFileBody, CsvGivesPositionsVolumesAndVelocities) {
  const fs::path dir = scratch("particle_file_csv");
  const fs::path csv = fs::path(MPM_SOURCE_DIR) / "tests" / "data" / "particles" / "block.csv";
  std::ofstream(dir / "scene.yaml")
      << "dimension: 2\n"
         "grid: {extent: [1, 1], cell_size: 0.1}\n"
         "materials: {m: {model: linear_elastic, density: 1000, youngs_modulus: 1.0e4, poisson_ratio: 0.3}}\n"
         "bodies: [{name: block, material: m, shape: {particles: "
      << csv.string()
      << "}}]\n"
         "solver: {dt: 1.0e-3, end_time: 1.0e-3}\n";
  const Result r = cli::mpm("run " + (dir / "scene.yaml").string() + " -o " + (dir / "out").string(), dir);
  ASSERT_EQ(r.status, 0) << r.err;
  // Four particles of 0.0025 m^2 at 1000 kg/m^3 moving at 1 m/s: kinetic energy 4 x 0.5 x 2.5 x 1 = 5 J/m at t = 0.
  std::ifstream energy(dir / "out" / "energy.csv");
  std::string header, first;
  std::getline(energy, header);
  std::getline(energy, first);
  EXPECT_EQ(first.substr(0, first.find(',', first.find(',') + 1) + 2), "0,0,5");
  if (!HasFailure()) fs::remove_all(dir);
}

}  // namespace
