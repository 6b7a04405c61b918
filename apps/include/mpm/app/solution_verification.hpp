#pragma once
/// \file solution_verification.hpp
/// Solution verification of a quantity computed at several resolutions (`mpm verify`, docs/verify.md): the
/// observed order of convergence, Richardson's extrapolation and Roache's grid-convergence index (GCI), an
/// error band on the finest run that holds when the runs are in the asymptotic range. Pure arithmetic on
/// (h, value, seconds) triples; no simulation here.
///
/// With phi_k = phi_exact + C h_k^p on three resolutions h1 < h2 < h3 (r21 = h2/h1, r32 = h3/h2):
///   (phi3 - phi2)/(phi2 - phi1) = r21^p (r32^p - 1)/(r21^p - 1)                (solved for p; = r^p if r is constant)
///   phi_ext = phi1 + (phi1 - phi2)/(r21^p - 1)                                  (Richardson 1911)
///   GCI = Fs |phi1 - phi2| / (r21^p - 1),  Fs = 1.25 (three or more runs), 3 (two) (Roache 1994, 1998)
/// following Celik et al. (2008) except that p is found by bisection, which also tells divergence (no p > 0
/// fits) from convergence.

#include <optional>
#include <string>
#include <vector>

namespace mpm {

/// One run: its resolution (a representative cell size, m), the quantity, and the wall time it took (s).
struct ConvergenceRun {
  double h = 0;
  double value = 0;
  double seconds = 0;
};

struct ConvergenceOptions {
  double safety_factor_three = 1.25;  ///< Roache's Fs with an observed order (three or more runs)
  double safety_factor_two = 3.0;     ///< with an assumed order (two runs)
  double min_order = 0.5;             ///< an observed order outside [min, max] is not believed
  double max_order = 4.0;
  /// Largest difference between the orders of the two finest triples (four or more runs) for the runs to count
  /// as asymptotic. (Roache's ratio GCI_32 / (r^p GCI_21) is 1 by construction on the triple p comes from, so
  /// with three runs only the plausibility of p and the monotone convergence are checked.)
  double order_agreement = 0.5;
  std::optional<double> assumed_order;  ///< needed with two runs (then Fs = 3)
};

struct ConvergenceResult {
  /// The order, extrapolation and GCI below are believable: monotone convergence at a plausible order (and,
  /// with four or more runs, the same order on the two finest triples).
  bool asymptotic = false;
  std::string verdict;  ///< one sentence: what was found, or why there is no number
  double order = 0;     ///< observed order p of the finest triple (or the assumed one); 0 when none
  bool order_observed = false;
  std::vector<double> triple_orders;  ///< p of each consecutive triple, coarsest first (NaN where none fits)
  double extrapolated = 0;            ///< Richardson-extrapolated value
  double gci = 0;                     ///< band on the finest run: |phi_1 - phi_exact| <= gci (absolute)
  double gci_relative = 0;            ///< gci / |phi_1| (infinite when phi_1 = 0)
  double safety_factor = 0;
  std::vector<double> estimated_error;  ///< |phi_k - extrapolated| for each run (the work-precision table)
  /// One more refinement by the finest ratio: its cell size, predicted error |phi - phi_exact| and wall time (the
  /// finest run's times its growth per refinement).
  double next_h = 0, next_error = 0, next_seconds = 0;
};

/// The observed order p of three runs (any order of the arguments' resolutions: sorted inside), or nothing
/// when no p > 0 fits (divergence, oscillation, or no change between the runs).
std::optional<double> observed_order(ConvergenceRun a, ConvergenceRun b, ConvergenceRun c);

/// Analyses runs at two or more distinct resolutions (any order). Throws std::invalid_argument for fewer than
/// two runs, a resolution given twice or not > 0, or two runs without an assumed order.
ConvergenceResult analyse_convergence(std::vector<ConvergenceRun> runs, const ConvergenceOptions& options = {});

}  // namespace mpm
