// Checkpoint, restart and fork through the `mpm` program (README "Long runs: checkpoints, restart, fork").
//
// For each case of the issue, a run to T is the reference. The same scene is then run again and interrupted
// twice: by SIGTERM at a quarter of the steps (the run writes a checkpoint and stops with 143), restarted, and
// killed by SIGKILL between its checkpoint at T/2 and the end (the frames and CSV rows written after that
// checkpoint are lost work). The last restart runs at one thread (the others at two) from the checkpoint
// directory, so it continues the checkpoint at T/2. Its output must be the reference's, byte for byte: every
// .vtu frame, every CSV (energy.csv, the contact forces), the .pvd, and every particle field of every body in
// the final checkpoint. The stop points come from the test seam `--test-signal-at STEP:NAME` (stop_signals.hpp),
// which makes the process send itself a real signal during a given step.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <string>

#include "restart_support.hpp"

namespace {

using namespace restart_support;

// ---- The cases of the issue: small scenes, a few hundred steps each ----

Case cpdi_q4() {
  return {"cpdi_q4_corners",
          "dimension: 2\n"
          "grid: {origin: [0, 0], extent: [1, 1], cell_size: 0.1}\n"
          "materials: {soft: {model: neo_hookean, density: 1000, youngs_modulus: 1.0e4, poisson_ratio: 0.3}}\n"
          "bodies:\n"
          "  - {name: block, material: soft, shape: {type: box, min: [0.3, 0.3], max: [0.7, 0.7]}, "
          "velocity: [\"0.5*(y-0.5)\", \"-0.5*(x-0.5)\"]}\n"
          "solver: {scheme: musl, shape_function: cpdi_q4, cpdi_domain_update: corners, cfl: 0.4, end_time: 0.2}\n"
          "output:\n"
          "  interval: 0.05\n"
          "  fields: [velocity, stress, domains]\n" +
              checkpoint_at(0.1)};
}

Case tlmpm() {
  return {
      "tlmpm_column",
      "dimension: 1\n"
      "grid:\n"
      "  extent: [0.1]\n"
      "  cell_size: 0.0025\n"
      "  boundary: {x_min: fixed, x_max: {traction: [\"-1.0e4*min(t, 1)\"]}}\n"
      "materials: {column: {model: neo_hookean, density: 10, youngs_modulus: 5.0e3, poisson_ratio: 0.3}}\n"
      "bodies: [{name: column, material: column, shape: {type: box, min: [0], max: [0.1]}, particles_per_cell: 1}]\n"
      "solver: {scheme: tlmpm, shape_function: lagrange_quadratic, flip_fraction: 0.5, dt: 2.2e-5, end_time: "
      "0.004, gravity: [-9.81]}\n"
      "output:\n"
      "  interval: 0.001\n"
      "  fields: [displacement, stress, deformation_gradient]\n" +
          checkpoint_at(0.002)};
}

Case apic() {
  return {"apic_spinning_disk",
          "dimension: 2\n"
          "grid: {origin: [0, 0], extent: [1, 1], cell_size: 0.05}\n"
          "materials: {elastic: {model: linear_elastic, density: 1000, youngs_modulus: 1.0e4, poisson_ratio: 0.3}}\n"
          "bodies:\n"
          "  - {name: disk, material: elastic, shape: {type: disk, center: [0.5, 0.5], radius: 0.25}, "
          "velocity: [\"-(y-0.5)\", \"x-0.5\"]}\n"
          "solver: {scheme: usl, shape_function: quadratic_bspline, velocity_transfer: apic, cfl: 0.5, end_time: 0.3}\n"
          "output:\n"
          "  interval: 0.1\n"
          "  fields: [velocity, stress]\n" +
              checkpoint_at(0.15)};
}

#ifdef MPM_WITH_FLUIDS
Case dam_break() {
  return {"dam_break",
          "dimension: 2\n"
          "grid:\n"
          "  extent: [1, 0.5]\n"
          "  cell_size: 0.05\n"
          "  boundary: {x_min: slip, x_max: slip, y_min: slip, y_max: slip}\n"
          "materials: {water: {model: newtonian_fluid, density: 1000, bulk_modulus: 1.0e5, eos_exponent: 7, "
          "viscosity: 1.0e-3}}\n"
          "bodies: [{name: water, material: water, shape: {type: box, min: [0, 0], max: [0.4, 0.25]}}]\n"
          "solver: {scheme: musl, shape_function: linear, dt: 5.0e-4, gravity: [0, -9.81], end_time: 0.1}\n"
          "output:\n"
          "  interval: 0.02\n"
          "  fields: [velocity, pressure, density]\n" +
              checkpoint_at(0.05)};
}

Case sod() {
  return {"sod",
          "dimension: 1\n"
          "grid: {extent: [1], cell_size: 0.01, boundary: {x_min: fixed, x_max: fixed}}\n"
          "materials:\n"
          "  left: {model: ideal_gas, gamma: 1.4, density: 1, initial_pressure: 1, artificial_viscosity_linear: 1, "
          "artificial_viscosity_quadratic: 2}\n"
          "  right: {model: ideal_gas, gamma: 1.4, density: 0.125, initial_pressure: 0.1, "
          "artificial_viscosity_linear: 1, artificial_viscosity_quadratic: 2}\n"
          "bodies:\n"
          "  - {name: high, material: left, shape: {type: box, min: [0], max: [0.5]}, particles_per_cell: 3}\n"
          "  - {name: low, material: right, shape: {type: box, min: [0.5], max: [1]}, particles_per_cell: 3}\n"
          "solver: {scheme: musl, shape_function: cpgimp, flip_fraction: 1, cfl: 0.2, end_time: 0.1}\n"
          "output:\n"
          "  interval: 0.05\n"
          "  fields: [velocity, density, pressure, internal_energy]\n" +
              checkpoint_at(0.05)};
}
#endif

#ifdef MPM_WITH_PLASTICITY
Case johnson_cook_damage_3d() {
  return {"johnson_cook_damage_3d",
          "dimension: 3\n"
          "grid:\n"
          "  extent: [0.006, 0.006, 0.004]\n"
          "  cell_size: 0.0005\n"
          "  boundary: {z_min: slip}\n"
          "materials:\n"
          "  copper: {model: johnson_cook, density: 8940, youngs_modulus: 115.0e9, poisson_ratio: 0.31, "
          "yield_stress: 65.0e6, hardening_coefficient: 356.0e6, hardening_exponent: 0.37, "
          "strain_rate_coefficient: 0.013, damage_d1: 0.54, damage_d2: 4.89, damage_d3: -3.03, damage_d4: 0.014}\n"
          "bodies: [{name: block, material: copper, shape: {type: box, min: [0.002, 0.002, 0], max: [0.0045, 0.004, "
          "0.0025]}, velocity: [0, 0, -300]}]\n"
          "solver: {scheme: musl, shape_function: linear, cfl: 0.5, end_time: 4.0e-6}\n"
          "output:\n"
          "  interval: 1.0e-6\n"
          "  fields: [velocity, stress, plastic_strain, damage]\n" +
              checkpoint_at(2.0e-6)};
}
#endif

#if defined(MPM_WITH_THERMAL) && defined(MPM_WITH_PLASTICITY)
Case thermal_coupling() {
  return {"thermal_coupling",
          "dimension: 2\n"
          "grid:\n"
          "  extent: [0.01, 0.01]\n"
          "  cell_size: 0.0005\n"
          "  boundary: {y_min: slip}\n"
          "materials:\n"
          "  steel: {model: j2_plasticity, density: 7800, youngs_modulus: 200.0e9, poisson_ratio: 0.3, "
          "yield_stress: 300.0e6, specific_heat: 450, thermal_conductivity: 5.0e4, thermal_expansion: 1.2e-5, "
          "taylor_quinney_coefficient: 0.9}\n"
          "bodies: [{name: block, material: steel, shape: {type: box, min: [0.003, 0], max: [0.007, 0.004]}, "
          "velocity: [0, -200]}]\n"
          "solver: {scheme: musl, shape_function: linear, cfl: 0.5, end_time: 4.0e-6}\n"
          "thermal:\n"
          "  boundary: {x_min: {temperature: \"293.15 + 1.0e7*t\"}}\n"
          "output:\n"
          "  interval: 1.0e-6\n"
          "  fields: [velocity, stress, plastic_strain, temperature, heat_flux]\n"
          "  grid: true\n" +
              checkpoint_at(2.0e-6)};
}
#endif

#if defined(MPM_WITH_THERMAL) && defined(MPM_WITH_CONTACT)
/// The thermal analysis (`scheme: heat`) with a finite contact conductance: the conduction's and contact's state
/// (first-step flux, the bodies' own nodal fields) across a restart.
Case heat_analysis() {
  return {"heat_analysis",
          "dimension: 2\n"
          "grid: {origin: [0, 0], extent: [0.004, 0.04], cell_size: 0.001}\n"
          "materials:\n"
          "  steel: {model: linear_elastic, density: 7850, youngs_modulus: 2.0e11, poisson_ratio: 0.3, "
          "specific_heat: 460, thermal_conductivity: 45}\n"
          "bodies:\n"
          "  - {name: cold, material: steel, shape: {type: box, min: [0, 0], max: [0.004, 0.02]}}\n"
          "  - {name: hot, material: steel, shape: {type: box, min: [0, 0.02], max: [0.004, 0.04]}}\n"
          "solver: {scheme: heat, cfl: 0.8, end_time: 4}\n"
          "thermal: {initial_temperature: \"y < 0.02 ? 300 : 800\"}\n"
          "contact: {thermal_conductance: 1.0e4}\n"
          "output:\n"
          "  interval: 1\n"
          "  fields: [temperature, heat_flux]\n"
          "  grid: true\n" +
              checkpoint_at(2)};
}
#endif

#ifdef MPM_WITH_CONTACT
/// Contact with its defaults (onset: particle_gap, velocity_transfer: apic; contact/README.md, Defaults): two blocks
/// stacked at rest under gravity.
Case contact_defaults() {
  return {"contact_defaults_stacked",
          "dimension: 2\n"
          "grid: {origin: [0, 0], extent: [0.2, 0.3], cell_size: 0.01, boundary: {x_min: slip, x_max: slip, y_min: "
          "slip}}\n"
          "materials: {rubber: {model: neo_hookean, density: 1000, youngs_modulus: 1.0e6, poisson_ratio: 0.3}}\n"
          "bodies:\n"
          "  - {name: lower, material: rubber, shape: {type: box, min: [0, 0], max: [0.2, 0.1]}}\n"
          "  - {name: upper, material: rubber, shape: {type: box, min: [0, 0.1], max: [0.2, 0.2]}}\n"
          "solver: {scheme: musl, cfl: 0.5, gravity: [0, -9.81], end_time: 0.06}\n"
          "contact: {force_file: forces.csv, force_interval: 0.005}\n"
          "output:\n"
          "  interval: 0.02\n"
          "  fields: [velocity, stress]\n" +
              checkpoint_at(0.03)};
}

Case contact_rigid() {
  return {"contact_rigid_platen",
          "dimension: 2\n"
          "grid: {origin: [0, 0], extent: [1, 1], cell_size: 0.05}\n"
          "materials:\n"
          "  elastic: {model: linear_elastic, density: 1000, youngs_modulus: 1.0e4, poisson_ratio: 0.3}\n"
          "  platen: {model: rigid, density: 1000}\n"
          "bodies:\n"
          "  - {name: disk, material: elastic, shape: {type: disk, center: [0.5, 0.35], radius: 0.2}}\n"
          "  - {name: platen, material: platen, shape: {type: box, min: [0.2, 0.6], max: [0.8, 0.65]}}\n"
          "solver: {scheme: musl, shape_function: linear, cfl: 0.5, end_time: 0.3}\n"
          "contact:\n"
          "  friction: 0.2\n"
          "  rigid_bodies: [{body: platen, velocity: [\"0\", \"-0.5\"]}]\n"
          "  planes: [{name: floor, point: [0, 0.1], normal: [0, 1], velocity: [\"0\", \"0.1\"]}]\n"
          "  force_file: forces.csv\n"
          "  force_interval: 0.01\n"
          "output:\n"
          "  interval: 0.05\n"
          "  fields: [velocity, stress, body]\n" +
              checkpoint_at(0.15)};
}
#endif

// Histories carry state between rows (a reaction's impulse since its last row) and continue their CSVs: with
// intervals that do not divide the checkpoint's time, a restart must still write every row to the same bits.
Case histories() {
  return {
      "histories",
      "dimension: 2\n"
      "grid: {origin: [0, 0], extent: [1, 0.6], cell_size: 0.05, boundary: {y_min: fixed, x_min: slip}}\n"
      "materials: {m: {model: linear_elastic, density: 1000, youngs_modulus: 1.0e4, poisson_ratio: 0.3}}\n"
      "bodies:\n"
      "  - {name: block, material: m, shape: {type: box, min: [0.2, 0.0], max: [0.6, 0.3]}, velocity: [0.2, -0.3]}\n"
      "solver: {scheme: musl, shape_function: linear, cfl: 0.5, end_time: 0.3, gravity: [0, -9.81]}\n"
      "output:\n"
      "  interval: 0.05\n"
      "  fields: [velocity, stress, body]\n"
      "  histories:\n"
      "    - {name: floor, type: reaction, face: y_min, moment_about: [0, 0], interval: 0.007}\n"
      "    - {name: wall, type: reaction, face: x_min, interval: 0.013}\n"
      "    - {name: block_energy, type: energy, body: block, interval: 0.011}\n"
      "    - {name: front, type: extent, body: block, axis: x}\n"
      "    - {name: block_force, type: force, body: block, interval: 0.009}\n"
      "    - {name: centre, type: probe, point: [0.4, 0.15], radius: 0.08, fields: [velocity, stress]}\n" +
          checkpoint_at(0.15)};
}

// An outflow face: a block thrown up through y_max starts to leave at t = 0.043 s, so the checkpoint at T/2 holds
// fewer particles than the scene makes, and the books and energy.csv's outflow columns continue from it.
Case outflow() {
  return {
      "outflow",
      "dimension: 2\n"
      "grid: {extent: [1, 1], cell_size: 0.05, boundary: {x_min: slip, x_max: slip, y_min: slip, y_max: outflow}}\n"
      "materials: {gel: {model: neo_hookean, density: 1000, youngs_modulus: 2.0e5, poisson_ratio: 0.3}}\n"
      "bodies:\n"
      "  - {name: gel, material: gel, shape: {type: box, min: [0.35, 0.3], max: [0.65, 0.75]}, velocity: [0.5, 6]}\n"
      "solver: {scheme: musl, shape_function: cubic_bspline, cfl: 0.5, end_time: 0.12, gravity: [0, -9.81]}\n"
      "output:\n"
      "  interval: 0.02\n"
      "  fields: [velocity, stress]\n" +
          checkpoint_at(0.06)};
}

// Absorbing faces (docs/theory.md §19): a column on a compliant base driven by an input pulse, with absorbing sides.
// The faces keep no state, and the energy sentinel's W (the work the dashpots did) continues from the checkpoint.
Case absorbing() {
  return {"absorbing",
          "dimension: 2\n"
          "grid:\n"
          "  extent: [0.4, 1]\n"
          "  cell_size: 0.05\n"
          "  boundary:\n"
          "    x_min: {type: absorbing, density: 1000, p_wave_speed: 109.5445, s_wave_speed: 63.2456}\n"
          "    x_max: {type: absorbing, density: 1000, p_wave_speed: 109.5445, s_wave_speed: 63.2456}\n"
          "    y_min: {type: absorbing, density: 1000, p_wave_speed: 109.5445, s_wave_speed: 63.2456, input_velocity: "
          "[\"t < 0.004 ? 0.05 * sin(_pi * t / 0.004)^2 : 0\", 0.01]}\n"
          "materials: {soil: {model: linear_elastic, density: 1000, youngs_modulus: 1.0e7, poisson_ratio: 0.25}}\n"
          "bodies:\n"
          "  - {name: soil, material: soil, shape: {type: box, min: [0, 0], max: [0.4, 1]}}\n"
          "solver: {scheme: musl, shape_function: linear, cfl: 0.5, end_time: 0.03}\n"
          "output:\n"
          "  interval: 0.005\n"
          "  fields: [velocity, stress]\n" +
              checkpoint_at(0.015)};
}

// Erosion (materials.NAME.failure): block a erodes whole at step 51 (t = 0.051 s: its particles' own time step
// falls to the floor as it falls, tests/libmpm/test_failure.cpp), after the checkpoint at 0.03 s, and block b of
// the pulled-apart cut erodes at its first steps, before it; the eroded books and energy.csv's eroded_* columns
// continue from the checkpoint; so do the histories of a particle at the cut and of the cut's region, with the
// empty cells of a particle that has eroded.
Case erosion() {
  return {"erosion",
          "dimension: 2\n"
          "grid: {extent: [2, 1], cell_size: 0.1, boundary: {y_min: slip, y_max: slip}}\n"
          "materials:\n"
          "  brittle: {model: linear_elastic, density: 1000, youngs_modulus: 1.0e4, poisson_ratio: 0.3, failure: "
          "{min_time_step: 1.2e-2}}\n"
          "  cut: {model: neo_hookean, density: 1000, youngs_modulus: 1.0e4, poisson_ratio: 0.3, failure: "
          "{principal_stress: 500}}\n"
          "bodies:\n"
          "  - {name: a, material: brittle, shape: {type: box, min: [0.1, 0.5], max: [0.4, 0.9]}}\n"
          "  - {name: left, material: cut, shape: {type: box, min: [0.6, 0.1], max: [1.2, 0.4]}, velocity: [-1, 0]}\n"
          "  - {name: right, material: cut, shape: {type: box, min: [1.2, 0.1], max: [1.8, 0.4]}, velocity: [1, 0]}\n"
          "solver: {scheme: usl, dt: 1.0e-3, end_time: 0.08, gravity: [0, -9.81]}\n"
          "output:\n"
          "  interval: 0.01\n"
          "  fields: [velocity, stress, failed]\n"
          "  histories:\n"
          "    - {name: at_cut, type: particle, body: left, nearest: [1.19, 0.26], fields: [velocity, stress], "
          "interval: 0.004}\n"
          "    - {name: peak, type: probe, body: left, fields: [von_mises_stress], statistics: [max, max_at]}\n"
          "    - {name: cut, type: probe, box: {min: [1.1, 0.1], max: [1.3, 0.4]}, fields: [velocity]}\n" +
              checkpoint_at(0.03)};
}

// Particle sets with TLMPM (stencils at the reference positions): a beam clamped by a set, loaded by a total force
// on another and pushed by a third; the membership field, the reactions accumulated since the last row and the
// statistics over a set continue from the checkpoint.
Case particle_sets() {
  return {
      "particle_sets",
      "dimension: 2\n"
      "grid: {origin: [-0.1, -0.3], extent: [1.3, 0.5], cell_size: [0.05, 0.05]}\n"
      "materials: {gel: {model: neo_hookean, density: 1000, youngs_modulus: 1.0e5, poisson_ratio: 0.3}}\n"
      "bodies:\n"
      "  - {name: beam, material: gel, shape: {type: box, min: [0, 0], max: [1.1, 0.1]}}\n"
      "sets:\n"
      "  clamp: {body: beam, region: {type: box, min: [0, 0], max: [0.1, 0.1]}}\n"
      "  tip: {body: beam, region: {type: box, min: [1.05, 0], max: [1.1, 0.1]}}\n"
      "  middle: {ids: [[40, 47]]}\n"
      "conditions:\n"
      "  - {set: clamp, velocity: [0, 0]}\n"
      "  - {set: tip, force: [0, \"-5 * min(t / 0.05, 1)\"]}\n"
      "  - {set: middle, velocity: [free, \"0.2 * t\"]}\n"
      "solver: {scheme: tlmpm, cfl: 0.5, end_time: 0.2}\n"
      "output:\n"
      "  interval: 0.05\n"
      "  fields: [velocity, stress, particle_sets]\n"
      "  histories:\n"
      "    - {name: clamp, type: reaction, set: clamp, moment_about: [0.1, 0.05], interval: 0.007}\n"
      "    - {name: tip_force, type: force, set: tip, interval: 0.009}\n"
      "    - {name: tip, type: probe, set: tip, fields: [velocity], statistics: [mean, max_at], interval: 0.011}\n" +
          checkpoint_at(0.1)};
}

// The gravity stage (docs/theory.md §20): the run starts from the settled column; a footing set is then pushed in.
// The restart does not run the stage again (the checkpoint holds the settled state) and reaches the same bits.
Case gravity_stage() {
  return {"gravity_stage",
          "dimension: 2\n"
          "grid: {extent: [1, 1.2], cell_size: 0.1, boundary: {x_min: slip, x_max: slip, y_min: fixed}}\n"
          "materials: {soil: {model: linear_elastic, density: 2000, youngs_modulus: 1.0e6, poisson_ratio: 0.3}}\n"
          "bodies: [{name: soil, material: soil, shape: {type: box, min: [0, 0], max: [1, 1]}}]\n"
          "sets: {footing: {region: {type: box, min: [0, 0.9], max: [0.3, 1]}}}\n"
          "conditions: [{set: footing, velocity: [free, \"-0.5 * t\"]}]\n"
          "solver: {cfl: 0.5, end_time: 0.1, gravity: [0, -10], gravity_stage: {tolerance: 1.0e-3}}\n"
          "output:\n"
          "  interval: 0.02\n"
          "  fields: [velocity, stress, displacement]\n"
          "  histories:\n"
          "    - {name: footing, type: reaction, set: footing, interval: 0.01}\n" +
              checkpoint_at(0.05)};
}

class InterruptedRun : public ::testing::TestWithParam<Case> {};

TEST_P(InterruptedRun, ReachesTheSameBitsAsTheUninterruptedOne) {
  check_interrupted_run_reaches_the_same_bits(GetParam());
}

std::vector<Case> cases() {
  std::vector<Case> all{two_disks(), cpdi_q4(),   tlmpm(),   apic(),          histories(),
                        outflow(),   absorbing(), erosion(), particle_sets(), gravity_stage()};
#ifdef MPM_WITH_FLUIDS
  all.push_back(dam_break());
  all.push_back(sod());
#endif
#ifdef MPM_WITH_PLASTICITY
  all.push_back(johnson_cook_damage_3d());
#endif
#if defined(MPM_WITH_THERMAL) && defined(MPM_WITH_PLASTICITY)
  all.push_back(thermal_coupling());
#endif
#ifdef MPM_WITH_CONTACT
  all.push_back(contact_rigid());
  all.push_back(contact_defaults());
#endif
#if defined(MPM_WITH_THERMAL) && defined(MPM_WITH_CONTACT)
  all.push_back(heat_analysis());
#endif
  return all;
}

INSTANTIATE_TEST_SUITE_P(Cases, InterruptedRun, ::testing::ValuesIn(cases()),
                         [](const ::testing::TestParamInfo<Case>& info) { return info.param.name; });

}  // namespace

