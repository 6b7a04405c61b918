#include "fluids_cases.hpp"

#include <limits>

#include "dam_break.hpp"
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
  // Martin & Moyce's surge front (a = 2.25 in), the Tait water and the incompressible one, each with the shape
  // functions it takes; the measure is against the experiment, so it does not converge to 0 (the gate's release:
  // examples/12_dam_break/README.md) — the report shows what each water costs for the front it gives.
  std::vector<int> widths = quick ? std::vector<int>{8, 16} : std::vector<int>{8, 16, 32};
  for (int r = 0; !quick && r < refinements; ++r) widths.push_back(2 * widths.back());
  const MartinMoyce experiment = martin_moyce(std::string(MPM_SOURCE_DIR) + "/tests/data/dam_break_martin_moyce.csv");
  for (const bool incompressible : {false, true})
    for (const std::string shape : {"linear", "quadratic_bspline", "cpgimp"}) {
      if (incompressible && shape == "cpgimp") continue;  // the projection reads no particle domain
      add_case(list, incompressible ? "martin_moyce_incompressible" : "martin_moyce", 2,
               "Martin & Moyce (1952), a = 2.25 in, n^2 = 2 (tests/data/dam_break_martin_moyce.csv)",
               "largest |Z / Z_experiment - 1| for T <= 3 (-)", "musl", shape, widths,
               [incompressible, shape, experiment](int n) {
                 DamBreakSpec s;
                 s.cells_per_width = n;
                 s.shape_function = shape;
                 s.incompressible = incompressible;
                 const DamBreakResult r = run_dam_break(s);
                 CaseRun run;
                 run.error = r.failure.empty() ? largest_front_deviation(r, experiment)
                                               : std::numeric_limits<double>::infinity();
                 run.failure = r.failure;
                 run.wall_seconds = r.wall_seconds;
                 run.steps = r.steps;
                 run.particles = r.particles;
                 run.h = s.width / n;
                 return run;
               });
    }
}

}  // namespace mpm::verification
