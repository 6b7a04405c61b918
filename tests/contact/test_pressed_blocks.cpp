// A face traction with multi-velocity contact (docs/theory.md §11, "Face tractions"): two elastic blocks stacked
// between slip walls on a fixed base, the upper one pressed by a traction of 10 kPa on the grid's top face, brought to
// rest by the local damping (eq. 2.74). The traction goes to the upper block's own field (the only body at the loaded
// nodes), the blocks press on each other, and at equilibrium the interface carries the traction: the contact force
// per unit width is 10 kPa, and sigma_yy is -10 kPa in both blocks (no gravity). Before the traction was shared among
// the bodies' fields the scene was refused ("face tractions ... are not supported together with contact").
// The contact settings are pinned, not the defaults: MUSL with pure FLIP and the grid onset does not hold a resting
// interface where it meets the slip walls (it sinks and gains energy, also undamped: the resting-contact defect of the
// contact defaults). Measured at 0.5 s (contact/README.md): FLIP 0.99 9998.7 Pa, APIC 9999.7 Pa (mean force of the
// last 0.1 s); USF with FLIP 0.99 settles to 9998.7 Pa too, after an energy gain during the first 250 steps.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "contact_scene_support.hpp"
#include "mpm/diagnostics/energy_sentinel.hpp"

namespace mpm {
namespace {

const std::string pressed_blocks = R"(
dimension: 2
grid:
  origin: [0, 0]
  extent: [0.1, 1.0]
  cell_size: 0.05
  boundary: {x_min: slip, x_max: slip, y_min: fixed, y_max: {traction: [0, -1.0e4]}}
materials:
  elastic: {model: linear_elastic, density: 1000, youngs_modulus: 1.0e7, poisson_ratio: 0.25}
bodies:
  - {name: lower, material: elastic, shape: {type: box, min: [0, 0], max: [0.1, 0.5]}, particles_per_cell: 2}
  - {name: upper, material: elastic, shape: {type: box, min: [0, 0.5], max: [0.1, 1.0]}, particles_per_cell: 2}
solver: {scheme: musl, @TRANSFER@, damping: 0.8, cfl: 0.5, end_time: 0.5}
contact: {onset: particle_gap}
)";

constexpr double traction = 1.0e4, width = 0.1;

TEST(PressedBlocks, InterfacePressureEqualsTheTraction) {
  for (const char* transfer : {"flip_fraction: 0.99", "velocity_transfer: apic"}) {
    SCOPED_TRACE(transfer);
    auto sim = test::simulation_from_yaml<2>(test::fill(pressed_blocks, {{"TRANSFER", transfer}}));
    const double e0 = sim->energy().total();
    sim->run();
    auto* contact = test::contact_module(*sim);
    ASSERT_NE(contact, nullptr);
    double normal = 0;  // N per unit thickness: the force on the lower block from the upper one
    for (const auto& f : contact->last_forces())
      if (f.body == 0 && f.other == 1) normal = f.normal;
    const double pressure = normal / width;
    double stress[2] = {0, 0};
    for (int b = 0; b < 2; ++b) {
      const auto& p = sim->bodies()[static_cast<std::size_t>(b)].particles;
      for (Index i = 0; i < p.size(); ++i) stress[b] += p.stress[i].c[1] / static_cast<double>(p.size());
    }
    const EnergySentinel<2>* sentinel = sim->energy_sentinel();
    std::printf(
        "%s: interface pressure %.6g Pa (traction %.6g, error %+.3f%%), mean sigma_yy lower %.6g upper %.6g Pa, "
        "energy E - E0 %.6g J, external work %.6g J, largest balance / tolerance %.3g\n",
        transfer, pressure, traction, 100 * (pressure / traction - 1), stress[0], stress[1], sim->energy().total() - e0,
        sentinel->work(), sentinel->largest_ratio());
    EXPECT_NEAR(pressure / traction, 1, 0.02);
    EXPECT_NEAR(stress[0] / -traction, 1, 0.02);
    EXPECT_NEAR(stress[1] / -traction, 1, 0.02);
    // The traction's work is booked on the shared field (the centre-of-mass velocity of the bodies' fields), and the
    // sentinel's balance stays below its tolerance.
    EXPECT_GT(sentinel->work(), 0);
    EXPECT_LT(sentinel->largest_ratio(), 1);
  }
}

}  // namespace
}  // namespace mpm
