#pragma once
/// \file discrete_gradient.hpp
/// Discrete derivatives of ref. 003 §3.3 (Love & Sulsky; equation numbers are the paper's, docs/implicit.md)
/// for the energy-consistent algorithmic stress of the implicit scheme. Pure functions of the two ends of a
/// step, for 3x3 symmetric tensors (plane strain and axisymmetric included: the zz entries are kept).
///   discrete_gradient          (75)/(79) with the dot product the print drops (erratum):
///                              D f = g + [Delta f + D - g : Delta z] / ||Delta z||^2 Delta z;
///   algorithmic_deviatoric_stress  (81)-(83): S_algo^dev with 1/2 S_algo^dev : Delta C = Delta W~ + Delta D;
///   jacobian_discrete_derivative   D_C J with D_C J : Delta C = Delta J, in closed form (no quotient);
///   algorithmic_stress             (90): S^h = S_algo^dev + 2 p D_C J;
/// and the helpers pull_back (S = F^-1 tau F^-T, eqs. 4, 82) and right_cauchy_green_increment (Delta C from
/// f = 1 + grad Delta phi without the cancellation of C_{n+1} - C_n). D_Theta U is in log_volumetric_energy.hpp.
///
/// When ||Delta z|| is so small that the bracket's numerator is not above its own round-off, the correction
/// is pure noise divided by ||Delta z||: the functions then return the midpoint value g (for S_algo^dev the
/// trapezoidal S-bar of eq. 82), which satisfies the identity to that same round-off (Delta z = 0 included).

#include <cmath>
#include <limits>

#include "mpm/core/types.hpp"

