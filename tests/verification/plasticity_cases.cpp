#include "plasticity_cases.hpp"

#include <limits>

#include "taylor_anvil.hpp"

namespace mpm::verification {

void add_plasticity_cases(std::vector<VerificationCase>& list, bool quick, int refinements) {
  std::vector<int> ladder = quick ? std::vector<int>{8} : std::vector<int>{8, 16, 32};
  for (int r = 0; !quick && r < refinements; ++r) ladder.push_back(2 * ladder.back());
  for (const auto& [scheme, shape] :
       {std::pair<const char*, const char*>{"tlmpm", "linear"}, {"musl", "linear"}, {"musl", "cubic_bspline"}}) {
    add_case(list, "taylor_anvil", 3, "experiment, Johnson & Holmquist 1988 (review §6.3.1, Table 6)",
             "Delta of eq. 6.19, mean relative error of L_f, D_f, W_f (-)", scheme, shape, ladder,
             [scheme = std::string(scheme), shape = std::string(shape)](int n) {
               TaylorSpec s;
               s.scheme = scheme;
               s.shape_function = shape;
               s.h = 8e-3 / n;
               const TaylorResult r = run_taylor_anvil(s);
               CaseRun run;
               run.error = r.failure.empty() ? r.error : std::numeric_limits<double>::infinity();
               run.failure = r.failure;
               run.wall_seconds = r.wall_seconds;
               run.steps = r.steps;
               run.particles = r.particles;
               run.h = s.h;
               return run;
             });
  }
}

}  // namespace mpm::verification
