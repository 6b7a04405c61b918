// Particle sets (`sets:`) and the conditions on them (`conditions:`; libmpm/include/mpm/sets/): membership at
// t = 0, histories over a set, a set held at rest with its reaction, a set loaded by a total force, against beam and
// plate theory.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "history_fixture.hpp"
#include "mpm/app/body_summary.hpp"
#include "mpm/particles/field_keys.hpp"
#include "mpm/sets/particle_sets.hpp"

namespace mpm::test {
namespace {

// A cantilever of free length L = 1 m and depth H = 0.1 m (plane strain, nu = 0), clamped by the particles of its
// first 0.1 m (a set held at rest) and loaded by P = 10 N/m on the particles of its last cell column (a set with a
// total force, ramped over 0.5 s), brought to rest by local damping (the reaction approaches the load by a factor
// of about 3 every 0.5 s: 2e-5 relative at 5 s, 2.5e-9 at 8 s).
const std::string cantilever = R"yaml(
dimension: 2
grid: {origin: [-0.1, -0.3], extent: [1.3, 0.5], cell_size: [0.025, 0.025]}
materials:
  rubber: {model: linear_elastic, density: 1000, youngs_modulus: 1.0e7, poisson_ratio: 0.0}
bodies:
  - {name: beam, material: rubber, shape: {type: box, min: [0, 0], max: [1.1, 0.1]}}
sets:
  clamp: {body: beam, region: {type: box, min: [0, 0], max: [0.1, 0.1]}}
  tip: {body: beam, region: {type: box, min: [1.075, 0], max: [1.1, 0.1]}}
conditions:
  - {set: clamp, velocity: [0, 0]}
  - {set: tip, force: [0, "-10 * min(t / 0.5, 1)"]}
solver: {scheme: musl, cfl: 0.5, damping: 0.8, end_time: 7}
output:
  histories:
    - {name: clamp, type: reaction, set: clamp, moment_about: [0.1, 0.05], interval: 0.05}
    - {name: tip, type: force, set: tip, interval: 0.05}
    - {name: clamped, type: probe, set: clamp, fields: [displacement], statistics: [min, max], interval: 0.05}
)yaml";

TEST(ParticleSets, MembershipIsDecidedAtTheStartByBodyRegionAndId) {
  std::string yaml = cantilever;
  yaml.replace(yaml.find("  tip: {body"), 0, "  first: {ids: [0, [10, 12]]}\n");
  auto m = measured<2>(yaml);
  const auto& p = m->sim->bodies()[0].particles;
  const auto& bits = p.field(keys::particle_sets);
  Index clamp = 0, tip = 0, first = 0;
  for (Index i = 0; i < p.size(); ++i) {
    const bool in_clamp = p.x[i][0] <= 0.1, in_tip = p.x[i][0] >= 1.075;
    EXPECT_EQ((bits[i] & set_bit(0)) != 0, in_clamp) << i;
    EXPECT_EQ((bits[i] & set_bit(2)) != 0, in_tip) << i;
    EXPECT_EQ((bits[i] & set_bit(1)) != 0, p.id[i] == 0 || (p.id[i] >= 10 && p.id[i] <= 12)) << i;
    clamp += in_clamp;
    tip += in_tip;
    first += (bits[i] & set_bit(1)) != 0;
  }
  EXPECT_EQ(clamp, 8 * 8);  // particles 0.0125 m apart: 8 columns of 8 in the first 0.1 m
  EXPECT_EQ(tip, 2 * 8);
  EXPECT_EQ(first, 4);
}

TEST(ParticleSets, CheckReportsEachSetsParticlesAndAnEmptySet) {
  std::string yaml = cantilever;
  yaml.replace(yaml.find("  tip: {body"), 0, "  above: {region: {type: box, min: [0, 0.15], max: [1, 0.2]}}\n");
  auto m = measured<2>(yaml);
  EXPECT_EQ(app::set_summary<2>(*m->sim, m->scene),
            "  set 'clamp': 64 particles in beam, mass 10 kg/m\n"
            "  set 'above': no particle (its bodies, region and ids select none)\n"
            "  set 'tip': 16 particles in beam, mass 2.5 kg/m\n");
}

TEST(ParticleSets, CantileverClampedByASetMatchesBeamTheoryAndItsReactionIsTheLoad) {
  auto m = measured<2>(cantilever);
  std::vector<double> reaction, load, clamped;  // of the last step (each sample: the mean since the previous)
  m->sim->run([&](const Simulation<2>&) {
    reaction = m->sample(0);
    load = m->sample(1);
    clamped = m->sample(2);
  });
  // The tip's deflection: the mean displacement of the loaded column's particles.
  const auto& p = m->sim->bodies()[0].particles;
  double deflection = 0;
  int n = 0;
  for (Index i = 0; i < p.size(); ++i)
    if (in_sets(p, i, set_bit(1))) {
      deflection += p.x[i][1] - p.field(keys::reference_position<2>)[i][1];
      ++n;
    }
  deflection /= n;
  // Timoshenko: P L^3 / (3 E I) + P L / (kappa G A), kappa = 5/6, plane strain with nu = 0.
  const double P = 10, L = 1, H = 0.1, E = 1e7, I = H * H * H / 12, G = E / 2;
  const double theory = P * L * L * L / (3 * E * I) + P * L / (5.0 / 6 * G * H);
  std::printf(
      "[ measured ] tip deflection %.6g m, theory %.6g m (%+.2f%%); clamp reaction (%.9g, %.9g) N/m, "
      "moment %.9g N m/m; force on the tip set (%.9g, %.9g); clamp displacement in [%.3g, %.3g] m\n",
      -deflection, theory, 100 * (-deflection / theory - 1), reaction[0], reaction[1], reaction[2], load[0], load[1],
      clamped[2], clamped[3]);
  EXPECT_NEAR(-deflection, theory, 0.06 * theory);  // 4 cells through the depth, linear hats
  EXPECT_NEAR(reaction[1], P, 1e-7 * P);            // at rest: the clamp holds the load
  EXPECT_NEAR(reaction[0], 0, 1e-7 * P);
  EXPECT_NEAR(reaction[2], P * L, 0.02 * P * L);  // the moment about the clamp's face, P L
  EXPECT_NEAR(load[1], P, 1e-7 * P);              // the tip set at rest: the beam holds it against its load
}

// A circular plate (radius a = 0.5 m, thickness t = 0.05 m, nu = 0.3) clamped at its perimeter by the ring of particles
// beyond r = a, under its own weight (a uniform pressure q = rho g t), axisymmetric, 4 cells through the thickness,
// brought to rest by local damping: the centre's deflection against Reissner–Mindlin's q a^4 / (64 D) (1 +
// 8 / (3 kappa (1 - nu)) (t / a)^2), kappa = 5/6 (Kirchhoff's q a^4 / (64 D) is 4.4% smaller), and the rim's reaction
// against the whole plate's weight (a full revolution: 2 pi times the weight per radian).
TEST(ParticleSets, PlateClampedAtItsPerimeterMatchesPlateTheory) {
  auto m = measured<2>(R"(
dimension: 2
grid: {coordinates: axisymmetric, origin: [0, -0.1], extent: [0.6, 0.2], cell_size: [0.0125, 0.0125]}
materials:
  rubber: {model: linear_elastic, density: 1000, youngs_modulus: 1.0e7, poisson_ratio: 0.3}
bodies:
  - {name: plate, material: rubber, shape: {type: box, min: [0, 0], max: [0.55, 0.05]}}
sets:
  rim: {body: plate, region: {type: box, min: [0.5, 0], max: [0.55, 0.05]}}
  centre: {body: plate, region: {type: box, min: [0, 0], max: [0.0125, 0.05]}}
conditions:
  - {set: rim, velocity: [0, 0]}
solver: {scheme: musl, cfl: 0.5, damping: 0.8, end_time: 1.5, gravity: [0, -2]}
output:
  histories:
    - {name: rim, type: reaction, set: rim, interval: 0.05}
    - {name: centre, type: probe, set: centre, fields: [displacement], statistics: [mean], interval: 0.05}
)");
  std::vector<double> rim, centre;
  m->sim->run([&](const Simulation<2>&) {
    rim = m->sample(0);
    centre = m->sample(1);
  });
  const double E = 1e7, nu = 0.3, t = 0.05, a = 0.5, q = 1000 * 2 * t, D = E * t * t * t / (12 * (1 - nu * nu));
  const double theory = q * std::pow(a, 4) / (64 * D) * (1 + 8 / (3 * 5.0 / 6 * (1 - nu)) * (t / a) * (t / a));
  const double weight = 2 * std::numbers::pi * 1000 * 2 * t * 0.55 * 0.55 / 2;  // N, the whole plate
  std::printf(
      "[ measured ] centre deflection %.6g m, Reissner-Mindlin %.6g m (%+.2f%%); rim reaction %.12g N, weight "
      "%.12g N (%.2g relative)\n",
      -centre[1], theory, 100 * (-centre[1] / theory - 1), rim[1], weight, rim[1] / weight - 1);
  EXPECT_NEAR(-centre[1], theory, 0.03 * theory);
  EXPECT_NEAR(rim[1], weight, 1e-9 * weight);
}

// Without damping nothing but the clamp acts on the beam (the tip load is a body force, which the force history
// leaves out as it does gravity): at every step the beam's rate of change of momentum less its loads equals the
// clamp's reaction (eq. 17.1), with FLIP, PIC and APIC.
class HeldSetReaction : public ::testing::TestWithParam<std::string> {};

TEST_P(HeldSetReaction, IsTheForceOnTheBodyAtEveryStep) {
  std::string yaml = cantilever;
  yaml.replace(yaml.find("damping: 0.8, end_time: 7"), 25, "end_time: 0.3, " + GetParam());
  yaml += "    - {name: beam, type: force, body: beam, interval: 0.05}\n";
  auto m = measured<2>(yaml);
  double worst = 0, peak = 0;
  m->sim->run([&](const Simulation<2>&) {
    const auto clamp = m->sample(0), beam = m->sample(3);
    worst = std::max({worst, std::abs(beam[0] - clamp[0]), std::abs(beam[1] - clamp[1])});
    peak = std::max(peak, std::hypot(clamp[0], clamp[1]));
  });
  std::printf("[ measured ] %s: peak clamp reaction %.6g N/m; |force on the beam - reaction| <= %.3g N/m\n",
              GetParam().c_str(), peak, worst);
  EXPECT_GT(peak, 1.0);
  EXPECT_LT(worst, 1e-9 * peak);
}

INSTANTIATE_TEST_SUITE_P(Transfers, HeldSetReaction,
                         ::testing::Values("flip_fraction: 1", "flip_fraction: 0", "velocity_transfer: apic"));

// A soil column at rest under gravity, laterally confined (slip walls, fixed base), plane strain: its geostatic
// stress is sigma_yy = -rho g (H - y), sigma_xx = sigma_zz = K0 sigma_yy with K0 = nu / (1 - nu). Started from it
// (`initial_stress` on a set of the whole column) the column stays at rest; started from zero stress it settles by
// rho g H^2 / (2 M) at its top (M the constrained modulus) and rings about that. @MODEL@ chooses the material.
const std::string geostatic = R"yaml(
dimension: 2
grid: {origin: [0, 0], extent: [1, 2.5], cell_size: 0.1, boundary: {x_min: slip, x_max: slip, y_min: fixed}}
materials:
  soil: {model: linear_elastic, density: 2000, youngs_modulus: 1.0e7, poisson_ratio: 0.3}
bodies:
  - {name: column, material: soil, shape: {type: box, min: [0, 0], max: [1, 2]}}
sets:
  all: {body: column}
conditions:
  - {set: all, initial_stress: ["-0.3 / 0.7 * 2000 * 10 * (2 - y)", "-2000 * 10 * (2 - y)",
                                "-0.3 / 0.7 * 2000 * 10 * (2 - y)", 0]}
solver: {scheme: musl, cfl: 0.5, gravity: [0, -10], end_time: 0.1}
output: {fields: [displacement]}
)yaml";

