// Face conditions of one body's own field (`contact.body_boundaries`, docs/scene-reference.md#contact): two
// elastic blocks stand on a free-slip floor under gravity tilted along it (g_x = 2 m/s^2). Block `held` has
// `y_min: fixed` of its own, block `loose` keeps the scene's slip floor. Frictionless contact between them never
// acts (they stay 0.2 m apart). Reference: a block on a frictionless floor under a uniform body force slides
// with a = g_x (every node of it, the floor's included, accelerates alike: its mean velocity is g_x t up to
// round-off); a block whose base is clamped only sways (its centre of mass moves by the bending of a cantilever).
#include <cmath>
#include <cstdio>

#include "contact_scene_support.hpp"

namespace mpm::test {
namespace {

const std::string blocks = R"(
dimension: 2
grid: {origin: [0, 0], extent: [1.2, 0.4], cell_size: 0.05, boundary: {y_min: slip}}
materials:
  rubber: {model: linear_elastic, density: 1000, youngs_modulus: 1.0e6, poisson_ratio: 0.3}
bodies:
  - {name: held, material: rubber, shape: {type: box, min: [0.1, 0.0], max: [0.3, 0.2]}, particles_per_cell: 2}
  - {name: loose, material: rubber, shape: {type: box, min: [0.5, 0.0], max: [0.7, 0.2]}, particles_per_cell: 2}
solver: {scheme: musl, velocity_transfer: @TRANSFER@, shape_function: linear, cfl: 0.4, end_time: 0.2,
         gravity: [2, -9.81]}
contact:
  @OWN@
)";

struct BlockRun {
  double held_vx = 0, loose_vx = 0, held_base_vx = 0;  ///< mean x velocities at the end, m/s
};

BlockRun run_blocks(const std::string& transfer, const std::string& own) {
  auto sim = simulation_from_yaml<2>(fill(blocks, {{"TRANSFER", transfer}, {"OWN", own}}));
  sim->run();
  BlockRun r;
  r.held_vx = body_velocity(sim->bodies()[0])[0];
  r.loose_vx = body_velocity(sim->bodies()[1])[0];
  const auto& p = sim->bodies()[0].particles;  // the held block's lowest row of particles (y = h/4)
  double mv = 0, m = 0;
  for (Index i = 0; i < p.size(); ++i)
    if (p.x[i][1] < 0.025) mv += p.mass[i] * p.v[i][0], m += p.mass[i];
  r.held_base_vx = mv / m;
  std::printf("[ measured ] blocks (%s, %s) at 0.2 s: held %.6f m/s (its base %.3e), loose %.6f m/s (g_x t = 0.4)\n",
              transfer.c_str(), own.c_str(), r.held_vx, r.held_base_vx, r.loose_vx);
  return r;
}

TEST(BodyBoundaries, ClampOneBodyWhileAnotherSlidesOnTheSlipFloor) {
  for (const std::string transfer : {"flip", "apic", "polypic"}) {
    const BlockRun own = run_blocks(transfer, "body_boundaries: [{body: held, y_min: fixed}]");
    EXPECT_NEAR(own.loose_vx, 0.4, 1e-9) << transfer;  // slides freely: g_x t
    EXPECT_LT(std::abs(own.held_base_vx), 0.02) << transfer;
    EXPECT_LT(std::abs(own.held_vx), 0.1) << transfer;  // it sways, it does not slide
    // Without its own condition the held block slides like the other one.
    const BlockRun none = run_blocks(transfer, "friction: 0");
    EXPECT_NEAR(none.held_vx, 0.4, 1e-9) << transfer;
    // The scene's own condition given again changes nothing, bit for bit.
    const BlockRun same = run_blocks(transfer, "body_boundaries: [{body: held, y_min: slip}]");
    EXPECT_EQ(same.held_vx, none.held_vx) << transfer;
    EXPECT_EQ(same.loose_vx, none.loose_vx) << transfer;
  }
}

}  // namespace
}  // namespace mpm::test
