// Love & Sulsky's copper Taylor bar, axisymmetric (reference 003 §4.1): runs the bar to 80 us
// with an explicit scheme or the implicit one and prints L_f and R_f against the converged finite-element results
// (L_f 21.42-21.48 mm, R_f 7.12-7.22 mm), the kinetic energy left, the energy error, the wall time and, for the
// implicit scheme, the solver's work: Newton iterations per step, GMRES per Newton iteration, residual
// evaluations per step and where the wall time goes (projection, residual, LU, the rest: Krylov and line
// search). The case is the verification runner tests/verification/taylor_bar.hpp, so the numbers are those the
// tests and examples/17_love_sulsky_bar use.
//
//   bench_taylor_bar [--scheme musl|usl|usf|tlmpm|implicit] [--shape linear|quadratic_bspline|cubic_bspline|cpgimp]
//                    [--model hencky_j2|j2_plasticity] [--h 0.4e-3] [--hz M] [--paper-box] [--ppc 2] [--cfl 0.5]
//                    [--dt 1e-6] [--newton N] [--threads 1] [--output DIR] [--print-scene]
//   bench_taylor_bar --scheme implicit --paper-box --h 0.8e-3 --hz 0.648e-3 --dt 1e-6   # the paper's run
#include <tbb/global_control.h>

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <string>

#include <fmt/format.h>

#include "bench_options.hpp"
#include "taylor_bar.hpp"

int main(int argc, char** argv) {
  mpm::TaylorBarSpec spec;
  int threads = 1;
  bool print_scene = false;
  mpm::bench::BenchOptions cli(
      "bench_taylor_bar",
      "[--scheme S] [--shape F] [--model hencky_j2|j2_plasticity] [--h M] [--hz M] [--paper-box] "
      "[--ppc N] [--cfl F] [--dt S] [--newton N] [--threads N] [--output DIR] [--print-scene]");
  method_options(cli, spec)
      .option("--model", spec.model)
      .option("--hz", spec.h_z)
      .flag("--paper-box", spec.paper_box)
      .option("--dt", spec.dt)
      .option("--newton", spec.max_newton_iterations)
      .threads(threads)
      .flag("--print-scene", print_scene);
  if (const auto status = cli.parse(argc, argv)) return *status;
  if (print_scene) {
    std::cout << mpm::taylor_bar_scene(spec);
    return 0;
  }
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
  const mpm::TaylorBarResult r = mpm::run_taylor_bar(spec);
  if (!r.failure.empty()) std::fprintf(stderr, "stopped: %s\n", r.failure.c_str());
  const double h_z = spec.h_z > 0 ? spec.h_z : spec.h;
  const std::string step =
      spec.scheme == "implicit" ? fmt::format("dt {:g} us", spec.dt * 1e6) : fmt::format("CFL {:g}", spec.cfl);
  std::printf(
      "| scheme | shape | model | cells (mm) | ppc | particles | step | steps | L_f (mm) | R_f (mm) | KE left | "
      "plastic strain (face / max) | energy error | largest rise / E0 | CPU s | CPU s per us |\n"
      "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  std::printf(
      "| %s | %s | %s | %g x %g | %d | %lld | %s | %lld | %.2f | %.2f | %.2f%% | %.2f / %.2f | %.1e | %.1e | %.1f | "
      "%.3f |\n",
      spec.scheme.c_str(), spec.shape_function.c_str(), spec.model.c_str(), spec.h * 1e3, h_z * 1e3,
      spec.particles_per_cell, r.particles, step.c_str(), r.steps, r.length * 1e3, r.radius * 1e3,
      100 * r.kinetic_fraction, r.face_plastic_strain, r.largest_plastic_strain, r.energy_error, r.largest_rise,
      r.cpu_seconds, r.cpu_seconds / std::max(r.simulated_time * 1e6, 1e-300));
  std::printf("wall %.1f s (%d threads), %.3g particle-updates/s\n", r.wall_seconds, threads,
              static_cast<double>(r.particles) * r.steps / std::max(r.wall_seconds, 1e-300));
  if (r.newton > 0 || spec.scheme == "implicit") {
    const double steps = std::max<double>(static_cast<double>(r.steps), 1);
    const double other = r.wall_seconds - r.projection_seconds - r.residual_seconds - r.factorization_seconds;
    std::printf(
        "implicit: %.2f Newton iterations per step (max %d), %.2f GMRES per Newton iteration, %.1f residual "
        "evaluations per step; wall time: projection %.0f%%, residual %.0f%%, LU %.0f%%, the rest (Krylov, line "
        "search, update) %.0f%%\n",
        r.newton / steps, r.max_newton, static_cast<double>(r.gmres) / std::max<double>(r.newton, 1),
        r.residuals / steps, 100 * r.projection_seconds / r.wall_seconds, 100 * r.residual_seconds / r.wall_seconds,
        100 * r.factorization_seconds / r.wall_seconds, 100 * other / r.wall_seconds);
  }
  std::printf("reference (converged FE, Simo 1992; Zienkiewicz et al. 1998): L_f 21.42-21.48 mm, R_f 7.12-7.22 mm\n");
  return r.failure.empty() ? 0 : 3;
}
