#pragma once
// Exact solution of the Riemann problem for the ideal gas (Toro, "Riemann Solvers and Numerical Methods
// for Fluid Dynamics", 3rd ed., ch. 4: pressure function 4.5-4.7 solved by Newton iteration 4.44, star
// velocity 4.9, sampling 4.53-4.63). The reference of the Sod shock-tube test (review §6.1.4).
#include <algorithm>
#include <cmath>

namespace mpm::test {

struct GasState {
  double rho, u, p;
};

class ExactRiemann {
 public:
  ExactRiemann(GasState left, GasState right, double gamma) : L_(left), R_(right), g_(gamma) {
    cL_ = std::sqrt(g_ * L_.p / L_.rho);
    cR_ = std::sqrt(g_ * R_.p / R_.rho);
    double p = std::max(1e-8, 0.5 * (L_.p + R_.p));
    for (int it = 0; it < 100; ++it) {
      double fL, dL, fR, dR;
      f(p, L_, cL_, fL, dL);
      f(p, R_, cR_, fR, dR);
      const double next = std::max(1e-12, p - (fL + fR + R_.u - L_.u) / (dL + dR));
      const bool done = std::abs(next - p) < 1e-14 * (next + p);
      p = next;
      if (done) break;
    }
    p_star_ = p;
    double fL, dL, fR, dR;
    f(p, L_, cL_, fL, dL);
    f(p, R_, cR_, fR, dR);
    u_star_ = 0.5 * (L_.u + R_.u) + 0.5 * (fR - fL);
  }
  double p_star() const { return p_star_; }
  double u_star() const { return u_star_; }

  /// The state at x/t = s (the discontinuity at x = 0, t > 0).
  GasState sample(double s) const {
    const double gm = (g_ - 1) / (2 * g_), gp = (g_ + 1) / (2 * g_);
    if (s <= u_star_) {      // left of the contact
      if (p_star_ > L_.p) {  // left shock
        const double SL = L_.u - cL_ * std::sqrt(gp * p_star_ / L_.p + gm);
        if (s <= SL) return L_;
        const double r = p_star_ / L_.p, k = (g_ - 1) / (g_ + 1);
        return {L_.rho * (r + k) / (k * r + 1), u_star_, p_star_};
      }
      const double head = L_.u - cL_, c_star = cL_ * std::pow(p_star_ / L_.p, gm), tail = u_star_ - c_star;
      if (s <= head) return L_;
      if (s >= tail) return {L_.rho * std::pow(p_star_ / L_.p, 1 / g_), u_star_, p_star_};
      const double c = 2 / (g_ + 1) * (cL_ + (g_ - 1) / 2 * (L_.u - s));
      const double rho = L_.rho * std::pow(c / cL_, 2 / (g_ - 1));
      return {rho, 2 / (g_ + 1) * (cL_ + (g_ - 1) / 2 * L_.u + s), L_.p * std::pow(c / cL_, 2 * g_ / (g_ - 1))};
    }
    if (p_star_ > R_.p) {  // right shock
      const double SR = R_.u + cR_ * std::sqrt(gp * p_star_ / R_.p + gm);
      if (s >= SR) return R_;
      const double r = p_star_ / R_.p, k = (g_ - 1) / (g_ + 1);
      return {R_.rho * (r + k) / (k * r + 1), u_star_, p_star_};
    }
    const double head = R_.u + cR_, c_star = cR_ * std::pow(p_star_ / R_.p, gm), tail = u_star_ + c_star;
    if (s >= head) return R_;
    if (s <= tail) return {R_.rho * std::pow(p_star_ / R_.p, 1 / g_), u_star_, p_star_};
    const double c = 2 / (g_ + 1) * (cR_ - (g_ - 1) / 2 * (R_.u - s));
    const double rho = R_.rho * std::pow(c / cR_, 2 / (g_ - 1));
    return {rho, 2 / (g_ + 1) * (-cR_ + (g_ - 1) / 2 * R_.u + s), R_.p * std::pow(c / cR_, 2 * g_ / (g_ - 1))};
  }

 private:
  // Toro 4.6-4.7: the pressure function of one side and its derivative.
  void f(double p, const GasState& K, double c, double& value, double& derivative) const {
    if (p > K.p) {
      const double A = 2 / ((g_ + 1) * K.rho), B = (g_ - 1) / (g_ + 1) * K.p, root = std::sqrt(A / (p + B));
      value = (p - K.p) * root;
      derivative = root * (1 - 0.5 * (p - K.p) / (B + p));
    } else {
      const double r = p / K.p;
      value = 2 * c / (g_ - 1) * (std::pow(r, (g_ - 1) / (2 * g_)) - 1);
      derivative = std::pow(r, -(g_ + 1) / (2 * g_)) / (K.rho * c);
    }
  }
  GasState L_, R_;
  double g_, cL_, cR_, p_star_ = 0, u_star_ = 0;
};

}  // namespace mpm::test
