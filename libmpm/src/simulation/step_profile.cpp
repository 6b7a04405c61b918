#include "mpm/simulation/step_profile.hpp"

#include <fmt/format.h>

namespace mpm {

double StepProfile::stepping_seconds() const { return total_seconds() - (*this)[StepPhase::output]; }

double StepProfile::total_seconds() const {
  double s = 0;
  for (double x : seconds) s += x;
  return s;
}

void FusedSplit::distribute(StepProfile& profile, double wall) const {
  const double a = transfer.load(), b = stress.load();
  const double share = a + b > 0 ? a / (a + b) : 1;
  profile.add(StepPhase::g2p, wall * share);
  profile.add(StepPhase::stress_update, wall * (1 - share));
}

std::string format_profile(const StepProfile& p) {
  const double total = p.total_seconds();
  std::string out = fmt::format("{:<14} {:>10} {:>7} {:>22}\n", "phase", "seconds", "share", "ns/particle-update");
  for (int i = 0; i < step_phase_count; ++i) {
    const double s = p.seconds[static_cast<std::size_t>(i)];
    out += fmt::format("{:<14} {:>10.4f} {:>6.1f}% {:>22.2f}\n", step_phase_names[static_cast<std::size_t>(i)], s,
                       total > 0 ? 100 * s / total : 0.0,
                       p.particle_updates > 0 ? 1e9 * s / static_cast<double>(p.particle_updates) : 0.0);
  }
  out += fmt::format("{:<14} {:>10.4f} {:>6.1f}% {:>22.2f}\n", "total", total, 100.0,
                     p.particle_updates > 0 ? 1e9 * total / static_cast<double>(p.particle_updates) : 0.0);
  out += fmt::format("{} steps, {} particle-updates", p.steps, p.particle_updates);
  return out;
}

}  // namespace mpm
