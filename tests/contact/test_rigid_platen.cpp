// A rigid platen (a body of rigid particles with a prescribed velocity, review Alg. 4) compresses an
// elastic block standing on a frictionless rigid floor (a contact plane). Quasi-static reference: uniaxial
// stress in plane strain, sigma_yy = E / (1 - nu^2) eps_yy, so the reaction per unit thickness is
// F = E / (1 - nu^2) (delta / H) W. Also checks that the rigid particles keep their velocity and zero
// stress, and that the reaction on the platen and on the floor are written to the CSV.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "contact_scene_support.hpp"
#include "mpm/scene/scene_loader.hpp"

namespace mpm::test {
namespace {

const std::string platen = R"(
dimension: 2
grid: {origin: [0, -0.04], extent: [0.4, 0.24], cell_size: 0.01}
materials:
  rubber: {model: linear_elastic, density: 1000, youngs_modulus: 1.0e6, poisson_ratio: 0.3}
  steel: {model: rigid, density: 7800}
bodies:
  - {name: block, material: rubber, shape: {type: box, min: [0.1, 0.0], max: [0.3, 0.1]}, particles_per_cell: 2}
  - {name: platen, material: steel, shape: {type: box, min: [0.05, 0.1], max: [0.35, 0.12]}, particles_per_cell: 2}
solver: {scheme: musl, shape_function: linear, flip_fraction: 0, cfl: 0.4, end_time: 0.2}
contact:
  rigid_bodies: [{body: platen, velocity: ["0", "-0.01"]}]
  planes: [{name: floor, point: [0, 0], normal: [0, 1]}]
  force_file: platen_forces.csv
  force_interval: 0.01
output: {directory: @DIR@}
)";

TEST(RigidPlaten, ReactionFollowsTheElasticStiffness) {
  const auto dir = std::filesystem::path(MPM_BINARY_DIR) / "tests" / "contact_platen_output";
  std::filesystem::remove_all(dir);
  auto sim = simulation_from_yaml<2>(fill(platen, {{"DIR", dir.string()}}));
  auto* contact = contact_module(*sim);
  ASSERT_NE(contact, nullptr);
  const double E = 1e6, nu = 0.3, H = 0.1, W = 0.2, v = 0.01;
  sim->run();
  double platen_force = 0;
  for (const auto& f : contact->last_forces())
    if (f.body == 0 && f.other == 1) platen_force = f.normal;  // on the block from the platen
  // The platen first closes the gap between its lowest particles and the block's top nodes (contact is
  // detected at the shared nodes, half a cell early): the compression is measured from the platen travel
  // since the first contact.
  const double delta = v * (sim->time() - contact->onset_time());
  const double expected = E / (1 - nu * nu) * (delta / H) * W;
  std::printf("[ measured ] platen: onset %.4f s, travel since %.3e m, force %.2f N/m (quasi-static %.2f)\n",
              contact->onset_time(), delta, platen_force, expected);
  EXPECT_NEAR(platen_force, expected, 0.1 * expected);
  // The rigid particles move exactly with the platen and carry no stress.
  const auto& p = sim->bodies()[1].particles;
  for (Index i = 0; i < p.size(); ++i) {
    EXPECT_NEAR(p.v[i][1], -v, 1e-12);
    EXPECT_EQ(p.stress[i].c[1], 0.0);
  }
  // The CSV has the platen's and the floor's reactions ("all"): their last rows balance the block
  // (quasi-static: equal and opposite within the tolerance above).
  std::ifstream csv(dir / "platen_forces.csv");
  ASSERT_TRUE(csv.good());
  std::string line, last_platen, last_floor;
  std::getline(csv, line);
  EXPECT_EQ(line, "time,body,other,normal_force,tangential_force,force_x,force_y");
  while (std::getline(csv, line)) {
    if (line.find(",platen,all,") != std::string::npos) last_platen = line;
    if (line.find(",floor,all,") != std::string::npos) last_floor = line;
  }
  ASSERT_FALSE(last_platen.empty());
  ASSERT_FALSE(last_floor.empty());
  auto column = [](const std::string& row, int k) {
    std::size_t at = 0;
    for (int i = 0; i < k; ++i) at = row.find(',', at) + 1;
    return std::stod(row.substr(at));
  };
  const double fy_platen = column(last_platen, 6), fy_floor = column(last_floor, 6);
  std::printf("[ measured ] reactions over the last 0.01 s: platen %.2f N/m, floor %.2f N/m\n", fy_platen, fy_floor);
  EXPECT_GT(fy_platen, 0.9 * expected);  // the block pushes the platen up
  EXPECT_LT(fy_floor, -0.9 * expected);  // and the floor down
}

}  // namespace
}  // namespace mpm::test

namespace mpm::test {
namespace {

// examples/09_ring_crush builds (the ring, two rigid platens, the contact module) and its platens move with
// their prescribed velocities from the first steps (the full run is the example's, see its README).
TEST(RingCrushExample, BuildsAndMovesThePlatens) {
  app::register_modules();
  SceneDescription scene =
      load_scene(std::filesystem::path(MPM_SOURCE_DIR) / "examples" / "09_ring_crush" / "scene.yaml");
  scene.output.directory = (std::filesystem::path(MPM_BINARY_DIR) / "tests" / "ring_crush_example_output").string();
  std::filesystem::remove_all(scene.output.directory);
  auto sim = app::build_simulation<2>(scene);
  ASSERT_NE(contact_module(*sim), nullptr);
  // Building (what `mpm check` does) writes no file: the force CSV is opened at its first row.
  EXPECT_FALSE(std::filesystem::exists(std::filesystem::path(scene.output.directory) / "ring_forces.csv"));
  ASSERT_EQ(sim->bodies().size(), 3u);
  const double dt = sim->next_time_step();
  for (int i = 0; i < 10; ++i) sim->advance(dt);
  EXPECT_NEAR(body_velocity(sim->bodies()[1])[1], -5.0, 1e-12);     // top platen
  EXPECT_NEAR(body_velocity(sim->bodies()[2])[1], 5.0, 1e-12);      // bottom platen
  EXPECT_NEAR(body_velocity(sim->bodies()[0]).norm(), 0.0, 1e-12);  // the ring is not touched yet (gap 0.17 mm)
}

}  // namespace
}  // namespace mpm::test
