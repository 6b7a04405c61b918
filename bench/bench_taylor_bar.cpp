// Love & Sulsky's copper Taylor bar with the explicit schemes, axisymmetric (reference 003 §4.1; issue 16): runs
// the bar to 80 us and prints L_f and R_f against the converged finite-element results (L_f 21.42-21.48 mm,
// R_f 7.12-7.22 mm), with the wall time and particle-updates per second. The case is the verification runner
// tests/verification/taylor_bar.hpp, so the numbers are those the test and examples/17_love_sulsky_bar use.
//
//   bench_taylor_bar [--scheme musl|usl|usf|tlmpm] [--shape linear|quadratic_bspline|cubic_bspline|cpgimp]
//                    [--model hencky_j2|j2_plasticity] [--h 0.4e-3] [--ppc 2] [--cfl 0.5] [--threads 1]
//                    [--output DIR] [--print-scene]
#include <tbb/global_control.h>

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <string>

#include "bench_options.hpp"
#include "taylor_bar.hpp"

int main(int argc, char** argv) {
  mpm::TaylorBarSpec spec;
  int threads = 1;
  bool print_scene = false;
  mpm::bench::BenchOptions cli("bench_taylor_bar",
                               "[--scheme S] [--shape F] [--model hencky_j2|j2_plasticity] [--h M] [--ppc N] [--cfl F] "
                               "[--threads N] [--output DIR] [--print-scene]");
  method_options(cli, spec).option("--model", spec.model).threads(threads).flag("--print-scene", print_scene);
  if (const auto status = cli.parse(argc, argv)) return *status;
  if (print_scene) {
    std::cout << mpm::taylor_bar_scene(spec);
    return 0;
  }
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
  const mpm::TaylorBarResult r = mpm::run_taylor_bar(spec);
  if (!r.failure.empty()) std::fprintf(stderr, "stopped: %s\n", r.failure.c_str());
  std::printf(
      "| scheme | shape | model | h (mm) | particles | steps | L_f (mm) | R_f (mm) | energy error | wall (s) | "
      "particle-updates/s | threads |\n|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  std::printf("| %s | %s | %s | %g | %lld | %lld | %.2f | %.2f | %.1e | %.1f | %.3g | %d |\n", spec.scheme.c_str(),
              spec.shape_function.c_str(), spec.model.c_str(), spec.h * 1e3, r.particles, r.steps, r.length * 1e3,
              r.radius * 1e3, r.energy_error, r.wall_seconds,
              static_cast<double>(r.particles) * r.steps / std::max(r.wall_seconds, 1e-300), threads);
  std::printf("reference (converged FE, Simo 1992; Zienkiewicz et al. 1998): L_f 21.42-21.48 mm, R_f 7.12-7.22 mm\n");
  return r.failure.empty() ? 0 : 3;
}
