// Tensile test to failure (review §6.3.2, Weldox 460E): runs the TLMPM cylinder until it breaks,
// writes the engineering stress-strain curve as CSV and prints the neck, the damage, the wall time and
// the particle-updates per second. The case is the runner tests/verification/tensile_necking.hpp.
//
//   bench_necking [--shape linear|cubic_bspline|bernstein] [--h 0.5e-3] [--v-max 1] [--tau 1e-3]
//                 [--threads 1] [--csv FILE] [--print-scene]
// Defaults: the review's loading (v_max = 1 mm/ms, tau = 1 ms) at h = 0.5 mm; --print-scene writes the
// scene file of that configuration (for `mpm run`) instead of running.
#include <tbb/global_control.h>

#include <cstdio>
#include <fstream>
#include <iostream>
#include <string>

#include "bench_options.hpp"
#include "tensile_necking.hpp"

int main(int argc, char** argv) {
  mpm::TensileSpec spec;
  int threads = 1;
  std::string csv;
  bool print_scene = false;
  mpm::bench::BenchOptions cli(
      "bench_necking",
      "[--shape linear|cubic_bspline|bernstein] [--h M] [--v-max M/S] [--tau S] [--threads N] [--csv FILE] "
      "[--print-scene]");
  cli.option("--shape", spec.shape_function)
      .option("--h", spec.h)
      .option("--v-max", spec.v_max)
      .option("--tau", spec.tau)
      .threads(threads)
      .option("--csv", csv)
      .flag("--print-scene", print_scene);
  if (const auto status = cli.parse(argc, argv)) return *status;
  if (print_scene) {
    std::cout << mpm::tensile_necking_scene(spec);
    return 0;
  }
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
  std::fprintf(stderr, "tensile test: %s, h = %g mm, v_max = %g m/s, tau = %g ms, %d thread(s)...\n",
               spec.shape_function.c_str(), spec.h * 1e3, spec.v_max, spec.tau * 1e3, threads);
  const mpm::TensileResult r = mpm::run_tensile_necking(spec);
  if (!r.failure.empty()) std::fprintf(stderr, "stopped: %s\n", r.failure.c_str());
  std::printf(
      "%lld particles, %lld steps, %.1f s wall, %.3g particle-updates/s; peak engineering stress %.1f MPa at "
      "strain %.4f; neck at z = %.2f mm (radius %.3f mm, largest damage there %.3f); largest damage at "
      "z = %.2f mm; stress below 10%% of the peak at strain %.4f\n",
      r.particles, r.steps, r.wall_seconds,
      static_cast<double>(r.particles) * r.steps / (r.wall_seconds > 0 ? r.wall_seconds : 1), r.peak_stress / 1e6,
      r.strain_at_peak, r.neck_z * 1e3, r.neck_radius * 1e3, r.neck_max_damage, r.max_damage_z * 1e3, r.failure_strain);
  if (!csv.empty()) {
    std::ofstream out(csv);
    out << "engineering_strain,engineering_stress_Pa\n";
    for (std::size_t k = 0; k < r.strain.size(); ++k) out << r.strain[k] << ',' << r.stress[k] << '\n';
  }
  return r.failure.empty() ? 0 : 3;
}
