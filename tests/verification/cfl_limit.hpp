#pragma once
/// \file cfl_limit.hpp
/// The largest CFL factor (alpha_dt of review eq. 2.73: dt = alpha_dt min_d h_d / (c + |v_d|)) that a method
/// keeps stable on a problem, found by a search over the factor. The error-against-run-time report
/// (bench/verification_report.cpp) prints it per scheme and shape function for the bar and the two disks.
///
/// A probe runs the problem to its end with dt = factor x Simulation::stable_time_step(), recomputed every
/// step (the adaptive time step of the scenes, driven directly so that factors above 1, which the scene
/// loader refuses, can be tried). It is stable when the stability guard never trips and the total energy
/// never grows by more than 10% of its initial value: an explicit scheme beyond its limit amplifies its
/// highest mode exponentially, which either trips the guard or shows as energy growth within these runs,
/// while below it the energy of the resolved modes only oscillates (by a few per cent near factor 1).
/// "Stable" is over the problem's duration: a run with many more steps may need a slightly smaller factor.

#include <string>
#include <vector>

namespace mpm::verification {

struct CflProbe {
  double cfl = 0;
  bool stable = false;
  double max_energy_growth = 0;  ///< max over the steps of (E(t) - E0) / |E0|
  long long steps = 0;
  std::string failure;  ///< the stability guard's message, or the energy growth, when not stable
};

struct CflLimit {
  std::string problem, scheme, shape_function;
  double largest_stable = 0;       ///< every probed factor up to this one was stable
  double smallest_unstable = 0;    ///< the first unstable factor (0 when every probe up to the maximum was stable)
  std::string failure{};           ///< what happened at smallest_unstable
  std::vector<CflProbe> probes{};  ///< in the order run
};

/// "bar": 1D bar, mode 1 (review §6.1.1), 32 cells, 2 particles per cell, 50 periods (500 s).
/// "two_disks": the two elastic disks of examples/02_two_disks (review §6.1.2) to t = 3.5 s (about 90 steps at
/// factor 1). Not with TLMPM, which has no contact between bodies: its disks pass through each other
/// without deforming, so nothing can go unstable (probe_cfl refuses it).
std::vector<std::string> cfl_problems();

/// One run at one factor.
CflProbe probe_cfl(const std::string& problem, const std::string& scheme, const std::string& shape_function,
                   double cfl);

/// Scans the factor from `step` up to `max` in steps of `step`; after the first unstable factor, bisects
/// `refinements` times between it and the last stable one. Throws std::invalid_argument for an unknown
/// problem.
CflLimit largest_stable_cfl(const std::string& problem, const std::string& scheme, const std::string& shape_function,
                            double step = 0.1, double max = 2.0, int refinements = 4);

}  // namespace mpm::verification
