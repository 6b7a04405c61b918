// An elastic sphere dropped on a rigid plane, axisymmetric (the runner tests/verification/hertz_sphere.hpp):
// the window-averaged contact force's peak and duration against Hertz, with the wall time.
//
//   bench_hertz [--cells 160] [--scheme musl|usl|usf] [--shape linear|quadratic_bspline|cubic_bspline|cpgimp]
//               [--onset grid|particle_gap] [--ppc 2] [--threads 1]
// The default is the resolution at which the test's errors come within 10% (160 cells per radius).
#include <tbb/global_control.h>

#include <cstdio>
#include <string>

#include "bench_options.hpp"
#include "hertz_sphere.hpp"

int main(int argc, char** argv) {
  mpm::verification::HertzSpec spec;
  spec.cells_per_radius = 160;
  int threads = 1;
  mpm::bench::BenchOptions cli(
      "bench_hertz", "[--cells N] [--scheme S] [--shape F] [--onset grid|particle_gap] [--ppc N] [--threads N]");
  cli.option("--cells", spec.cells_per_radius)
      .option("--scheme", spec.scheme)
      .option("--shape", spec.shape_function)
      .option("--onset", spec.onset)
      .option("--ppc", spec.particles_per_cell)
      .threads(threads)
      .require([&] { return spec.cells_per_radius >= 4; }, "--cells must be >= 4");
  if (const auto status = cli.parse(argc, argv)) return *status;
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
  const auto r = mpm::verification::run_hertz_sphere(spec);
  if (!r.failure.empty()) std::fprintf(stderr, "stopped: %s\n", r.failure.c_str());
  std::printf(
      "| scheme | shape | onset | cells per radius | particles | steps | peak (N) | vs Hertz | duration (ms) | "
      "vs Hertz | rebound (m/s) | wall (s) |\n|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  std::printf("| %s | %s | %s | %d | %lld | %lld | %.0f | %+.1f%% | %.2f | %+.1f%% | %.3f | %.1f |\n",
              spec.scheme.c_str(), spec.shape_function.c_str(), spec.onset.c_str(), spec.cells_per_radius, r.particles,
              r.steps, r.peak, 100 * (r.peak / r.exact_peak - 1), 1e3 * r.duration,
              100 * (r.duration / r.exact_duration - 1), r.rebound, r.wall_seconds);
  std::printf("Hertz: F_max %.0f N, t_c %.2f ms\n", r.exact_peak, 1e3 * r.exact_duration);
  return r.failure.empty() ? 0 : 3;
}
