// Taylor anvil (review §6.3.1, Table 5, eq. 6.19) at a coarse resolution, as a regression bound: the full
// resolution is the example examples/05_taylor_anvil and the benchmark bench/bench_taylor.
#include <gtest/gtest.h>

#include "taylor_anvil.hpp"

namespace mpm {
namespace {

TEST(TaylorAnvil, CoarseTlmpm) {
  TaylorSpec s;
  s.scheme = "tlmpm";
  s.h = 1e-3;
  const TaylorResult r = run_taylor_anvil(s);
  ASSERT_TRUE(r.failure.empty()) << r.failure;
  RecordProperty("L_f_mm", std::to_string(r.length * 1e3));
  RecordProperty("D_f_mm", std::to_string(r.diameter * 1e3));
  RecordProperty("W_f_mm", std::to_string(r.bulge * 1e3));
  RecordProperty("Delta", std::to_string(r.error));
  std::printf(
      "L %.3f D %.3f W %.3f mm Delta %.4f t %.2f us steps %lld particles %lld energy %.3e eps_max %.3f "
      "%.3g s %.3g pu/s\n",
      r.length * 1e3, r.diameter * 1e3, r.bulge * 1e3, r.error, r.time * 1e6, r.steps, r.particles, r.energy_error,
      r.max_plastic_strain, r.wall_seconds, r.particle_updates_per_second);
}

}  // namespace
}  // namespace mpm