namespace {

using namespace restart_support;

/// The two disks with `checkpoint` instead of a checkpoint at T/2.
std::string two_disks_scene(const std::string& checkpoint) { return with_checkpoint(two_disks().scene, checkpoint); }

TEST(Restart, KilledWhileWritingACheckpointContinuesThePreviousOne) {
  const fs::path dir = scratch("restart_kill_in_write");
  std::ofstream(dir / "scene.yaml") << two_disks_scene("  checkpoint: {interval: 0.1, keep: 3}\n");
  const std::string scene = (dir / "scene.yaml").string();
  const Result ref = cli::mpm("run " + scene + " -o " + (dir / "reference").string(), dir);
  ASSERT_EQ(ref.status, 0) << ref.err;
  const auto steps = checkpoint_steps(dir / "reference" / "checkpoints");  // at T/4, T/2, 3T/4, T; keep 3
  ASSERT_EQ(steps.size(), 3u);
  // The second checkpoint (T/2) is killed halfway through its datasets: the first (T/4) stays valid.
  const Result killed_run =
      cli::mpm("run " + scene + " -o " + (dir / "run").string() + " --test-kill-in-checkpoint 2", dir);
  EXPECT_TRUE(killed(killed_run)) << killed_run.status << "\n" << killed_run.err;
  const auto left = checkpoint_steps(dir / "run" / "checkpoints");
  ASSERT_EQ(left.size(), 1u);
  bool temporary = false;  // the half-written file, under a temporary name
  for (const auto& e : fs::directory_iterator(dir / "run" / "checkpoints"))
    temporary = temporary || e.path().filename().string().find(".tmp-") != std::string::npos;
  EXPECT_TRUE(temporary);
  const Result resumed = cli::mpm(
      "run " + scene + " -o " + (dir / "run").string() + " --restart " + (dir / "run" / "checkpoints").string(), dir);
  ASSERT_EQ(resumed.status, 0) << resumed.err;
  EXPECT_NE(resumed.err.find(mpm::checkpoint::checkpoint_name(left[0])), std::string::npos) << resumed.err;
  expect_same_output(dir / "reference", dir / "run", steps.back());
  if (!HasFailure()) fs::remove_all(dir);
}

TEST(Restart, CheckpointsDoNotChangeTheRun) {
  const fs::path dir = scratch("restart_no_effect");
  std::ofstream(dir / "with.yaml") << two_disks().scene;
  std::ofstream(dir / "without.yaml") << two_disks_scene("");
  ASSERT_EQ(cli::mpm("run " + (dir / "with.yaml").string() + " -o " + (dir / "with").string(), dir).status, 0);
  ASSERT_EQ(cli::mpm("run " + (dir / "without.yaml").string() + " -o " + (dir / "without").string(), dir).status, 0);
  EXPECT_FALSE(fs::exists(dir / "without" / "checkpoints"));
  expect_same_files(dir / "with", dir / "without");
  if (!HasFailure()) fs::remove_all(dir);
}

TEST(Restart, SignalsStopWithTheirExitStatus) {
  const fs::path dir = scratch("restart_signals");
  std::ofstream(dir / "scene.yaml") << two_disks_scene("");  // no checkpoint settings: a signal writes one anyway
  const std::string run = "run " + (dir / "scene.yaml").string() + " -o " + (dir / "out").string();
  for (const auto& [name, status] : {std::pair{"INT", 130}, std::pair{"USR1", 138}, std::pair{"TERM", 143}}) {
    fs::remove_all(dir / "out");
    const Result r = cli::mpm(run + " --test-signal-at 10:" + name, dir);
    EXPECT_EQ(r.status, status) << name << "\n" << r.err;
    EXPECT_NE(r.err.find(std::string("stopped by SIG") + name + " at step 10 (t = 0.02 s)"), std::string::npos)
        << r.err;
    EXPECT_EQ(checkpoint_steps(dir / "out" / "checkpoints"), std::vector<long long>{10});
  }
  // A second SIGINT stops at once: no checkpoint, no message.
  fs::remove_all(dir / "out");
  const Result twice = cli::mpm(run + " --test-signal-at 10:INT+INT", dir);
  EXPECT_EQ(twice.status, 130) << twice.err;
  EXPECT_EQ(twice.err.find("stopped by"), std::string::npos) << twice.err;
  EXPECT_TRUE(checkpoint_steps(dir / "out" / "checkpoints").empty());
  // `mpm run --help` says so, and does not list the test seams.
  const Result help = cli::mpm("run --help", dir);
  EXPECT_NE(help.out.find("SIGINT (Ctrl-C), SIGTERM and SIGUSR1"), std::string::npos) << help.out;
  EXPECT_NE(help.out.find("128 + N stopped by signal N"), std::string::npos) << help.out;
  EXPECT_EQ(help.out.find("--test-"), std::string::npos) << help.out;
  // A seam that cannot be read is bad input, before anything is run.
  const Result bad = cli::mpm(run + " --test-signal-at 10:HUP", dir);
  EXPECT_EQ(bad.status, 2) << bad.err;
  EXPECT_NE(bad.err.find("--test-signal-at: expected STEP:NAME[+NAME...] (NAME: INT, TERM, USR1, KILL), got '10:HUP'"),
            std::string::npos)
      << bad.err;
  const Result bad_rank = cli::mpm(run + " --test-fail-at 1", dir);
  EXPECT_EQ(bad_rank.status, 2) << bad_rank.err;
  EXPECT_NE(bad_rank.err.find("--test-fail-at: expected RANK:STEP, got '1'"), std::string::npos) << bad_rank.err;
  if (!HasFailure()) fs::remove_all(dir);
}

}  // namespace