namespace mpm::plasticity {

/// A : B (double contraction).
inline Real contract(const Mat3& a, const Mat3& b) { return (a.array() * b.array()).sum(); }

/// Cofactor matrix cof(A) = det(A) A^-T, as a polynomial (defined for singular A): d det(A) = cof(A) : dA.
inline Mat3 cofactor(const Mat3& a) {
  Mat3 c;
  c(0, 0) = a(1, 1) * a(2, 2) - a(1, 2) * a(2, 1);
  c(0, 1) = a(1, 2) * a(2, 0) - a(1, 0) * a(2, 2);
  c(0, 2) = a(1, 0) * a(2, 1) - a(1, 1) * a(2, 0);
  c(1, 0) = a(0, 2) * a(2, 1) - a(0, 1) * a(2, 2);
  c(1, 1) = a(0, 0) * a(2, 2) - a(0, 2) * a(2, 0);
  c(1, 2) = a(0, 1) * a(2, 0) - a(0, 0) * a(2, 1);
  c(2, 0) = a(0, 1) * a(1, 2) - a(0, 2) * a(1, 1);
  c(2, 1) = a(0, 2) * a(1, 0) - a(0, 0) * a(1, 2);
  c(2, 2) = a(0, 0) * a(1, 1) - a(0, 1) * a(1, 0);
  return c;
}

/// The pull-back S = phi^*(tau) = F^-1 tau F^-T of a spatial (Kirchhoff) tensor (eqs. 4, 82).
inline Mat3 pull_back(const Mat3& F, const Mat3& tau) {
  const Mat3 F_inv = F.inverse();
  const Mat3 S = F_inv * tau * F_inv.transpose();
  return 0.5 * (S + S.transpose());
}

/// Delta C = C_{n+1} - C_n for F_{n+1} = (1 + H) F_n (eq. 91, H = grad_n Delta phi):
/// F_n^T (H + H^T + H^T H) F_n, accurate also when H is tiny (C_{n+1} - C_n would cancel).
inline Mat3 right_cauchy_green_increment(const Mat3& F_n, const Mat3& H) {
  const Mat3 D = F_n.transpose() * (H + H.transpose() + H.transpose() * H) * F_n;
  return 0.5 * (D + D.transpose());
}

/// The same in the inner product <A, B> = A : G B of a metric G (symmetric positive definite on symmetric
/// tensors): D_z f = g + [Delta f + D - g : Delta z] / (Delta z : G Delta z) G Delta z, given `metric_dz` = G Delta z.
/// D_z f : Delta z = Delta f + D exactly for any G (the proofs of (80) and (102)-(106) use only that), so G is
/// free; (75) is G = identity. Gonzalez's discrete gradients are defined for any metric.
inline Mat3 discrete_gradient(const Mat3& mean_gradient, const Mat3& dz, const Mat3& metric_dz, Real increment,
                              Real round_off) {
  constexpr Real eps = std::numeric_limits<Real>::epsilon();
  const Real dz2 = contract(dz, metric_dz), g_dz = contract(mean_gradient, dz);
  const Real numerator = increment - g_dz;
  const Real noise = round_off + 16 * eps * (std::abs(increment) + mean_gradient.norm() * dz.norm());
  if (dz2 == 0 || std::abs(numerator) <= noise) return mean_gradient;  // NaN goes on to the correction
  return mean_gradient + (numerator / dz2) * metric_dz;
}

/// Discrete derivative of a scalar function f of a symmetric tensor z, eqs. (75) and (79) with the dot
/// product restored: D_z f = g + [Delta f + D - g : Delta z] / ||Delta z||^2 Delta z, so that
/// D_z f : Delta z = Delta f + D exactly (eq. 80). `mean_gradient` g is the midpoint (77) or trapezoidal (78)
/// gradient, `increment` = Delta f + D (the dissipation D >= 0 of (79) included), `round_off` an absolute
/// bound on the rounding error of that increment. Returns g when the numerator is not above
/// round_off + its own rounding (then the identity holds to that level).
inline Mat3 discrete_gradient(const Mat3& mean_gradient, const Mat3& dz, Real increment, Real round_off) {
  return discrete_gradient(mean_gradient, dz, dz, increment, round_off);
}

/// The algorithmic deviatoric stress S_algo^dev of eq. (81) with S-bar of eq. (82), from what the material
/// gives at the two ends of the step: S_n = phi_n^*(dev tau_n), S_n1 = phi_{n+1}^*(dev tau_{n+1}) (Pa),
/// W~_n, W~_{n+1} and Delta D (J/m^3 of reference volume), with dC = C_{n+1} - C_n and C_n.
/// 1/2 S_algo^dev : dC = W~_{n+1} - W~_n + Delta D (83).
/// The metric: G dC = C-bar^-1 dC C-bar^-1 (C-bar = C_n + dC/2), not the identity of (75). dC : G dC is then
/// the squared spatial strain increment at the midpoint, whatever the stretch already reached; with the
/// identity, a point compressed 11:1 (eigenvalues of C_n 4.6e-3 and 11) shows its axial strain increment in
/// dC scaled by 4.6e-3, the correction [...] / ||dC||^2 dC grew like 1/||dC||, and the residual had a kink
/// within each Newton step (the implicit Taylor bar, docs/theory.md §15). Objective (C does not see a
/// superposed rotation), symmetric, and the same identity to round-off.
/// The round-off of W~ is that of the principal log strains (absolute eps each): eps ||dev tau|| per unit
/// strain, bounded by eps ||S-bar|| (||C_n|| + ||dC||); the fallback is S-bar.
inline Mat3 algorithmic_deviatoric_stress(const Mat3& S_n, const Mat3& S_n1, Real W_n, Real W_n1, Real dissipation,
                                          const Mat3& C_n, const Mat3& dC) {
  constexpr Real eps = std::numeric_limits<Real>::epsilon();
  const Mat3 S_bar = 0.5 * (S_n + S_n1);
  const Real round_off =
      16 * eps * (std::abs(W_n) + std::abs(W_n1) + dissipation + S_bar.norm() * (C_n.norm() + dC.norm()));
  const Mat3 C_mid_inv = (C_n + 0.5 * dC).inverse();
  Mat3 metric_dC = C_mid_inv * dC * C_mid_inv;
  metric_dC = (0.5 * (metric_dC + metric_dC.transpose())).eval();
  // S_algo = 2 D_C W~ (D = Delta D), whose mean gradient is S-bar / 2
  return 2 * discrete_gradient(0.5 * S_bar, dC, metric_dC, W_n1 - W_n + dissipation, round_off);
}

/// D_C J(C_n, C_{n+1}) for J = sqrt(det C), in closed form: det is cubic, so exactly
///   det C_{n+1} - det C_n = [cof(C-bar) + cof(Delta C)/12] : Delta C   (C-bar the midpoint),
/// and Delta J = Delta det / (J_n + J_{n+1}); hence
///   D_C J = [cof(C-bar) + cof(Delta C)/12] / (J_n + J_{n+1})
/// with D_C J : Delta C = Delta J to round-off for any pair, no quotient by ||Delta C||, symmetric, and
/// D_C J = dJ/dC(C-bar) + O(||Delta C||^2) = J C^-1 / 2 + ... (Def. 3.1). The paper leaves the discrete
/// derivative of J open; the generic (75) with the midpoint gradient is the alternative
/// (jacobian_discrete_derivative_generic). J_n, J_n1 > 0: det F at the two ends.
inline Mat3 jacobian_discrete_derivative(const Mat3& C_n, const Mat3& dC, Real J_n, Real J_n1) {
  const Mat3 C_mid = C_n + 0.5 * dC;
  return (cofactor(C_mid) + cofactor(dC) / 12) / (J_n + J_n1);
}

/// D_C J by the generic (75) with the midpoint gradient (77) dJ/dC(C-bar) = sqrt(det C-bar) C-bar^-1 / 2, for
/// comparison with the closed form. dJ = J_{n+1} - J_n.
inline Mat3 jacobian_discrete_derivative_generic(const Mat3& C_n, const Mat3& dC, Real J_n, Real J_n1) {
  constexpr Real eps = std::numeric_limits<Real>::epsilon();
  const Mat3 C_mid = C_n + 0.5 * dC;
  const Mat3 g = 0.5 * cofactor(C_mid) / std::sqrt(C_mid.determinant());
  return discrete_gradient(g, dC, J_n1 - J_n, 4 * eps * (J_n + J_n1));
}

/// The second Piola-Kirchhoff stress of the mixed form, eq. (90): S^h = S_algo^dev + 2 p D_C J, with p the
/// element's mixed pressure (Pa); 1/2 S^h : Delta C = Delta W~ + Delta D + p Delta J.
inline Mat3 algorithmic_stress(const Mat3& S_dev_algo, Real pressure, const Mat3& D_C_J) {
  return S_dev_algo + 2 * pressure * D_C_J;
}

}  // namespace mpm::plasticity
