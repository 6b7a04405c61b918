#pragma once
/// \file catalogue.hpp
/// The verification catalogue: every case with a reference (analytic, manufactured, series solution)
/// registered once, for every applicable scheme and shape function, with its error measure and a ladder
/// of resolutions. The tests use it, and the error-against-run-time report (bench/) runs the ladders.
/// A case = one runner (mms.hpp, vortex.hpp, tlmpm_paper.hpp, the bar in catalogue.cpp) at one configuration.
///
/// Adding cases (a physics module, a new benchmark): write a runner that builds the scene for a resolution
/// and returns a CaseRun, then register it in catalogue() (catalogue.cpp) with one explicit call per
/// module, e.g. `add_plasticity_cases(list, quick);` under the module's MPM_WITH_* definition. No static
/// registration: linkers drop unreferenced objects from static libraries (STYLE.md).

#include <functional>
#include <string>
#include <utility>
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
  std::string name;    ///< e.g. "mms_1d_large/tlmpm/cubic_bspline" (= family/scheme/shape_function)
  std::string family;  ///< the problem without the method, e.g. "mms_1d_large": the report's plot groups
  int dimension = 1;
  std::string reference;      ///< where the exact solution comes from
  std::string error_measure;  ///< what CaseRun::error is, with its unit
  std::string scheme, shape_function;
  std::vector<int> resolutions;  ///< cells per side (per bar length, per element count for the 000 cases)
  std::function<CaseRun(int resolution)> run;
};

/// Appends the case family/scheme/shape (the name the report and the tests use) to `list`.
void add_case(std::vector<VerificationCase>& list, const std::string& family, int dimension, std::string reference,
              std::string measure, const std::string& scheme, const std::string& shape, std::vector<int> resolutions,
              std::function<CaseRun(int)> run);

/// Every registered case. `quick`: shorter ladders (smoke runs: the tests run the first resolution of each).
/// `refinements` (ignored when quick): continue every ladder by that many geometric steps (the full report).
std::vector<VerificationCase> catalogue(bool quick = false, int refinements = 0);

/// The vibrating bar of review §6.1.1 (L = 25 m, fixed at x = 0, c = 10 m/s, 2 particles per cell), released in
/// mode 1 at v0: max over one period of |v_cm - (2 v0 / pi) cos(2 pi t / 10)| relative to the amplitude
/// (eq. 6.4), dt = courant h / c.
struct BarMode1Spec {
  std::string material = "{model: linear_elastic, density: 1, youngs_modulus: 100, poisson_ratio: 0}";
  std::string scheme, shape;
  int cells = 8;
  double courant = 0.1;
  double v0 = 0.1;  ///< m/s
};
CaseRun run_bar_mode1(const BarMode1Spec& spec);

/// Every (scheme, shape function) pair the engine accepts in `dimension`: each scheme with each shape
/// function of that dimension (CPDI elements exist in one dimension; Lagrange quadratic only with TLMPM).
/// Taken from the engine's own tables, so a new scheme or shape function joins the cases that use this.
std::vector<std::pair<std::string, std::string>> methods(int dimension);

}  // namespace mpm::verification
