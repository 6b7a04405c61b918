// Reaction histories of the contact module's rigid partners (reaction_provider.hpp): the ring-crush platens
// (examples/09_ring_crush) against the contact module's own force CSV, step by step; and a rigid plane under a
// block at rest, whose reaction balances the block's weight and is the force the module logs.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "../apps/run_mpm.hpp"
#include "../libmpm/history_fixture.hpp"
#include "contact_scene_support.hpp"

namespace mpm::test {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> cells;
  std::stringstream s(line);
  std::string cell;
  while (std::getline(s, cell, ',')) cells.push_back(cell);
  return cells;
}

TEST(ReactionHistory, RingCrushPlatensEqualTheContactCsv) {
  // The example with a row at every step in both files (intervals far below the time step), its platens moved
  // onto the ring (the example starts them 0.37 mm away: 1,500 steps before they touch).
  YAML::Node scene = YAML::LoadFile(std::string(MPM_SOURCE_DIR) + "/examples/09_ring_crush/scene.yaml");
  scene["contact"]["force_interval"] = 1e-12;
  for (const YAML::Node& body : scene["bodies"]) {
    const double side = body["name"].as<std::string>() == "top_platen" ? 1 : -1;
    if (body["name"].as<std::string>() == "ring") continue;
    YAML::Node shape = body["shape"];
    shape["min"][1] = side > 0 ? 0.02545 : -0.02745;
    shape["max"][1] = side > 0 ? 0.02745 : -0.02545;
  }
  YAML::Node histories;
  for (const char* platen : {"top_platen", "bottom_platen"}) {
    YAML::Node h;
    h["name"] = platen;
    h["type"] = "reaction";
    h["body"] = platen;
    h["interval"] = 1e-12;
    histories.push_back(h);
  }
  scene["output"]["histories"] = histories;
  const auto dir = cli::scratch("ring_reaction");
  {
    std::ofstream out(dir / "ring.yaml");
    out << scene;
  }
  const auto r = cli::mpm("run " + (dir / "ring.yaml").string() + " --steps 150 -o " + (dir / "out").string(), dir);
  ASSERT_EQ(r.status, 0) << r.err;
  // The contact CSV: force on the ring from each platen, per step (10 significant digits).
  std::map<std::string, std::map<double, std::pair<double, double>>> csv;
  std::ifstream forces(dir / "out" / "ring_forces.csv");
  std::string line;
  std::getline(forces, line);
  while (std::getline(forces, line)) {
    const auto c = split(line);
    if (c[1] == "ring" && c[2].find("platen") != std::string::npos)
      csv[c[2]][std::stod(c[0])] = {std::stod(c[5]), std::stod(c[6])};
  }
  int compared = 0;
  double largest = 0;
  for (const char* platen : {"top_platen", "bottom_platen"}) {
    std::ifstream history(dir / "out" / (std::string(platen) + ".csv"));
    std::getline(history, line);
    EXPECT_EQ(line, "time [s],step,force_x [N/m],force_y [N/m]");
    while (std::getline(history, line)) {
      const auto c = split(line);
      const double t = std::stod(c[0]), fx = std::stod(c[2]), fy = std::stod(c[3]);
      // find the CSV row of this step (times written with 10 digits)
      const auto& rows = csv[platen];
      const auto it = rows.lower_bound(t * (1 - 1e-9));
      if (it == rows.end() || std::abs(it->first - t) > 1e-9 * t) {
        EXPECT_EQ(fy, 0.0) << platen << " at t = " << t << ": a reaction without a contact row";
        continue;
      }
      EXPECT_NEAR(fx, it->second.first, 1e-9 * std::abs(fy) + 1e-9) << platen << " t = " << t;
      EXPECT_NEAR(fy, it->second.second, 2e-9 * std::abs(fy)) << platen << " t = " << t;
      largest = std::max(largest, std::abs(fy));
      ++compared;
    }
  }
  std::printf("[ measured ] %d platen rows equal to the contact CSV; largest |force_y| %.4g N/m\n", compared, largest);
  EXPECT_GT(compared, 20);
  EXPECT_GT(largest, 0);
  fs::remove_all(dir);
}

