// Generalized vortex (review §6.2.3, Figs 74-75; digest §C.8): the ring 0.75 <= R <= 1.25 m turned by
// alpha = sin(pi t) h(R), driven by the manufactured body force (corrected eq. 6.18), runner vortex.cpp.
// Error e1 of eqs A.11-A.12 (max over the steps of the volume-weighted RMS displacement error); rate = the
// least-squares slope of log e1 against log h. The review reports for the TLMPM (linear and Bernstein) order
// 2 on coarse grids, the order then falling and the error plateauing; "no MPM variant performs well".
//
// Settings common to all cases: grid [-1.5, 1.5]^2 m with N cells per side (h = 3/N), 2 particles per cell
// per axis on the sub-cell centres inside the ring, pure FLIP, dt = 0.2 h / (c + v_max) (halving it changes
// e1 by less than 0.5%), nodes outside the ring fixed as in the review, exact initial velocity.
// The review's FLIP fraction 0.99: TLMPM linear e1 at N = 40, 60, 80 is 8.14e-2, 5.80e-2, 3.80e-2 (as with
// pure FLIP); Bernstein at N = 60, 80, 120: 8.12e-2, 3.66e-2, 2.24e-2 (17-45% above pure FLIP).
// With MPM_VORTEX_OUTPUT=DIR set, the finest Bernstein run writes ParaView frames of the ring to DIR.
// The whole file takes 15-23 s on one core (Release), half of it for the cubic B-spline.
#include <gtest/gtest.h>

#include "convergence.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "vortex.hpp"

