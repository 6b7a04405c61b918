#include "implicit_cases.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "taylor_bar.hpp"

namespace mpm::verification {

namespace {

/// Love & Sulsky's Taylor bar at 227 m/s on the paper's box, n cells across the bar's radius (4: the paper's
/// 9 x 50 cells of 0.8 x 0.648 mm); the implicit scheme at dt = 1 us x 4 / n, MUSL at CFL 0.5. Error: the larger
/// relative distance of L_f and R_f from the FE midpoints 21.45 and 7.17 mm.
CaseRun taylor_bar_case(const std::string& scheme, int n) {
  TaylorBarSpec spec;
  spec.scheme = scheme, spec.paper_box = true;
  spec.h = 3.2e-3 / n, spec.h_z = 2.592e-3 / n;
  spec.dt = 4e-6 / n, spec.max_newton_iterations = 200;
  const TaylorBarResult r = run_taylor_bar(spec);
  CaseRun run;
  run.error = std::max(std::abs(r.length / 21.45e-3 - 1), std::abs(r.radius / 7.17e-3 - 1));
  run.wall_seconds = r.wall_seconds, run.steps = r.steps, run.particles = r.particles, run.h = spec.h;
  run.failure = r.failure;
  if (!r.failure.empty()) run.error = std::numeric_limits<double>::infinity();
  return run;
}

/// hencky_j2 with the constrained modulus K + 4G/3 = 100 of the linear bar, at a strain amplitude of 1e-4.
BarMode1Spec hencky_bar(const std::string& scheme, int cells, double courant) {
  return {.material = "{model: hencky_j2, density: 1, bulk_modulus: 40, shear_modulus: 45}",
          .scheme = scheme,
          .shape = "linear",
          .cells = cells,
          .courant = courant,
          .v0 = 1e-3};
}

}  // namespace

void add_implicit_cases(std::vector<VerificationCase>& list, bool quick, int refinements) {
  std::vector<int> ladder = quick ? std::vector<int>{8} : std::vector<int>{8, 16, 32, 64};
  for (int r = 0; !quick && r < refinements; ++r) ladder.push_back(2 * ladder.back());
  const std::string reference = "analytic, review eq. 6.4 (mode 1 of a fixed-free bar), hencky_j2 at strain 1e-4";
  const std::string measure = "max |v_cm - exact| over one period / amplitude (-)";
  add_case(list, "bar_mode1_hencky_j2", 1, reference, measure, "implicit", "linear", ladder,
           [](int n) { return run_bar_mode1(hencky_bar("implicit", n, 2.0)); });
  add_case(list, "bar_mode1_hencky_j2", 1, reference, measure, "musl", "linear", ladder,
           [](int n) { return run_bar_mode1(hencky_bar("musl", n, 0.1)); });
  // ~4 CPU s at the paper's mesh (implicit), ~60 at n = 8 (the quick ladder has the paper's mesh only); not
  // continued by `refinements`: n = 16 would take the implicit run 10-20 CPU minutes (theory.md §15)
  const std::vector<int> bar = quick ? std::vector<int>{4} : std::vector<int>{4, 8};
  const std::string fe = "converged finite elements (Simo 1992; Zienkiewicz et al. 1998): L_f 21.45, R_f 7.17 mm";
  const std::string shape = "max(|L_f / 21.45 mm - 1|, |R_f / 7.17 mm - 1|) at 80 us (-)";
  for (const std::string scheme : {"implicit", "musl"})
    add_case(list, "taylor_bar_227", 2, fe, shape, scheme, "linear", bar,
             [scheme](int n) { return taylor_bar_case(scheme, n); });
}

}  // namespace mpm::verification
