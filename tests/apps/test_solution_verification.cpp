// Solution verification (mpm/solution_verification.hpp) on manufactured sequences phi(h) = phi_exact + C h^p
// (+ higher-order terms) whose order, limit and error are known: the observed order, the Richardson limit and
// the GCI band (Roache; Celik et al. 2008) against them; and the sequences that must not get a number:
// oscillating, diverging, an implausible order, orders that disagree between triples.
#include <gtest/gtest.h>

#include <cmath>

#include "mpm/app/solution_verification.hpp"

namespace mpm {
namespace {

std::vector<ConvergenceRun> sequence(const std::vector<double>& h, double (*phi)(double)) {
  std::vector<ConvergenceRun> runs;
  for (double x : h) runs.push_back({x, phi(x), 1.0 / (x * x)});
  return runs;
}

TEST(SolutionVerification, PureSecondOrderSequence) {
  auto phi = [](double h) { return 1.0 + 0.3 * h * h; };
  const auto r = analyse_convergence(sequence({0.4, 0.2, 0.1}, phi));
  EXPECT_TRUE(r.asymptotic) << r.verdict;
  EXPECT_NEAR(r.order, 2.0, 1e-9);
  EXPECT_NEAR(r.extrapolated, 1.0, 1e-12);
  // GCI = 1.25 |phi1 - phi2| / (2^2 - 1) = 1.25 * 0.3 * (0.04 - 0.01) / 3 = 3.75e-3; the true error 3e-3
  EXPECT_NEAR(r.gci, 3.75e-3, 1e-12);
  EXPECT_EQ(r.safety_factor, 1.25);
  EXPECT_LT(std::abs(phi(0.1) - 1.0), r.gci);
  ASSERT_EQ(r.estimated_error.size(), 3u);
  EXPECT_NEAR(r.estimated_error[0], 0.3 * 0.01, 1e-12);  // finest first
  EXPECT_NEAR(r.next_h, 0.05, 1e-15);
  EXPECT_NEAR(r.next_error, 0.3 * 0.0025, 1e-12);
  EXPECT_NEAR(r.next_seconds, 400, 1e-9);  // cost grows by 4 per refinement here: 25, 100, then 400
}

TEST(SolutionVerification, NonConstantRatioAndHigherOrderTerms) {
  // Ratios sqrt(2) and 1.5, and a third-order term: the order found is close to 2, the band holds.
  auto phi = [](double h) { return 2.0 - 0.5 * h * h + 0.2 * h * h * h; };
  const auto runs = sequence({0.3, 0.2, 0.2 / std::sqrt(2.0), 0.1}, phi);
  const auto r = analyse_convergence(runs);
  EXPECT_TRUE(r.asymptotic) << r.verdict;
  EXPECT_NEAR(r.order, 2.0, 0.15);
  EXPECT_LT(std::abs(phi(0.1) - 2.0), r.gci);
  EXPECT_NEAR(r.extrapolated, 2.0, 0.1 * std::abs(phi(0.1) - 2.0));
  ASSERT_EQ(r.triple_orders.size(), 2u);
}

TEST(SolutionVerification, FirstOrderFromAbove) {
  auto phi = [](double h) { return -3.0 + 2.0 * h; };
  const auto r = analyse_convergence(sequence({0.8, 0.4, 0.2, 0.1}, phi));
  EXPECT_TRUE(r.asymptotic) << r.verdict;
  EXPECT_NEAR(r.order, 1.0, 1e-9);
  EXPECT_NEAR(r.extrapolated, -3.0, 1e-12);
}

TEST(SolutionVerification, OscillatingSequenceGetsNoNumber) {
  const std::vector<ConvergenceRun> runs{{0.4, 1.1, 1}, {0.2, 0.95, 1}, {0.1, 1.02, 1}};
  const auto r = analyse_convergence(runs);
  EXPECT_FALSE(r.asymptotic);
  EXPECT_NE(r.verdict.find("change sign"), std::string::npos) << r.verdict;
  EXPECT_FALSE(observed_order(runs[0], runs[1], runs[2]));
}

TEST(SolutionVerification, DivergingSequenceGetsNoNumber) {
  auto phi = [](double h) { return 1.0 / h; };  // the differences grow as h shrinks
  const auto r = analyse_convergence(sequence({0.4, 0.2, 0.1}, phi));
  EXPECT_FALSE(r.asymptotic);
  EXPECT_NE(r.verdict.find("not converging"), std::string::npos) << r.verdict;
  // Differences that shrink too slowly for any p > 0 (ratio 0.9 < 1 with r = 2) are divergence too.
  const std::vector<ConvergenceRun> slow{{0.4, 1.0, 1}, {0.2, 1.09, 1}, {0.1, 1.19, 1}};
  EXPECT_FALSE(analyse_convergence(slow).asymptotic);
}

TEST(SolutionVerification, ImplausibleOrderGetsNoNumber) {
  auto phi = [](double h) { return 1.0 + std::pow(h, 6.0); };
  const auto r = analyse_convergence(sequence({0.4, 0.2, 0.1}, phi));
  EXPECT_FALSE(r.asymptotic);
  EXPECT_TRUE(r.order_observed);
  EXPECT_NEAR(r.order, 6.0, 1e-6);
  EXPECT_NE(r.verdict.find("outside the plausible range"), std::string::npos) << r.verdict;
}

TEST(SolutionVerification, OrdersThatDisagreeBetweenTriplesAreNotAsymptotic) {
  // First order on the coarse runs, then the error drops as h^3: the triples give 1 and about 2.6.
  const std::vector<ConvergenceRun> runs{{0.8, 1.8, 1}, {0.4, 1.4, 1}, {0.2, 1.2, 1}, {0.1, 1.2 - 0.2 / 6, 1}};
  const auto r = analyse_convergence(runs);
  EXPECT_FALSE(r.asymptotic);
  EXPECT_NE(r.verdict.find("not in the asymptotic range"), std::string::npos) << r.verdict;
}

TEST(SolutionVerification, TwoRunsNeedAnAssumedOrderAndGetTheLargerSafetyFactor) {
  const std::vector<ConvergenceRun> runs{{0.2, 1.04, 1}, {0.1, 1.01, 1}};
  EXPECT_THROW(analyse_convergence(runs), std::invalid_argument);
  ConvergenceOptions o;
  o.assumed_order = 2;
  const auto r = analyse_convergence(runs, o);
  EXPECT_TRUE(r.asymptotic);
  EXPECT_EQ(r.safety_factor, 3.0);
  EXPECT_NEAR(r.gci, 3.0 * 0.03 / 3, 1e-12);
  EXPECT_NEAR(r.extrapolated, 1.0, 1e-12);
}

TEST(SolutionVerification, RefusesBadRuns) {
  EXPECT_THROW(analyse_convergence({{0.1, 1, 1}}), std::invalid_argument);
  EXPECT_THROW(analyse_convergence({{0.1, 1, 1}, {0.1, 2, 1}, {0.2, 3, 1}}), std::invalid_argument);
  EXPECT_THROW(analyse_convergence({{0.0, 1, 1}, {0.1, 2, 1}, {0.2, 3, 1}}), std::invalid_argument);
}

}  // namespace
}  // namespace mpm
