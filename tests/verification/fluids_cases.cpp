#include "fluids_cases.hpp"

#include <limits>

#include "sod.hpp"

namespace mpm::verification {

void add_fluids_cases(std::vector<VerificationCase>& list, bool quick, int refinements) {
  std::vector<int> ladder = quick ? std::vector<int>{100, 200} : std::vector<int>{100, 200, 400};
  for (int r = 0; !quick && r < refinements; ++r) ladder.push_back(2 * ladder.back());
  for (const auto& [scheme, shape] : methods(1)) {
    if (scheme == "tlmpm") continue;
    add_case(list, "sod", 1, "exact Riemann solution (Toro ch. 4), review §6.1.4",
             "L1 of the particle density at t = 0.143 / 0.875 (-)", scheme, shape, ladder, [scheme, shape](int n) {
               SodSpec s;
               s.cells = n;
               s.scheme = scheme;
               s.shape_function = shape;
               s.viscosity_linear = 1;
               s.viscosity_quadratic = 2;
               const SodResult r = run_sod(s);
               CaseRun run;
               run.error = r.failure.empty() ? r.particles.density : std::numeric_limits<double>::infinity();
               run.failure = r.failure;
               run.wall_seconds = r.wall_seconds;
               run.steps = r.steps;
               run.particles = r.particle_count;
               run.h = 1.0 / n;
               return run;
             });
  }
}

}  // namespace mpm::verification
