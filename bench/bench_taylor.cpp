// Taylor anvil benchmark (review §6.3.1): runs the OFHC copper cylinder at 190 m/s to the time its
// kinetic energy falls below 1%, measures L_f, D_f, W_f and the error of eq. 6.19, and prints the wall time
// and particle-updates per second (particles x steps / stepping seconds). The case is the verification
// runner tests/verification/taylor_anvil.hpp, so the numbers are those the test and the example use.
//
//   bench_taylor [--scheme tlmpm|musl|usl] [--shape linear|cubic_bspline] [--h 0.25e-3] [--ppc N]
//                [--cfl 0.5] [--C 0.013] [--axisymmetric] [--threads 1] [--output DIR] [--csv FILE] [--print-scene]
// --axisymmetric: the same rod as a 2D axisymmetric run (examples/16_axisymmetric_taylor).
// --print-scene writes the scene file of that configuration (for `mpm run`) instead of running.
// Defaults: the full case of the review, TLMPM with hats, h = 0.25 mm (74,052 particles), one thread.
#include <tbb/global_control.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>
#include <string>

#include "bench_options.hpp"
#include "taylor_anvil.hpp"

int main(int argc, char** argv) {
  mpm::TaylorSpec spec;
  spec.h = 0.25e-3;
  int threads = 1;
  std::string csv;
  bool print_scene = false;
  mpm::bench::BenchOptions cli("bench_taylor",
                               "[--scheme tlmpm|musl|usl] [--shape linear|cubic_bspline] [--h M] [--ppc N] [--cfl F] "
                               "[--C C] [--axisymmetric] [--threads N] [--output DIR] [--csv FILE] [--print-scene]");
  method_options(cli, spec)
      .option("--C", spec.strain_rate_coefficient)
      .threads(threads)
      .option("--csv", csv)
      .flag("--print-scene", print_scene)
      .flag("--axisymmetric", spec.axisymmetric);
  if (const auto status = cli.parse(argc, argv)) return *status;
  if (print_scene) {  // the scene file of this configuration, for `mpm run` (ParaView frames)
    std::cout << mpm::taylor_anvil_scene(spec);
    return 0;
  }
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
  std::fprintf(stderr, "Taylor anvil%s: %s/%s, h = %g mm, cfl %g, C = %g, %d thread(s)...\n",
               spec.axisymmetric ? " (axisymmetric)" : "", spec.scheme.c_str(), spec.shape_function.c_str(),
               spec.h * 1e3, spec.cfl, spec.strain_rate_coefficient, threads);
  const mpm::TaylorResult r = mpm::run_taylor_anvil(spec);
  if (!r.failure.empty()) std::fprintf(stderr, "stopped: %s\n", r.failure.c_str());
  std::printf(
      "| scheme | shape | h (mm) | particles | steps | t_end (us) | KE left | L_f (mm) | D_f (mm) | W_f (mm) | Delta | "
      "energy error | max eps_p | wall (s) | particle-updates/s | CPU (s) | per CPU-s | threads |\n"
      "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  std::printf(
      "| %s | %s | %g | %lld | %lld | %.1f | %.2f%% | %.2f | %.2f | %.2f | %.3f | %.1e | %.2f | %.1f | %.3g | %.1f | "
      "%.3g | %d |\n",
      spec.scheme.c_str(), spec.shape_function.c_str(), spec.h * 1e3, r.particles, r.steps, r.time * 1e6,
      100 * r.kinetic_fraction, r.length * 1e3, r.diameter * 1e3, r.bulge * 1e3, r.error, r.energy_error,
      r.max_plastic_strain, r.wall_seconds, r.particle_updates_per_second, r.cpu_seconds,
      static_cast<double>(r.particles) * r.steps / std::max(r.cpu_seconds, 1e-300), threads);
  std::printf(
      "reference (Table 6): experiment L 16.2, D 13.5, W 10.1 mm; review TLMPM 16.2/13.9/9.4 (0.03), "
      "MPM 17.2/14.4/8.9 (0.08), BSMPM 16.5/13.9/9.5 (0.04)\n");
  if (!csv.empty()) {
    std::ofstream out(csv, std::ios::app);
    out << spec.scheme << ',' << spec.shape_function << ',' << spec.h << ',' << r.particles << ',' << r.steps << ','
        << r.time << ',' << r.length << ',' << r.diameter << ',' << r.bulge << ',' << r.error << ',' << r.energy_error
        << ',' << r.wall_seconds << ',' << r.particle_updates_per_second << ',' << r.cpu_seconds << ',' << threads
        << '\n';
  }
  return r.failure.empty() ? 0 : 3;
}
