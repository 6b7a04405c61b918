#include "mpm/app/solution_verification.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace mpm {
namespace {

/// The model ratio (phi3 - phi2)/(phi2 - phi1) of phi = phi_exact + C h^p, for refinement ratios r21, r32.
double model_ratio(double p, double r21, double r32) {
  return std::pow(r21, p) * std::expm1(p * std::log(r32)) / std::expm1(p * std::log(r21));
}

/// Sorted finest first.
void sort_fine_to_coarse(std::vector<ConvergenceRun>& runs) {
  std::sort(runs.begin(), runs.end(), [](const auto& a, const auto& b) { return a.h < b.h; });
}

}  // namespace

std::optional<double> observed_order(ConvergenceRun a, ConvergenceRun b, ConvergenceRun c) {
  std::vector<ConvergenceRun> r{a, b, c};
  sort_fine_to_coarse(r);
  const double e21 = r[1].value - r[0].value, e32 = r[2].value - r[1].value;
  if (e21 == 0 || e32 == 0) return std::nullopt;
  const double ratio = e32 / e21;  // > 0 for monotone convergence
  if (!(ratio > 0)) return std::nullopt;
  const double r21 = r[1].h / r[0].h, r32 = r[2].h / r[1].h;
  // The model ratio grows monotonically with p, from log(r32)/log(r21) at p -> 0: below that no p > 0 fits
  // (the differences do not shrink fast enough: divergence).
  double lo = 1e-9, hi = 30;
  if (!(ratio > model_ratio(lo, r21, r32)) || !(ratio < model_ratio(hi, r21, r32))) return std::nullopt;
  for (int k = 0; k < 200; ++k) {
    const double mid = 0.5 * (lo + hi);
    (model_ratio(mid, r21, r32) < ratio ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

ConvergenceResult analyse_convergence(std::vector<ConvergenceRun> runs, const ConvergenceOptions& o) {
  if (runs.size() < 2) throw std::invalid_argument("solution verification needs at least two runs");
  sort_fine_to_coarse(runs);
  for (std::size_t k = 0; k < runs.size(); ++k) {
    if (!(runs[k].h > 0) || !std::isfinite(runs[k].h))
      throw std::invalid_argument(fmt::format("resolution {} is not > 0", runs[k].h));
    if (k > 0 && runs[k].h == runs[k - 1].h)
      throw std::invalid_argument(fmt::format("resolution {} is given twice", runs[k].h));
  }
  if (runs.size() == 2 && !o.assumed_order)
    throw std::invalid_argument("two runs do not give an order: assume one (or add a third run)");
  ConvergenceResult r;
  const auto& f1 = runs[0];
  const auto& f2 = runs[1];
  const double r21 = f2.h / f1.h;
  // Orders of every consecutive triple, coarsest first.
  for (std::size_t k = runs.size(); k >= 3; --k) {
    const auto p = observed_order(runs[k - 3], runs[k - 2], runs[k - 1]);
    r.triple_orders.push_back(p ? *p : std::numeric_limits<double>::quiet_NaN());
  }
  std::string problem;
  if (runs.size() >= 3) {
    r.safety_factor = o.safety_factor_three;
    const double p = r.triple_orders.back();
    const double e21 = f2.value - f1.value, e32 = runs[2].value - f2.value;
    if (e21 == 0 && e32 == 0) {
      problem = "the three finest runs give the same value: the quantity does not depend on the resolution";
    } else if (e21 == 0 || e32 == 0 || e32 / e21 < 0) {
      problem = "the differences between the runs change sign (oscillatory convergence or noise): no order";
    } else if (std::isnan(p)) {
      problem = fmt::format(
          "the differences between the runs do not shrink with h (|phi3 - phi2| = {:.3g}, |phi2 - "
          "phi1| = {:.3g}): not converging",
          std::abs(e32), std::abs(e21));
    } else {
      r.order = p;
      r.order_observed = true;
      if (p < o.min_order || p > o.max_order)
        problem = fmt::format("the observed order {:.2f} is outside the plausible range [{:g}, {:g}]", p, o.min_order,
                              o.max_order);
      else if (r.triple_orders.size() >= 2) {
        const double coarser = r.triple_orders[r.triple_orders.size() - 2];
        if (std::isnan(coarser) || std::abs(coarser - p) > o.order_agreement)
          problem = fmt::format(
              "the order changes between the triples ({:.2f} on the coarser, {:.2f} on the finest): "
              "not in the asymptotic range",
              coarser, p);
      }
    }
  }
  if (runs.size() == 2) {  // Roache: an assumed order, and the larger safety factor
    r.order = *o.assumed_order;
    r.safety_factor = o.safety_factor_two;
  }
  if (r.order > 0) {
    const double rp = std::pow(r21, r.order);
    r.extrapolated = f1.value + (f1.value - f2.value) / (rp - 1);
    r.gci = r.safety_factor * std::abs(f1.value - f2.value) / (rp - 1);
    r.gci_relative = f1.value != 0 ? r.gci / std::abs(f1.value) : std::numeric_limits<double>::infinity();
    for (const auto& run : runs) r.estimated_error.push_back(std::abs(run.value - r.extrapolated));
    r.next_h = f1.h / r21;
    r.next_error = std::abs(f1.value - r.extrapolated) / rp;
    r.next_seconds = f2.seconds > 0 ? f1.seconds * f1.seconds / f2.seconds : 0;
  }
  r.asymptotic = problem.empty() && r.order > 0;
  if (!problem.empty())
    r.verdict = problem;
  else if (r.order_observed)
    r.verdict = fmt::format("monotone convergence at the observed order {:.2f}", r.order);
  else
    r.verdict = fmt::format("two runs: order {:g} assumed, safety factor {:g}", r.order, r.safety_factor);
  return r;
}

}  // namespace mpm