struct ColumnState {
  double largest_displacement = 0;   ///< m, over the particles and the steps
  double largest_stress_change = 0;  ///< Pa, |sigma - geostatic| over the particles and components, at the end
  double energy_change = 0;          ///< of E(t) - E(0), J/m, largest
};

ColumnState run_column(const std::string& yaml) {
  auto m = measured<2>(yaml);
  const auto& p = m->sim->bodies()[0].particles;
  const double e0 = m->sim->energy().total();
  ColumnState s;
  m->sim->run([&](const Simulation<2>& sim) {
    const auto& q = sim.bodies()[0].particles;
    for (Index i = 0; i < q.size(); ++i)
      s.largest_displacement =
          std::max(s.largest_displacement, (q.x[i] - q.field(keys::reference_position<2>)[i]).norm());
    s.energy_change = std::max(s.energy_change, std::abs(sim.energy().total() - e0));
  });
  // against the geostatic state at each particle's initial height (the particles are re-sorted during the run)
  for (Index i = 0; i < p.size(); ++i) {
    const double syy = -2000 * 10 * (2 - p.field(keys::reference_position<2>)[i][1]), k0 = 0.3 / 0.7;
    const double expected[4] = {k0 * syy, syy, k0 * syy, 0};
    for (int k = 0; k < 4; ++k)
      s.largest_stress_change = std::max(s.largest_stress_change, std::abs(p.stress[i].c[k] - expected[k]));
  }
  return s;
}

TEST(ParticleSets, InitialStressKeepsAGeostaticColumnAtRest) {
  const ColumnState started = run_column(geostatic);
  std::string unstressed = geostatic;
  unstressed.replace(unstressed.find("conditions:"), unstressed.find("solver:") - unstressed.find("conditions:"), "");
  const ColumnState settling = run_column(unstressed);
  const double rho_g_H = 2000 * 10 * 2.0, M = 1e7 * 0.7 / (1.3 * 0.4);
  const double settlement = 2000 * 10 * 2.0 * 2.0 / (2 * M);
  std::printf(
      "[ measured ] from the geostatic stress: displacement %.3g m, stress change %.3g Pa, energy %.3g J/m; "
      "from zero stress: displacement %.3g m (static settlement %.3g m)\n",
      started.largest_displacement, started.largest_stress_change, started.energy_change, settling.largest_displacement,
      settlement);
  EXPECT_GT(settling.largest_displacement, 0.5 * settlement);
  EXPECT_LT(started.largest_displacement, 1e-3 * settlement);
  EXPECT_LT(started.largest_stress_change, 1e-3 * rho_g_H);
}

}  // namespace
}  // namespace mpm::test
