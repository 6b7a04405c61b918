#pragma once
/// \file sand_pile.hpp
/// The sand pile of issue 52 (angle of repose; bench/sand_pile.py is the same case from the command line): half of a
/// symmetric pile, a column of cohesionless sand L0 = 1 m wide and H0 = 1 m tall against a smooth wall (x_min: slip,
/// the plane of symmetry) on a rough base (y_min: fixed), released from rest and zero stress under gravity with local
/// (Cundall) damping (docs/theory.md eq. 2.74), which takes the inertia out of the collapse: the flank fails, flows and
/// stops. Sand: rho = 1800 kg/m^3, E = 2 MPa, nu = 0.3 (rho g H0 / E = 0.9%), c = 0, no dilation (psi = 0); MUSL,
/// quadratic B-splines, APIC, 2 particles per cell per axis.
///
/// The references (docs/theory.md eqs. 18.25-18.27): a flowing surface layer stops at tan(beta_flow) = sin(phi) for
/// Mohr-Coulomb without dilation (22.91 and 29.84 deg at phi = 25 and 35 deg; Davis 1968) and at tan(beta_flow) = eta
/// for the plane_strain Drucker-Prager cone (22.32 and 28.57 deg); a slope can stand up to the static limit, phi for
/// Mohr-Coulomb and asin(eta) for the cone (24.24 and 32.99 deg). The two agree (at phi) only for associated flow.
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
  double damping = 0.8;                ///< solver.damping
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

/// The plane_strain cone's eta (docs/theory.md eq. 18.3).
inline double plane_strain_eta(double phi_deg) {
  const double t = std::tan(phi_deg * degree);
  return 3 * t / std::sqrt(9 + 12 * t * t);
}

/// The static slope limit in plane strain, deg: phi for Mohr-Coulomb (docs/theory.md eq. 18.25); asin(eta) for the
/// plane_strain cone with psi = 0 (eq. 18.26).
inline double static_limit(const Pile& p) {
  return p.model == "mohr_coulomb" ? p.phi : std::asin(plane_strain_eta(p.phi)) / degree;
}

/// The slope at which a layer flowing parallel to the surface stops, deg (docs/theory.md eq. 18.27 with psi = 0):
/// atan(sin phi) for Mohr-Coulomb, atan(eta) for the plane_strain cone.
inline double flow_limit(const Pile& p) {
  return std::atan(p.model == "mohr_coulomb" ? std::sin(p.phi * degree) : plane_strain_eta(p.phi)) / degree;
}

/// The surface: the highest particle of each column of width h along x, (x, y + spacing/2), by x.
inline std::vector<std::pair<double, double>> surface(const ParticleSet<2>& p, double h, double spacing) {
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
  double beta_flow = 0, beta_static = 0;  ///< deg, flow_limit and static_limit
  double speed = 0;                       ///< m/s, the rms speed at the end
  long long steps = 0;
};

inline PileResult run_pile(const Pile& p) {
  auto sim = test::simulation_from_yaml<2>(pile_scene(p), "pile.yaml");
  sim->run();
  const double h = L0 / p.cells;
  PileResult r;
  r.flank = flank(surface(sim->bodies().front().particles, h, h / 2));
  r.beta_flow = flow_limit(p);
  r.beta_static = static_limit(p);
  const EnergyBalance e = sim->energy();
  r.speed = std::sqrt(2 * e.kinetic / e.mass);
  r.steps = static_cast<long long>(sim->step());
  std::printf(
      "[ measured ] sand pile, %s phi = %g deg, %d cells per L0, damping %g, T = %g sqrt(H0/g): flank %.2f deg "
      "(%d surface points); flowing limit %.2f deg (%+.2f), static limit %.2f deg (%+.2f); rms speed at the end "
      "%.1e m/s, %lld steps\n",
      p.model.c_str(), p.phi, p.cells, p.damping, p.time, r.flank.angle, r.flank.points, r.beta_flow,
      r.flank.angle - r.beta_flow, r.beta_static, r.flank.angle - r.beta_static, r.speed, r.steps);
  return r;
}

}  // namespace mpm::verification::sand_pile
