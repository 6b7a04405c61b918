#include "implicit_cases.hpp"

namespace mpm::verification {

namespace {

/// hencky_j2 with the constrained modulus K + 4G/3 = 100 of the linear bar, at a strain amplitude of 1e-4.
BarMode1Spec hencky_bar(const std::string& scheme, int cells, double courant) {
  return {.material = "{model: hencky_j2, density: 1, bulk_modulus: 40, shear_modulus: 45}",
          .scheme = scheme,
          .shape = "linear",
          .cells = cells,
          .courant = courant,
          .v0 = 1e-3};
}

}  // namespace

void add_implicit_cases(std::vector<VerificationCase>& list, bool quick, int refinements) {
  std::vector<int> ladder = quick ? std::vector<int>{8} : std::vector<int>{8, 16, 32, 64};
  for (int r = 0; !quick && r < refinements; ++r) ladder.push_back(2 * ladder.back());
  const std::string reference = "analytic, review eq. 6.4 (mode 1 of a fixed-free bar), hencky_j2 at strain 1e-4";
  const std::string measure = "max |v_cm - exact| over one period / amplitude (-)";
  add_case(list, "bar_mode1_hencky_j2", 1, reference, measure, "implicit", "linear", ladder,
           [](int n) { return run_bar_mode1(hencky_bar("implicit", n, 2.0)); });
  add_case(list, "bar_mode1_hencky_j2", 1, reference, measure, "musl", "linear", ladder,
           [](int n) { return run_bar_mode1(hencky_bar("musl", n, 0.1)); });
}

}  // namespace mpm::verification
