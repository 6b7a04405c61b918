// Two elastic disks (review §6.1.2, Sulsky et al. 1994; examples/02_two_disks) with Bardenhagen contact.
// Exact bodies touch at t = (|c2 - c1| - 2R) / |v2 - v1| = (0.8485 - 0.4) / 0.28284 = 1.5858 s; the
// paper's grid contact starts about a cell early (about 1.3 s). With contact the disks must release
// after the rebound (no sticking), the total momentum stays zero (equal and opposite normals, Bardenhagen
// et al. 2001) and the energy is recovered within the stated tolerance.
#include <cmath>
#include <cstdio>

#include "contact_scene_support.hpp"

namespace mpm::test {
namespace {

const std::string& disks = two_disks_scene;

struct DiskRun {
  double onset = -1, worst = 0, rise = 0, final_change = 0, momentum = 0, separation_speed = 0;
  Index contact_nodes_at_end = -1;
};

DiskRun run_disks(const std::string& scheme, const std::string& shape, const std::string& onset, double mu = 0,
                  const std::string& normals = "mass_gradient") {
  auto sim = simulation_from_yaml<2>(fill(disks, {{"SCHEME", with_paper_transfer(scheme)},
                                                  {"SHAPE", shape},
                                                  {"ONSET", onset},
                                                  {"MU", std::to_string(mu)},
                                                  {"NORMALS", normals}}));
  auto* contact = contact_module(*sim);
  EXPECT_NE(contact, nullptr);
  const double e0 = sim->energy().total();
  DiskRun r;
  // Momentum drift from t = 1 s (before any contact): USF changes the momentum by 7.6e-5 near t = 0.15 s
  // with or without contact (a property of the core USF step, not of contact).
  Vec<2> p_before = Vec<2>::Zero();
  sim->run([&](const Simulation<2>& s) {
    r.worst = std::max(r.worst, std::abs(s.energy().total() / e0 - 1));
    r.rise = std::max(r.rise, s.energy().total() / e0 - 1);
    if (s.time() <= 1.0) p_before = total_momentum(s);
    if (s.time() > 1.0) r.momentum = std::max(r.momentum, (total_momentum(s) - p_before).norm());
  });
  r.onset = contact->onset_time();
  r.final_change = sim->energy().total() / e0 - 1;
  r.contact_nodes_at_end = contact->contact_node_count();
  // Relative velocity along the line of centres, positive when the disks move apart.
  const Vec<2> dv = body_velocity(sim->bodies()[1]) - body_velocity(sim->bodies()[0]);
  r.separation_speed = dv.dot(Vec<2>(1, 1).normalized());
  // a collision without friction never gains energy, with either onset (here also with friction)
  EXPECT_LT(r.rise, 0.005) << scheme << "/" << shape << " onset " << onset;
  std::printf(
      "[ measured ] two disks %s/%s onset %s mu %.1f: contact at t = %.4f s (exact 1.5858 s); total energy worst "
      "%.3e, largest rise %+.2e, final %+.3e; momentum drift %.2e; separation speed %.4f m/s (approach 0.2828)\n",
      scheme.c_str(), shape.c_str(), onset.c_str(), mu, r.onset, r.worst, r.rise, r.final_change, r.momentum,
      r.separation_speed);
  return r;
}

// Paper's criterion (contact nodes): onset one cell early.
TEST(TwoDisksContact, GridCriterionMusl) {
  const DiskRun r = run_disks("musl", "linear", "grid");
  EXPECT_NEAR(r.onset, 1.13, 0.05);      // measured 1.130 s (0.46 s early: a node is shared one cell early)
  EXPECT_EQ(r.contact_nodes_at_end, 0);  // released
  EXPECT_GT(r.separation_speed, 0.2);    // measured 0.25: clean rebound
  EXPECT_LT(r.momentum, 1e-12);          // zero initially; equal and opposite normals keep it zero
  // Measured -9.5% (worst -14.4% at the deepest point of the impact): the release of nodes separating at v^t
  // (with the paper's corrections -1.2%, worst -10.6%) dissipates more.
  EXPECT_LT(std::abs(r.final_change), 0.11);
  EXPECT_LT(r.worst, 0.16);
}

// Particle-gap criterion (contact/README.md): onset within about a particle spacing / closing speed.
TEST(TwoDisksContact, ParticleGapCriterionMusl) {
  const DiskRun r = run_disks("musl", "linear", "particle_gap");
  EXPECT_NEAR(r.onset, 1.5858, 0.06);  // measured 1.540 s
  EXPECT_EQ(r.contact_nodes_at_end, 0);
  EXPECT_GT(r.separation_speed, 0.2);
  EXPECT_LT(r.momentum, 1e-12);
  EXPECT_LT(std::abs(r.final_change), 0.04);  // measured -2.9% (-2.3% with the paper's Remark 33)
}

// Normals from the cell-centred density (eqs 5.9-5.11) instead of the mass gradient (5.12): the review
// found them identical; here the onset is the same and the rebound within 0.02 m/s of the other.
TEST(TwoDisksContact, DensityNormals) {
  const DiskRun gradient = run_disks("musl", "linear", "grid");
  const DiskRun density = run_disks("musl", "linear", "grid", 0, "density");
  EXPECT_NEAR(density.onset, gradient.onset, 1e-9);
  EXPECT_EQ(density.contact_nodes_at_end, 0);
  EXPECT_NEAR(density.separation_speed, gradient.separation_speed, 0.02);
  EXPECT_LT(density.momentum, 1e-12);
  EXPECT_LT(std::abs(density.final_change), 0.11);  // measured -9.7% (mass gradient: -9.5%)
}

// The other schemes and the cubic B-spline: clean release, momentum kept, onset as measured. The grid
// criterion starts contact at 1.127 s with hat functions and 0.636 s with cubic B-splines (wider
// support, review §6.1.2); the particle gap at 1.537 s and 1.528 s. USL and the B-splines dissipate more
// (final energy -12% USL, -13% to -19% B-splines with the grid criterion).
TEST(TwoDisksContact, OtherSchemesAndShapes) {
  for (const auto& [scheme, shape] : {std::pair<std::string, std::string>{"usl", "linear"},
                                      {"usf", "linear"},
                                      {"musl", "cubic_bspline"},
                                      {"usf", "cubic_bspline"}}) {
    const DiskRun grid = run_disks(scheme, shape, "grid");
    const DiskRun gap = run_disks(scheme, shape, "particle_gap", 0.2);
    EXPECT_LT(grid.onset, gap.onset) << scheme << "/" << shape;
    EXPECT_NEAR(gap.onset, 1.5858, 0.1) << scheme << "/" << shape;
    for (const DiskRun* r : {&grid, &gap}) {
      EXPECT_EQ(r->contact_nodes_at_end, 0) << scheme << "/" << shape;
      EXPECT_GT(r->separation_speed, 0.15) << scheme << "/" << shape;
      EXPECT_LT(r->momentum, 1e-9) << scheme << "/" << shape;  // measured <= 7e-11 (kg m/s; p0 = 26 per disk)
      EXPECT_LT(std::abs(r->final_change), 0.25) << scheme << "/" << shape;
    }
  }
}

// CPDI (review §3.6): the normals from the CPDI gradients (the ones its P2G uses), the particle gap from the
// domains' corners. CPDI-R4 (domains follow F) and CPDI-Q4 (corners tracked with each body's own nodal velocity).
// Measured (both functions alike): grid criterion at 1.002 s (the CPDI stencil reaches two cells, earlier than the
// hat's 1.127 s), final energy -19.2% (R4), -19.1% (Q4); particle gap at 1.502 s (the square domains' corners along
// the diagonal normal reach half a diagonal, 0.018 m, beyond the centre), final energy -5.1% (R4), -4.3% (Q4);
// rebound 0.210-0.226 m/s; never above E0. (With the paper's corrections alone: -10%, -3.7%, -3.1%.)
// With the Q4 corners moved by the shared field (the velocity of both bodies, as before contact was allowed with
// CPDI): particle gap at 1.658 s, final energy -18.8%, the disks stuck (8 contact nodes, separation -0.013 m/s).
TEST(TwoDisksContact, Cpdi) {
  for (const std::string shape : {"cpdi_r4", "cpdi_q4"}) {
    const DiskRun grid = run_disks("musl", shape, "grid");
    const DiskRun gap = run_disks("musl", shape, "particle_gap");
    EXPECT_NEAR(grid.onset, 1.00, 0.05) << shape;
    EXPECT_NEAR(gap.onset, 1.5858, 0.1) << shape;
    EXPECT_LT(std::abs(grid.final_change), 0.21) << shape;
    EXPECT_LT(std::abs(gap.final_change), 0.06) << shape;
    for (const DiskRun* r : {&grid, &gap}) {
      EXPECT_EQ(r->contact_nodes_at_end, 0) << shape;  // released
      EXPECT_GT(r->separation_speed, 0.2) << shape;
      EXPECT_LT(r->momentum, 1e-12) << shape;  // measured <= 3.2e-14
    }
  }
}

// APIC (velocity_transfer: apic) with contact, formerly refused ("a block on a contact plane diverges"): every
// body maps v_p + C_p (x_I - x_p) to its own nodal field and takes C_p from its own corrected velocities. Same
// checks as the FLIP runs on onset, release, momentum and rebound. The energy is not held to FLIP's bound:
// APIC dissipates the disks' vibration after the impact whether or not there is contact (MUSL, hats, no
// contact section, the disks then stick: -26.7% by 3.5 s); measured with contact, with the release of nodes
// separating at v^t under the grid criterion: -41.8% / -28.7% (MUSL, grid / particle gap) and
// -40.6% / -27.7% (USF); before that release -24.3% / -25.4% and -36.6% / -27.7%. Asserted: the energy only
// decreases (the contact correction adds none) and by less than 45%.
TEST(TwoDisksContact, Apic) {
  for (const std::string scheme : {"musl", "usf"}) {
    const DiskRun grid = run_disks(scheme + ", velocity_transfer: apic", "linear", "grid");
    const DiskRun gap = run_disks(scheme + ", velocity_transfer: apic", "linear", "particle_gap", 0.2);
    EXPECT_NEAR(grid.onset, 1.13, 0.05) << scheme;   // as FLIP: measured 1.126 s
    EXPECT_NEAR(gap.onset, 1.5858, 0.06) << scheme;  // measured 1.537 s
    for (const DiskRun* r : {&grid, &gap}) {
      EXPECT_EQ(r->contact_nodes_at_end, 0) << scheme;  // released
      EXPECT_GT(r->separation_speed, 0.2) << scheme;    // measured 0.221 to 0.241 (approach 0.283)
      EXPECT_LT(r->momentum, 1e-12) << scheme;          // measured <= 4.5e-14
      EXPECT_LT(r->final_change, 0) << scheme;
      EXPECT_NEAR(r->worst, -r->final_change, 1e-3) << scheme;  // never above E0: the largest change is the loss
      EXPECT_GT(r->final_change, -0.45) << scheme;
    }
  }
}

// PolyPIC (velocity_transfer: polypic) with contact: each body maps v_p + C_p r + its higher modes to its own field
// and takes them from its own corrected velocities. PolyPIC's transfer loses nothing at nodes of full mass, so it
// keeps far more of the disks' energy than APIC (above): measured with MUSL -24.3% (grid criterion) and -6.35%
// (particle gap) by 3.5 s (APIC -41.8% / -28.7%), never above E0 by more than 3.4e-6 (before contact), momentum
// drift <= 2.7e-13. Asserted: the same checks as APIC, with bounds about 1.2x the measured losses.
TEST(TwoDisksContact, PolyPic) {
  const DiskRun grid = run_disks("musl, velocity_transfer: polypic", "linear", "grid");
  const DiskRun gap = run_disks("musl, velocity_transfer: polypic", "linear", "particle_gap");
  EXPECT_NEAR(grid.onset, 1.13, 0.05);   // as FLIP
  EXPECT_NEAR(gap.onset, 1.5858, 0.06);  // as FLIP
  for (const DiskRun* r : {&grid, &gap}) {
    EXPECT_EQ(r->contact_nodes_at_end, 0);  // released
    EXPECT_GT(r->separation_speed, 0.2);
    EXPECT_LT(r->momentum, 1e-12);
    EXPECT_LT(r->rise, 1e-5);  // never above E0 but for the scheme's own 3.4e-6 before contact
  }
  EXPECT_GT(grid.final_change, -0.30);
  EXPECT_GT(gap.final_change, -0.08);
}

}  // namespace
}  // namespace mpm::test