namespace mpm {
namespace {

using verification::join;
using verification::observed_rate;

VortexSpec spec(const char* scheme, const char* shape, int cells) {
  VortexSpec s;
  s.scheme = scheme;
  s.shape_function = shape;
  s.cells_across = cells;
  s.particles_per_cell_per_axis = 2;
  s.flip_fraction = 1;
  return s;
}

struct VortexLadder {
  const char* scheme;
  const char* shape;
  std::vector<int> cells;  ///< cells per side, coarse to fine
  std::size_t fit_points;  ///< the asserted rate is fitted on the first fit_points resolutions
  double min_rate;         ///< lower bound of that rate
  double max_e1;           ///< bound of e1 at the finest resolution (m)
};

void check(const VortexLadder& c) {
  std::vector<double> h, e1, e2, cells, particles;
  double wall = 0;
  for (std::size_t k = 0; k < c.cells.size(); ++k) {
    VortexSpec s = spec(c.scheme, c.shape, c.cells[k]);
    const char* out = std::getenv("MPM_VORTEX_OUTPUT");
    if (out && std::string(c.shape) == "bernstein" && k + 1 == c.cells.size()) s.output_directory = out;
    const VortexResult r = run_vortex(s);
    EXPECT_TRUE(r.failure.empty()) << c.scheme << "/" << c.shape << " N = " << c.cells[k] << ": " << r.failure;
    EXPECT_NEAR(r.steps * r.dt, 1.0, 1e-9);
    h.push_back(r.h);
    e1.push_back(r.e1);
    e2.push_back(r.e2);
    cells.push_back(c.cells[k]);
    particles.push_back(static_cast<double>(r.particles));
    wall += r.wall_seconds;
  }
  const double rate_all = observed_rate(h, e1, 0, h.size()), rate_fit = observed_rate(h, e1, 0, c.fit_points);
  const double rate_last = observed_rate(h, e1, h.size() - 2, h.size());
  std::printf(
      "[ measured ] vortex %s/%s: N = %s; particles = %s; e1 = %s; e2 = %s; rate %.2f (all), %.2f (first %zu), %.2f "
      "(last two); asserted rate >= %.2f, finest e1 < %g; %.2f s\n",
      c.scheme, c.shape, join(cells, "%.0f").c_str(), join(particles, "%.0f").c_str(), join(e1, "%.3e").c_str(),
      join(e2, "%.3e").c_str(), rate_all, rate_fit, c.fit_points, rate_last, c.min_rate, c.max_e1, wall);
  for (std::size_t i = 0; i < e1.size(); ++i)
    EXPECT_TRUE(std::isfinite(e1[i]) && std::isfinite(e2[i])) << "N = " << cells[i];
  EXPECT_LT(e1.back(), c.max_e1) << c.scheme << "/" << c.shape;
  EXPECT_GE(rate_fit, c.min_rate) << c.scheme << "/" << c.shape;
}

// The body force is the manufactured one: b = a - Div P / rho0 with a and Div P by central differences of
// the exact motion (P = mu (F - F^-T) + lambda ln J F^-T, plane strain, E = 1e3 Pa, nu = 0.3, rho0 = 1000)
// at points across the ring and times over the period: they agree to 2.4e-5 m/s^2 (the differencing error;
// |b| is up to about 60 m/s^2). Eq. 6.18 as printed is off by 2 R (g'h)^2 sin(alpha) in b_Theta (6.7 m/s^2
// at these points).
TEST(Vortex, BodyForceIsManufactured) {
  using P2 = std::array<double, 2>;
  const double E = 1e3, nu = 0.3, rho0 = 1000, mu = E / (2 * (1 + nu)), lambda = E * nu / ((1 + nu) * (1 - 2 * nu));
  const auto position = [](const P2& X, double t) {
    const P2 u = vortex_displacement(X, t);
    return P2{X[0] + u[0], X[1] + u[1]};
  };
  const auto piola = [&](const P2& X, double t) {  // P(X, t), row-major
    const double d = 1e-6;
    double F[2][2];
    for (int c = 0; c < 2; ++c) {
      P2 Xp = X, Xm = X;
      Xp[c] += d;
      Xm[c] -= d;
      const P2 xp = position(Xp, t), xm = position(Xm, t);
      for (int r = 0; r < 2; ++r) F[r][c] = (xp[r] - xm[r]) / (2 * d);
    }
    const double J = F[0][0] * F[1][1] - F[0][1] * F[1][0];
    const double FinvT[2][2] = {{F[1][1] / J, -F[1][0] / J}, {-F[0][1] / J, F[0][0] / J}};
    std::array<double, 4> P;
    for (int r = 0; r < 2; ++r)
      for (int c = 0; c < 2; ++c) P[2 * r + c] = mu * (F[r][c] - FinvT[r][c]) + lambda * std::log(J) * FinvT[r][c];
    return P;
  };
  double worst = 0, worst_printed = 0;
  for (double R : {0.8, 0.9, 1.0, 1.1, 1.2})
    for (double theta : {0.3, 2.0, 4.5})
      for (double t : {0.1, 0.35, 0.6, 0.85}) {
        const P2 X{R * std::cos(theta), R * std::sin(theta)};
        const double d = 1e-4, dt = 1e-4;
        double b[2];
        for (int r = 0; r < 2; ++r) {
          double div = 0;
          for (int c = 0; c < 2; ++c) {
            P2 Xp = X, Xm = X;
            Xp[c] += d;
            Xm[c] -= d;
            div += (piola(Xp, t)[2 * r + c] - piola(Xm, t)[2 * r + c]) / (2 * d);
          }
          const double a = (position(X, t + dt)[r] - 2 * position(X, t)[r] + position(X, t - dt)[r]) / (dt * dt);
          b[r] = a - div / rho0;
        }
        const P2 ours = vortex_body_force(X, t), printed = vortex_body_force(X, t, true);
        worst = std::max({worst, std::abs(ours[0] - b[0]), std::abs(ours[1] - b[1])});
        worst_printed = std::max({worst_printed, std::abs(printed[0] - b[0]), std::abs(printed[1] - b[1])});
      }
  std::printf("[ measured ] vortex body force vs finite differences: %.2e m/s^2 (printed eq. 6.18: %.2f)\n", worst,
              worst_printed);
  EXPECT_LT(worst, 1e-4);
  EXPECT_GT(worst_printed, 1.0);
}

// Hat functions: e1 = 8.73e-2, 5.83e-2, 3.76e-2 (rate 1.20). Further down (measured outside the test) the
// local rates are 1.5-1.8: e1 = 2.07e-2, 1.24e-2, 6.14e-3 at N = 120, 160, 240. N = 20 and 30 (3 and 5 cells
// across the ring) invert a particle (det F < 0): the shear strain R g h' reaches 7.
TEST(Vortex, TlmpmLinear) { check({"tlmpm", "linear", {40, 60, 80}, 3, 1.1, 0.045}); }

// Quadratic Bernstein (element = 2 cells): e1 = 6.91e-2, 2.74e-2, 1.55e-2 (rate 2.11; local 3.22, then 1.41
// from 80 to 120). Outside the test: N = 48 gives 8.58e-2, N = 40 inverts a particle at t = 0.97 s; N = 160
// and 240 give 1.05e-2 and 4.33e-3 (local rates 1.34, 2.19): the rate dips but no plateau down to h = 0.0125.
TEST(Vortex, TlmpmBernstein) { check({"tlmpm", "bernstein", {60, 80, 120}, 3, 1.8, 0.02}); }

// Cubic B-spline: e1 = 1.84e-1, 5.30e-2, 1.97e-2, 1.29e-2 (rate 3.21 on N = 40-80, 1.04 from 80 to 120);
// N = 160 and 240 give 7.54e-3 and 3.68e-3 (local rates 1.87, 1.77).
TEST(Vortex, TlmpmCubicBSpline) { check({"tlmpm", "cubic_bspline", {40, 60, 80, 120}, 3, 2.6, 0.02}); }

// Standard MPM does not follow the vortex: MUSL with hat functions tracks it until t = 0.3 s, then the
// error grows to the size of the displacement itself: e1 = 0.82 m, e2 = 0.55 at N = 60 (0.89 and 0.92 m at
// N = 40 and 80; cubic B-spline 0.80 m, cpGIMP 0.83 m at N = 60; USL inverts a particle at t = 0.37 s).
// Asserted: the run completes and its e1 is over 5 times the TLMPM's on the same grid and particles
// (measured 14 times).
TEST(Vortex, MuslLinear) {
  const VortexResult musl = run_vortex(spec("musl", "linear", 60));
  const VortexResult tl = run_vortex(spec("tlmpm", "linear", 60));
  std::printf("[ measured ] vortex musl/linear N = 60: e1 = %.3e, e2 = %.3e (TLMPM: %.3e, %.3e); %.2f s\n", musl.e1,
              musl.e2, tl.e1, tl.e2, musl.wall_seconds + tl.wall_seconds);
  EXPECT_TRUE(musl.failure.empty()) << musl.failure;
  EXPECT_TRUE(std::isfinite(musl.e1));
  EXPECT_GT(musl.e1, 5 * tl.e1);
}

// CPDI follows the vortex where hat functions do not (review §6.2.3 shows CPDI-Q4 with distorted
// domains): MUSL with CPDI-R4 (domains convected with F, 2 PPC) gives e1 = 1.63e-1, 5.98e-2, 5.31e-2 at
// N = 40, 60, 80, against 0.82 m with hat functions at N = 60. CPDI-Q4 (tracked corners) reaches e1 =
// 4.5e-2 at N = 60 but its corners invert a domain at N = 40 (t = 0.68 s) and N = 80 (t = 0.73 s): the
// shear strain reaches 7 and the quadrilaterals fold. Asserted: R4 at N = 60 completes with e1 < 0.08 m,
// ten times below MUSL with hat functions on the same grid.
TEST(Vortex, MuslCpdiR4) {
  const VortexResult r = run_vortex(spec("musl", "cpdi_r4", 60));
  std::printf("[ measured ] vortex musl/cpdi_r4 N = 60: e1 = %.3e, e2 = %.3e; %.2f s\n", r.e1, r.e2, r.wall_seconds);
  EXPECT_TRUE(r.failure.empty()) << r.failure;
  EXPECT_LT(r.e1, 0.08);
}

// The equations as printed do not produce the vortex (docs/errata.md, the vortex body force): with "+R (g'h)^2" in
// b_Theta of eq. 6.18, or with the printed zero initial velocity (g'(0) = pi, so the exact ring starts at up to 3.17
// m/s), the TLMPM inverts a particle before t = 0.5 s (N = 40 and 80, hat functions). Asserted: guard failure or e1 at
// least 10 times the corrected run's.
TEST(Vortex, PrintedEquationsFail) {
  const VortexResult corrected = run_vortex(spec("tlmpm", "linear", 40));
  VortexSpec sign = spec("tlmpm", "linear", 40);
  sign.printed_body_force = true;
  VortexSpec rest = spec("tlmpm", "linear", 40);
  rest.exact_initial_velocity = false;
  for (const VortexSpec& s : {sign, rest}) {
    const VortexResult r = run_vortex(s);
    std::printf("[ measured ] vortex printed %s: e1 = %.3e (corrected %.3e) %s\n",
                s.printed_body_force ? "body force" : "initial velocity", r.e1, corrected.e1, r.failure.c_str());
    EXPECT_TRUE(!r.failure.empty() || r.e1 > 10 * corrected.e1);
  }
}

}  // namespace
}  // namespace mpm
