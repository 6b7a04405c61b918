// The Newton-Krylov driver (physics/implicit/newton_krylov.hpp) on small diagonal systems with known roots:
// R_i(x) = x_i^3 + x_i - b_i, root x_i = 1 for b_i = 2 (the cubic is monotone: one real root).
// The rounding floor: R evaluated as (R + 1e6) - 1e6 + h/2 is quantised to h = 2^-33 = 1.16e-10 (the spacing
// of doubles at 1e6) and never zero: ||R|| >= sqrt(8) h/2 = 1.6e-10, so a tolerance of 1e-13 cannot be
// reached. The driver must accept the iterate once no step reduces ||R|| and the Newton update is below
// step_rtol ||x|| (PETSc SNES's stol), and only then.
#include <gtest/gtest.h>

#include <cmath>

#include "mpm/implicit/newton_krylov.hpp"

namespace mpm::implicit {
namespace {

class DiagonalCubic : public NonlinearProblem {
 public:
  /// `quantised`: R is rounded at 1e6 and shifted by half the spacing there (the floor above).
  DiagonalCubic(Index n, Real b, bool quantised)
      : n_(n),
        b_(b),
        offset_(quantised ? 1e6 : 0),
        half_spacing_(quantised ? std::ldexp(1.0, -34) : 0),
        groups_(1),
        rows_(n) {
    for (Index i = 0; i < n; ++i) groups_[0].push_back(i), rows_[i] = {i};
  }
  Index size() const override { return n_; }
  bool residual(const Vector& x, Vector& r) override {
    r.resize(n_);
    for (Index i = 0; i < n_; ++i) {
      volatile Real shifted = x[i] * x[i] * x[i] + x[i] - b_ + offset_;  // volatile: keep the rounding
      r[i] = shifted - offset_ + half_spacing_;
    }
    return true;
  }
  const std::vector<std::vector<Index>>& column_groups() const override { return groups_; }
  const std::vector<std::vector<Index>>& column_rows() const override { return rows_; }
  Real unknown_scale() const override { return 1; }

 private:
  Index n_;
  Real b_, offset_, half_spacing_;
  std::vector<std::vector<Index>> groups_, rows_;
};

TEST(NewtonKrylov, ReachesTheToleranceWhenTheResidualCanResolveIt) {
  DiagonalCubic problem(8, 2, false);
  Vector x = Vector::Constant(8, 3);
  NewtonSettings s;
  s.rtol = 1e-12;
  const NewtonStats stats = solve_newton_krylov(problem, x, 10, s);
  ASSERT_TRUE(stats.converged) << stats.failure;
  EXPECT_FALSE(stats.at_rounding_floor);
  EXPECT_LE(stats.last_residual, 1e-11);
  EXPECT_NEAR(x.maxCoeff(), 1, 1e-12);
  EXPECT_NEAR(x.minCoeff(), 1, 1e-12);
}

TEST(NewtonKrylov, StopsAtTheRoundingFloorOfTheResidual) {
  DiagonalCubic problem(8, 2, true);
  Vector x = Vector::Constant(8, 3);
  NewtonSettings s;
  s.rtol = 1e-14;  // tolerance 1e-13, below the floor 1.6e-10
  const NewtonStats stats = solve_newton_krylov(problem, x, 10, s);
  ASSERT_TRUE(stats.converged) << stats.failure;
  EXPECT_TRUE(stats.at_rounding_floor);
  EXPECT_GT(stats.last_residual, stats.tolerance);
  EXPECT_LT(stats.last_residual, 4 * std::sqrt(8.0) * std::ldexp(1.0, -33));  // within 4 spacings per component
  // |x - 1| of the order of the spacing over R'(1) = 4: 3e-11
  EXPECT_NEAR(x.maxCoeff(), 1, 1e-10);
  EXPECT_NEAR(x.minCoeff(), 1, 1e-10);
}

TEST(NewtonKrylov, WithoutANegligibleUpdateAStallIsAFailure) {
  // The floor criterion is off (step_rtol = 0): the same stall is reported as a failure that says why.
  DiagonalCubic problem(8, 2, true);
  Vector x = Vector::Constant(8, 3);
  NewtonSettings s;
  s.rtol = 1e-14;
  s.step_rtol = 0;
  const NewtonStats stats = solve_newton_krylov(problem, x, 10, s);
  EXPECT_FALSE(stats.converged);
  EXPECT_FALSE(stats.at_rounding_floor);
  EXPECT_FALSE(stats.failure.empty());
  EXPECT_NEAR(x.maxCoeff(), 1, 1e-10);  // it did get to the floor
}

}  // namespace
}  // namespace mpm::implicit
