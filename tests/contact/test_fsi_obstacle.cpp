// The FSI example (examples/14_fsi_obstacle: a water column collapsing onto an elastic obstacle, Walhorn et al.
// 2005) in its contact set-up, coarse: water and obstacle on their own velocity fields with frictionless contact,
// the water on a free-slip floor, the obstacle's base clamped by its own `y_min: fixed` (contact.body_boundaries),
// the water with cavitation_pressure 0 and volumetric_deformation 1; PolyPIC with hat functions, MUSL, cfl 0.5.
// 10 cells across the column (0.0146 m; the example has 40), to 0.5 s.
//
// Reference: the energy audit (kinetic + stored + gravity), which the continuum conserves (nearly inviscid water,
// frictionless walls and contact, an elastic obstacle), so every loss is numerical (issue 21; physics/fluids/
// README.md, Limits; examples/14_fsi_obstacle/README.md). Measured here: -17.6% at 0.5 s, never above E0 (the
// example's 40 cells: -15.6%; APIC at these 10 cells -45%). Asserted: above -21% (1.2x the loss), never more than
// 0.1% above E0, no inverted particle, the obstacle's base on its footprint. Without cavitation_pressure the same
// set-up at 20 cells inverted a water particle in tension at 0.198 s; with the shared field and the no-slip floor
// the example lost 25.3% (PolyPIC, cfl 0.25) and 46.1% (APIC) and PolyPIC inverted at cfl 0.5.
#include <cmath>
#include <cstdio>

#include "contact_scene_support.hpp"

namespace mpm::test {
namespace {

const std::string fsi = R"(
dimension: 2
grid:
  origin: [0, 0]
  extent: [0.584, 0.584]
  cell_size: 0.0146
  boundary: {x_min: slip, x_max: slip, y_min: slip, y_max: slip}
materials:
  water: {model: newtonian_fluid, density: 1000, bulk_modulus: 6.6e5, eos_exponent: 7, viscosity: 1.0e-3,
          cavitation_pressure: 0, volumetric_deformation: 1}
  rubber: {model: neo_hookean, density: 2500, youngs_modulus: 1.0e6, poisson_ratio: 0.0}
bodies:
  - {name: water, material: water, shape: {type: box, min: [0, 0], max: [0.146, 0.292]}, particles_per_cell: 2}
  - {name: obstacle, material: rubber, shape: {type: box, min: [0.286, 0], max: [0.298, 0.080]},
     particles_per_cell: 3}
solver: {scheme: musl, shape_function: linear, velocity_transfer: @TRANSFER@, cfl: 0.5, gravity: [0, -9.81],
         end_time: 0.5}
contact:
  body_boundaries: [{body: obstacle, y_min: fixed}]
)";

TEST(FsiObstacle, ContactSetUpKeepsTheEnergyWithinItsMeasuredLoss) {
  auto sim = simulation_from_yaml<2>(fill(fsi, {{"TRANSFER", "polypic"}}), "fsi.yaml");
  const double e0 = sim->energy().total();
  double largest = -1;
  ASSERT_NO_THROW(sim->run([&](const Simulation<2>& s) { largest = std::max(largest, s.energy().total() / e0 - 1); }));
  const double change = sim->energy().total() / e0 - 1;
  // The obstacle's base stays on its footprint x in [0.286, 0.298] m (its lowest row of particles, 2.4 mm above
  // the floor, moves with the clamped nodes' weight 5/6 at rest); on the slip floor it would be pushed away.
  const auto& p = sim->bodies()[1].particles;
  double base_left = 1, base_right = 0;
  for (Index i = 0; i < p.size(); ++i)
    if (p.x[i][1] < 0.003)
      base_left = std::min<double>(base_left, p.x[i][0]), base_right = std::max<double>(base_right, p.x[i][0]);
  std::printf(
      "[ measured ] FSI obstacle, contact set-up, PolyPIC + hats, 10 cells: energy change %+.4f at 0.5 s, "
      "largest %+.2e; obstacle base from x = %.4f to %.4f m\n",
      change, largest, base_left, base_right);
  EXPECT_GT(change, -0.21);  // measured -0.176 (1.2x)
  EXPECT_LT(largest, 1e-3);
  EXPECT_GT(base_left, 0.286);
  EXPECT_LT(base_right, 0.298);
}

}  // namespace
}  // namespace mpm::test
