#pragma once
/// \file catalogue.hpp
/// The verification catalogue: every case with a reference (analytic, manufactured, series solution)
/// registered once, for every applicable scheme and shape function, with its error measure and a ladder
/// of resolutions. The tests use it, and the error-against-run-time report (bench/) runs the ladders.
/// A case = one runner (mms.hpp, vortex.hpp, tlmpm_paper.hpp, the bar below) at one configuration.

#include <functional>
#include <string>
#include <vector>

namespace mpm::verification {

/// One run of a case at one resolution.
struct CaseRun {
  double error = 0;         ///< the case's error measure (see VerificationCase::error_measure)
  double wall_seconds = 0;  ///< building and running
  long long steps = 0;
  long long particles = 0;
  double h = 0;         ///< cell size, m
  std::string failure;  ///< empty, or why the run stopped (stability guard); then error = +inf
};

struct VerificationCase {
  std::string name;           ///< e.g. "mms_1d_large/tlmpm/cubic_bspline"
  std::string reference;      ///< where the exact solution comes from
  std::string error_measure;  ///< what CaseRun::error is, with its unit
  std::string scheme, shape_function;
  std::vector<int> resolutions;  ///< cells per side (per bar length, per element count for the 000 cases)
  std::function<CaseRun(int resolution)> run;
};

/// Every registered case. `quick`: shorter ladders (for smoke runs).
std::vector<VerificationCase> catalogue(bool quick = false);

}  // namespace mpm::verification