TEST(ReactionHistory, RigidPlaneCarriesTheWeightOfABlockAtRest) {
  // A block on a frictionless rigid plane (not a grid face) under gravity; PIC damps it to rest.
  auto m = measured<2>(R"(
dimension: 2
grid: {origin: [0, -0.1], extent: [0.6, 0.5], cell_size: 0.05}
materials: {m: {model: linear_elastic, density: 1000, youngs_modulus: 2.0e5, poisson_ratio: 0.25}}
bodies:
  - {name: block, material: m, shape: {type: box, min: [0.2, 0.0], max: [0.4, 0.2]}}
solver: {scheme: musl, flip_fraction: 0, cfl: 0.5, end_time: 3.0, gravity: [0, -10]}
contact:
  planes: [{name: floor, point: [0, 0], normal: [0, 1]}]
output:
  interval: 0.1
  histories:
    - {name: floor, type: reaction, plane: floor, moment_about: [0.3, 0]}
)");
  auto* contact = contact_module(*m->sim);
  ASSERT_NE(contact, nullptr);
  std::vector<double> row;
  int steps = 0;
  m->sim->run([&](const Simulation<2>&) {
    row = m->sample(0);  // the mean over one step: the step's force (dt F / dt: equal to round-off)
    Vec<2> logged = Vec<2>::Zero();
    for (const auto& f : contact->last_forces())
      if (f.body == 0 && f.other == -1) logged = f.force;
    ASSERT_NEAR(row[0], logged[0], 1e-14 * logged.norm());
    ASSERT_NEAR(row[1], logged[1], 1e-14 * logged.norm());
    ++steps;
  });
  const double weight = 1000 * 0.2 * 0.2 * 10;
  std::printf("[ measured ] plane reaction after %d steps: %.12g N/m (weight %.12g), moment %.3g N\n", steps, row[1],
              weight, row[2]);
  EXPECT_NEAR(row[1], weight, 1e-6 * weight);
  EXPECT_NEAR(row[2], 0.0, 1e-6 * weight * 0.1);  // symmetric about x = 0.3
}

// The contact force on a body (reaction `on:`), a regular time series whether or not the bodies touch: the two
// disks of review §6.1.2 with the contact defaults, a row every step. Newton's third law row by row (the pair
// correction at a node gives the two bodies equal and opposite impulses), zero before they meet, and the force
// on each disk integrated over the run is its change of momentum (nothing else acts on it: no gravity, no
// boundary; the internal forces of a body's own field sum to zero, partition of unity), at every step the force
// history of the body (type: force, from the particles' momenta).
TEST(ReactionHistory, ContactForceOnABodyIsItsRateOfChangeOfMomentum) {
  std::string yaml = two_disks_scene;
  for (const auto& [key, value] : std::vector<std::pair<std::string, std::string>>{{"@SCHEME@", "musl"},
                                                                                   {"@SHAPE@", "linear"},
                                                                                   {"@ONSET@", "particle_gap"},
                                                                                   {"@MU@", "0"},
                                                                                   {"@NORMALS@", "mass_gradient"}})
    yaml.replace(yaml.find(key), key.size(), value);
  yaml.replace(yaml.find("end_time: 3.5"), 13, "end_time: 2.5");
  yaml += R"(output:
  interval: 0.1
  histories:
    - {name: on_a, type: reaction, on: lower_left, from: upper_right, interval: 1.0e-9}
    - {name: on_b, type: reaction, on: upper_right, interval: 1.0e-9}
    - {name: force_a, type: force, body: lower_left, interval: 1.0e-9}
)";
  auto m = measured<2>(yaml);
  auto momentum = [&](int b) {
    Vec<2> p = Vec<2>::Zero();
    const auto& ps = m->sim->bodies()[static_cast<std::size_t>(b)].particles;
    for (Index i = 0; i < ps.size(); ++i) p += ps.mass[i] * Vec<2>(ps.v[i]);
    return p;
  };
  const Vec<2> a0 = momentum(0), b0 = momentum(1);
  Vec<2> impulse_a = Vec<2>::Zero(), impulse_b = Vec<2>::Zero();
  double peak = 0, worst_third_law = 0, first_force = -1, last_time = 0, worst_balance = 0;
  m->sim->run([&](const Simulation<2>& sim) {
    const auto a = m->sample(0), b = m->sample(1);  // the mean over the step: the step's force
    const Vec<2> fa(a[0], a[1]), fb(b[0], b[1]);
    const auto f = m->sample(2);  // the force history: the body's rate of change of momentum
    worst_balance = std::max(worst_balance, (Vec<2>(f[0], f[1]) - fa).norm());
    const double dt = sim.time() - last_time;
    last_time = sim.time();
    impulse_a += dt * fa;
    impulse_b += dt * fb;
    peak = std::max(peak, fa.norm());
    worst_third_law = std::max(worst_third_law, (fa + fb).norm());
    if (first_force < 0 && fa.norm() > 0) first_force = sim.time();
  });
  const Vec<2> da = momentum(0) - a0, db = momentum(1) - b0;
  std::printf(
      "[ measured ] peak contact force %.6g N/m, first at t = %.4g s; |F_a + F_b| <= %.3g N/m; impulse on a "
      "(%.9g, %.9g) against its momentum change (%.9g, %.9g) N s/m\n",
      peak, first_force, worst_third_law, impulse_a[0], impulse_a[1], da[0], da[1]);
  EXPECT_GT(first_force, 1.0);  // the disks' gap closes at about 1.3-1.6 s
  EXPECT_GT(peak, 0.1);
  EXPECT_LT(worst_third_law, 1e-12 * peak);
  std::printf("[ measured ] |force history - contact force| <= %.3g N/m at every step\n", worst_balance);
  EXPECT_LT(worst_balance, 1e-9 * peak);
  EXPECT_LT((impulse_a - da).norm(), 1e-9 * da.norm());
  EXPECT_LT((impulse_b - db).norm(), 1e-9 * db.norm());
  EXPECT_GT(da.norm(), 0.5 * a0.norm());  // the collision reverses most of the disk's momentum
}

}  // namespace
}  // namespace mpm::test
