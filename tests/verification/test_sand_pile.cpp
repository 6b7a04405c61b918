// Angle of repose of a cohesionless sand pile in plane strain (issue 52, item 4): the static slope limit of a
// Mohr-Coulomb continuum is the friction angle (docs/theory.md eq. 18.25), and that of the Drucker-Prager cone in plane
// strain the angle of eq. 18.26 (phi itself for the plane_strain matching with associated flow; asin(eta) with no
// dilation). Half of a symmetric pile: a column of sand L0 = 1 m wide and H0 = 1 m tall against a smooth wall
// (x_min: slip, the plane of symmetry) on a rough base (y_min: fixed), released from rest and zero stress under
// gravity with local (Cundall) damping (docs/theory.md eq. 2.74), which takes the inertia out of the collapse: the
// flank fails and creeps until it stands at the limit. Sand: rho = 1800 kg/m^3, E = 2 MPa, nu = 0.3, c = 0, psi = 0;
// MUSL, quadratic B-splines, APIC, 2 particles per cell per axis.
//
// The slope (bench/sand_pile.py, flank_angle): the free surface is the highest particle of each column of one cell
// along x (its y plus half a particle spacing); the flank is the surface points between 25% and 75% of the pile's
// height, which leaves out the toe and the rounded crest; the angle is that of their least-squares line.
//
// What the numbers rest on (docs/verification-notes.md, "Angle of repose"; the ladders of bench/sand_pile.py): the
// damping takes the overshoot of the falling flank out (damping 0.8 leaves it 6 degrees below phi = 35 deg); the
// run must be long enough for the flank to creep down to the limit.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "../libmpm/scene_fixture.hpp"
#include "granular_column.hpp"

namespace mpm::sand_pile_test {  // named: the unity build puts the verification tests in one unit

constexpr double L0 = 1, H0 = 1, g = 9.81;
constexpr double degree = std::numbers::pi / 180;

struct Pile {
  std::string model;  ///< mohr_coulomb or drucker_prager (plane_strain matching)
  double phi;         ///< deg
  int cells;          ///< per L0
  double damping;     ///< solver.damping
  double time;        ///< end time in sqrt(H0/g)
};

std::string pile_scene(const Pile& p) {
  verification::GranularColumn c;
  c.width = L0;
  c.height = H0;
  c.cell = L0 / p.cells;
  // room for a flank flatter than 25 deg (bench/sand_pile.py)
  c.cells_x = static_cast<int>(std::ceil((L0 + 1.3 * H0 / std::tan(std::min(p.phi, 25.0) * degree)) * p.cells)) + 4;
  c.cells_y = static_cast<int>(std::ceil(1.05 * H0 * p.cells)) + 2;
  c.material_name = "sand";
  c.material = "{model: " + p.model +
               ", density: 1800, youngs_modulus: 2.0e6, poisson_ratio: 0.3, friction_angle: " + std::to_string(p.phi) +
               ", dilation_angle: 0" + (p.model == "drucker_prager" ? ", cone_matching: plane_strain}" : "}");
  c.solver = "shape_function: quadratic_bspline, damping: " + std::to_string(p.damping) + ", ";
  c.end_time = p.time * std::sqrt(H0 / g);
  return verification::granular_column_scene(c);
}

/// The static slope limit in plane strain (docs/theory.md eqs. 18.25-18.26), deg: phi for Mohr-Coulomb; for the
/// plane_strain cone with psi = 0, asin(eta) with eta of eq. 18.3.
double slope_limit(const Pile& p) {
  if (p.model == "mohr_coulomb") return p.phi;
  const double t = std::tan(p.phi * degree);
  return std::asin(3 * t / std::sqrt(9 + 12 * t * t)) / degree;
}

/// The surface: the highest particle of each column of width h along x, (x, y + spacing/2).
std::vector<std::pair<double, double>> surface(const Particles<2>& p, double h, double spacing) {
  std::map<long, std::pair<double, double>> top;
  for (Index i = 0; i < p.size(); ++i) {
    const long k = static_cast<long>(std::floor(p.x[i][0] / h));
    auto it = top.find(k);
    if (it == top.end() || p.x[i][1] > it->second.second) top[k] = {p.x[i][0], p.x[i][1]};
  }
  std::vector<std::pair<double, double>> s;
  for (const auto& [k, xy] : top) s.emplace_back(xy.first, xy.second + spacing / 2);
  return s;
}

struct Flank {
  double angle;  ///< deg, atan of minus the least-squares slope
  int points;
};

/// The least-squares line through the surface points between 25% and 75% of the highest.
Flank flank(const std::vector<std::pair<double, double>>& s) {
  double H = 0;
  for (const auto& [x, y] : s) H = std::max(H, y);
  double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (const auto& [x, y] : s) {
    if (y < 0.25 * H || y > 0.75 * H) continue;
    n += 1;
    sx += x;
    sy += y;
    sxx += x * x;
    sxy += x * y;
  }
  const double slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
  return {std::atan(-slope) / degree, static_cast<int>(n)};
}

double pile_angle(const Pile& p) {
  auto sim = test::simulation_from_yaml<2>(pile_scene(p), "pile.yaml");
  sim->run();
  const double h = L0 / p.cells;
  const Flank f = flank(surface(sim->bodies().front().particles, h, h / 2));
  const EnergyBalance e = sim->energy();
  std::printf(
      "[ measured ] sand pile, %s phi = %g deg, %d cells per L0, damping %g, T = %g sqrt(H0/g): flank %.2f deg "
      "(%d surface points), static limit %.2f deg (%+.2f), rms speed at the end %.1e m/s, %lld steps\n",
      p.model.c_str(), p.phi, p.cells, p.damping, p.time, f.angle, f.points, slope_limit(p), f.angle - slope_limit(p),
      std::sqrt(2 * e.kinetic / e.mass), static_cast<long long>(sim->step()));
  EXPECT_GE(f.points, 8);  // the flank is long enough to be a line
  return f.angle;
}

}  // namespace mpm::sand_pile_test