namespace {

using namespace restart_support;

// The guard's snapshot is not stored: the restart takes it at the checkpoint. Its roll-back replays the steps
// since the snapshot (and restores the modules' state), so it reaches the same last good state from either.
TEST(Restart, TheGuardStopsTheRestartedRunWhereItStoppedTheOriginal) {
  const fs::path dir = scratch("restart_guard");
  // A block thrown at 20 m/s through the +x face: it leaves the grid after about 19 steps.
  std::ofstream(dir / "scene.yaml")
      << "dimension: 2\n"
         "grid: {origin: [0, 0], extent: [1, 1], cell_size: 0.05}\n"
         "materials: {m: {model: linear_elastic, density: 1000, youngs_modulus: 1.0e4, poisson_ratio: 0.3}}\n"
         "bodies: [{name: block, material: m, shape: {type: box, min: [0.3, 0.3], max: [0.6, 0.6]}, velocity: [20, "
         "0]}]\n"
         "solver: {cfl: 0.5, end_time: 1}\n"
         "output: {interval: 0.005, fields: [velocity, stress]}\n";
  const std::string run = "run " + (dir / "scene.yaml").string() + " -o ";
  const Result ref = cli::mpm(run + (dir / "reference").string(), dir);
  ASSERT_EQ(ref.status, 3) << ref.err;
  const Result stopped = cli::mpm(run + (dir / "run").string() + " --test-signal-at 7:TERM", dir);
  ASSERT_EQ(stopped.status, 143) << stopped.err;
  const Result resumed =
      cli::mpm(run + (dir / "run").string() + " --restart " + (dir / "run" / "checkpoints").string(), dir);
  EXPECT_EQ(resumed.status, 3) << resumed.err;
  const auto guard = [](const std::string& err) { return err.substr(err.find("stability guard: step")); };
  EXPECT_EQ(guard(resumed.err), guard(ref.err));
  expect_same_files(dir / "reference", dir / "run");
  if (!HasFailure()) fs::remove_all(dir);
}

}  // namespace

namespace {

using namespace restart_support;

// wall_interval: a checkpoint whenever that much wall-clock time has passed (here after every step of the first
// 12); keep: the newest three are left.
TEST(Restart, WallIntervalAndKeep) {
  const fs::path dir = scratch("restart_wall_interval");
  std::ofstream(dir / "scene.yaml") << with_checkpoint(two_disks().scene,
                                                       "  checkpoint: {wall_interval: 1.0e-9, keep: 3}\n");
  const Result r = cli::mpm("run " + (dir / "scene.yaml").string() + " --steps 12 -o " + (dir / "out").string(), dir);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(checkpoint_steps(dir / "out" / "checkpoints"), (std::vector<long long>{10, 11, 12}));
  if (!HasFailure()) fs::remove_all(dir);
}

}  // namespace
