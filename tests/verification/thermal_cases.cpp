#include "thermal_cases.hpp"

#include <limits>
#include <utility>

#include "heat_conduction.hpp"

namespace mpm::verification {

void add_thermal_cases(std::vector<VerificationCase>& list, bool quick, int refinements) {
  struct Family {
    const char* name;
    int dimension;
    const char* reference;
    std::vector<int> cells;
    int particles_per_cell;
  };
  const Family families[] = {
      {"heat_bar_1d", 1, "series solution, review eq. 5.27 (§5.3.3, 1D bar)", {50, 100, 200}, 1},
      {"heat_plate_2d", 2, "series solution, review eq. 5.28 (§5.3.3, 2D plate)", {10, 20, 40}, 2},
  };
  for (const auto& f : families) {
    std::vector<int> ladder = f.cells;
    if (quick) ladder.resize(1);
    for (int r = 0; !quick && r < refinements; ++r) ladder.push_back(2 * ladder.back());
    // Lagrange quadratic (TLMPM) and CPDI too, whose nodal values are the field's; not Bernstein, whose mid-node
    // values are coefficients (its nodal error would overstate the field's: test_heat_conduction.cpp).
    const char* cpdi = f.dimension == 1 ? "cpdi_l2" : "cpdi_q4";
    for (const auto& [scheme, shape] : {std::pair<const char*, const char*>{"musl", "linear"},
                                        {"musl", "cubic_bspline"},
                                        {"tlmpm", "lagrange_quadratic"},
                                        {"musl", cpdi}}) {
      const int dim = f.dimension, ppc = f.particles_per_cell;
      const std::string shape_name = shape, scheme_name = scheme;
      add_case(list, f.name, f.dimension, f.reference, "max nodal |T - T_exact| / (T1 - T0) at t = 0.05 (-)", scheme,
               shape, ladder, [dim, ppc, shape_name, scheme_name](int n) {
                 HeatSpec s;
                 s.dimension = dim;
                 s.cells = n;
                 s.particles_per_cell = ppc;
                 s.scheme = scheme_name;
                 s.shape_function = shape_name;
                 const HeatResult r = run_heat(s);
                 CaseRun run;
                 run.error = r.failure.empty() ? r.max_error : std::numeric_limits<double>::infinity();
                 run.failure = r.failure;
                 run.wall_seconds = r.wall_seconds;
                 run.steps = r.steps;
                 run.particles = r.particles;
                 run.h = r.h;
                 return run;
               });
    }
  }
}

}  // namespace mpm::verification
