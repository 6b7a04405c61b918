#pragma once
/// \file sand_pile.hpp
/// The sand pile of issue 52 (angle of repose; bench/sand_pile.py is the same case from the command line): half of a
/// symmetric pile, a column of cohesionless sand L0 = 1 m wide and H0 = 1 m tall against a smooth wall (x_min: slip,
/// the plane of symmetry) on a rough base (y_min: fixed), released from rest and zero stress under gravity with local
/// (Cundall) damping (docs/theory.md eq. 2.74), which takes most of the inertia out of the collapse: the flank fails
/// and creeps towards the static slope limit (docs/theory.md eqs. 18.25-18.26). Sand: rho = 1800 kg/m^3, E = 2 MPa, nu
/// = 0.3 (rho g H0 / E = 0.9%), c = 0, psi = 0; MUSL, quadratic B-splines, APIC, 2 particles per cell per axis.
///
/// The slope is read from the final particles: the free surface is the highest particle of each column one cell wide
/// along x (its y plus half a particle spacing); the flank is the surface points between 25% and 75% of the pile's
/// height (the highest surface point), which leaves out the toe and the rounded crest; the angle is that of their
/// least-squares line.

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

namespace mpm::verification::sand_pile {

inline constexpr double L0 = 1, H0 = 1, g = 9.81;
inline constexpr double degree = std::numbers::pi / 180;

struct Pile {
  std::string model = "mohr_coulomb";  ///< or drucker_prager (cone_matching: plane_strain)
  double phi = 30;                     ///< deg, the friction angle; no dilation, no cohesion
  int cells = 20;                      ///< per L0
  double damping = 0.95;               ///< solver.damping
  double time = 40;                    ///< the end time in sqrt(H0/g)
};

inline std::string pile_scene(const Pile& p) {
  GranularColumn c;
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
  return granular_column_scene(c);
}

/// The static slope limit in plane strain, deg: phi for Mohr-Coulomb (docs/theory.md eq. 18.25); for the
/// plane_strain cone with psi = 0, asin(eta) with eta of eq. 18.3 (eq. 18.26).
inline double slope_limit(const Pile& p) {
  if (p.model == "mohr_coulomb") return p.phi;
  const double t = std::tan(p.phi * degree);
  return std::asin(3 * t / std::sqrt(9 + 12 * t * t)) / degree;
}

/// The surface: the highest particle of each column of width h along x, (x, y + spacing/2), by x.
inline std::vector<std::pair<double, double>> surface(const Particles<2>& p, double h, double spacing) {
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
  double angle = 0;  ///< deg, atan of minus the least-squares slope
  int points = 0;    ///< surface points on the flank
};

/// The least-squares line through the surface points between 25% and 75% of the highest.
inline Flank flank(const std::vector<std::pair<double, double>>& s) {
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
  if (n < 2) return {};
  return {std::atan(-(n * sxy - sx * sy) / (n * sxx - sx * sx)) / degree, static_cast<int>(n)};
}

struct PileResult {
  Flank flank;
  double limit = 0;  ///< deg, slope_limit
  double speed = 0;  ///< m/s, the rms speed at the end
  long long steps = 0;
};

inline PileResult run_pile(const Pile& p) {
  auto sim = test::simulation_from_yaml<2>(pile_scene(p), "pile.yaml");
  sim->run();
  const double h = L0 / p.cells;
  PileResult r;
  r.flank = flank(surface(sim->bodies().front().particles, h, h / 2));
  r.limit = slope_limit(p);
  const EnergyBalance e = sim->energy();
  r.speed = std::sqrt(2 * e.kinetic / e.mass);
  r.steps = static_cast<long long>(sim->step());
  std::printf(
      "[ measured ] sand pile, %s phi = %g deg, %d cells per L0, damping %g, T = %g sqrt(H0/g): flank %.2f deg "
      "(%d surface points), static limit %.2f deg (%+.2f), rms speed at the end %.1e m/s, %lld steps\n",
      p.model.c_str(), p.phi, p.cells, p.damping, p.time, r.flank.angle, r.flank.points, r.limit,
      r.flank.angle - r.limit, r.speed, r.steps);
  return r;
}

}  // namespace mpm::verification::sand_pile
