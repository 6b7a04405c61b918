// Newton-Krylov (newton_krylov.hpp): Eigen's GMRES on a matrix-free finite-difference operator, preconditioned
// by the sparse LU of a coloured finite-difference Jacobian; backtracking line search.
#include "mpm/implicit/newton_krylov.hpp"

#include <fmt/format.h>

#include <Eigen/SparseCore>
#include <Eigen/SparseLU>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <unsupported/Eigen/IterativeSolvers>

namespace mpm::implicit {
class JacobianOperator;
}

// Eigen's matrix-free protocol: the operator looks like a sparse matrix to the iterative solvers.
template <>
struct Eigen::internal::traits<mpm::implicit::JacobianOperator>
    : public Eigen::internal::traits<Eigen::SparseMatrix<double>> {};

namespace mpm::implicit {

/// J v = [R(x + e v) - R(x)] / e with e = sqrt(eps) max(||x||, s sqrt(n)) / ||v|| (s: the problem's unknown
/// scale), about the base point x with R(x) known.
class JacobianOperator : public Eigen::EigenBase<JacobianOperator> {
 public:
  using Scalar = double;
  using RealScalar = double;
  using StorageIndex = int;
  enum { ColsAtCompileTime = Eigen::Dynamic, MaxColsAtCompileTime = Eigen::Dynamic, IsRowMajor = false };

  JacobianOperator(NonlinearProblem& problem, const Vector& x, const Vector& r, NewtonStats& stats)
      : problem_(problem), x_(x), r_(r), stats_(stats), trial_(x.size()), r_trial_(x.size()) {}
  Eigen::Index rows() const { return x_.size(); }
  Eigen::Index cols() const { return x_.size(); }

  template <typename Rhs>
  Eigen::Product<JacobianOperator, Rhs, Eigen::AliasFreeProduct> operator*(const Eigen::MatrixBase<Rhs>& v) const {
    return Eigen::Product<JacobianOperator, Rhs, Eigen::AliasFreeProduct>(*this, v.derived());
  }

  /// out += alpha J v.
  void apply(const Vector& v, Vector& out, double alpha) const {
    const double norm_v = v.norm();
    if (norm_v == 0) return;
    const double scale = std::max(x_.norm(), problem_.unknown_scale() * std::sqrt(double(x_.size())));
    double e = std::sqrt(std::numeric_limits<double>::epsilon()) * scale / norm_v;
    for (int tries = 0; tries < 30; ++tries, e *= 0.5) {  // halve the probe while it leaves the admissible set
      trial_ = x_ + e * v;
      ++stats_.residual_evaluations;
      if (problem_.residual(trial_, r_trial_)) {
        out += (alpha / e) * (r_trial_ - r_);
        return;
      }
    }
    out.setConstant(std::numeric_limits<double>::quiet_NaN());
  }

 private:
  NonlinearProblem& problem_;
  const Vector& x_;
  const Vector& r_;
  NewtonStats& stats_;
  mutable Vector trial_, r_trial_;
};

/// The preconditioner: the sparse LU of the finite-difference Jacobian (factorised outside, compute() is a no-op).
class LuPreconditioner {
 public:
  using StorageIndex = int;
  enum { ColsAtCompileTime = Eigen::Dynamic, MaxColsAtCompileTime = Eigen::Dynamic };
  LuPreconditioner() = default;
  template <typename MatType>
  explicit LuPreconditioner(const MatType&) {}
  template <typename MatType>
  LuPreconditioner& analyzePattern(const MatType&) {
    return *this;
  }
  template <typename MatType>
  LuPreconditioner& factorize(const MatType&) {
    return *this;
  }
  template <typename MatType>
  LuPreconditioner& compute(const MatType&) {
    return *this;
  }
  void set(const Eigen::SparseLU<Eigen::SparseMatrix<double>>* lu) { lu_ = lu; }
  template <typename Rhs>
  Vector solve(const Eigen::MatrixBase<Rhs>& b) const {
    return lu_ ? Vector(lu_->solve(Vector(b))) : Vector(b);
  }
  Eigen::ComputationInfo info() { return Eigen::Success; }

 private:
  const Eigen::SparseLU<Eigen::SparseMatrix<double>>* lu_ = nullptr;
};

}  // namespace mpm::implicit

template <typename Rhs>
struct Eigen::internal::generic_product_impl<mpm::implicit::JacobianOperator, Rhs, Eigen::SparseShape,
                                             Eigen::DenseShape, Eigen::GemvProduct>
    : Eigen::internal::generic_product_impl_base<
          mpm::implicit::JacobianOperator, Rhs,
          generic_product_impl<mpm::implicit::JacobianOperator, Rhs, Eigen::SparseShape, Eigen::DenseShape,
                               Eigen::GemvProduct>> {
  using Scalar = typename Eigen::Product<mpm::implicit::JacobianOperator, Rhs>::Scalar;
  template <typename Dest>
  static void scaleAndAddTo(Dest& dst, const mpm::implicit::JacobianOperator& lhs, const Rhs& rhs,
                            const Scalar& alpha) {
    mpm::implicit::Vector out = dst;
    lhs.apply(mpm::implicit::Vector(rhs), out, alpha);
    dst = out;
  }
};

namespace mpm::implicit {
namespace {

using SparseMatrix = Eigen::SparseMatrix<double>;
using Clock = std::chrono::steady_clock;

/// The problem with the time spent in its residual counted (NewtonStats::residual_seconds, solver.csv).
class TimedProblem final : public NonlinearProblem {
 public:
  TimedProblem(NonlinearProblem& problem, double& seconds) : problem_(problem), seconds_(seconds) {}
  Index size() const override { return problem_.size(); }
  bool residual(const Vector& x, Vector& r) override {
    const auto start = Clock::now();
    const bool ok = problem_.residual(x, r);
    seconds_ += std::chrono::duration<double>(Clock::now() - start).count();
    return ok;
  }
  const std::vector<std::vector<Index>>& column_groups() const override { return problem_.column_groups(); }
  const std::vector<std::vector<Index>>& column_rows() const override { return problem_.column_rows(); }
  Real unknown_scale() const override { return problem_.unknown_scale(); }

 private:
  NonlinearProblem& problem_;
  double& seconds_;
};

/// Runs f and adds its wall time to `seconds`.
template <class F>
void timed(double& seconds, F&& f) {
  const auto start = Clock::now();
  f();
  seconds += std::chrono::duration<double>(Clock::now() - start).count();
}

/// The finite-difference Jacobian at x (R(x) = r), one residual per column group; false if a probe fails.
bool finite_difference_jacobian(NonlinearProblem& problem, const Vector& x, const Vector& r, SparseMatrix& J,
                                NewtonStats& stats) {
  const Index n = problem.size();
  const auto& groups = problem.column_groups();
  const auto& rows = problem.column_rows();
  const double root_eps = std::sqrt(std::numeric_limits<double>::epsilon());
  const double floor = problem.unknown_scale();
  std::vector<Eigen::Triplet<double>> entries;
  Vector trial = x, r_trial(n), step(n);
  for (const auto& group : groups) {
    for (Index j : group) {
      step[j] = root_eps * std::max(std::abs(x[j]), floor);
      trial[j] = x[j] + step[j];
      step[j] = trial[j] - x[j];  // the step actually taken (exactly representable)
    }
    ++stats.residual_evaluations;
    const bool ok = problem.residual(trial, r_trial);
    for (Index j : group) trial[j] = x[j];
    if (!ok) return false;
    for (Index j : group)
      for (Index i : rows[j])
        entries.emplace_back(static_cast<int>(i), static_cast<int>(j), (r_trial[i] - r[i]) / step[j]);
  }
  J.resize(static_cast<int>(n), static_cast<int>(n));
  J.setFromTriplets(entries.begin(), entries.end());
  ++stats.jacobians;
  return true;
}

}  // namespace

NewtonStats solve_newton_krylov(NonlinearProblem& untimed, Vector& x, Real reference, const NewtonSettings& s) {
  NewtonStats stats;
  TimedProblem problem(untimed, stats.residual_seconds);
  const Index n = problem.size();
  Vector r(n), r_trial(n), x_trial(n);
  // The start: of the points s x0 (s = 1, 1/2, 1/4, 1/8, 0) between the predictor x0 and x = 0 (F_{n+1} = F_n,
  // always admissible), the admissible one with the smallest ||R||; the predictor alone when it converges
  // already (a uniform translation). Where a body meets a wall at speed the predictor is a poor start: at the
  // Taylor bar's first step on the halved mesh it compresses the cells on the wall by 62% (||R|| = 7.0e6
  // against 1.6e5 at x = 0), the linearisation there is nearly singular (Newton directions of 1e-2 m, 30 cells,
  // along the axis nodes) and Newton stalled; from x = 0 it converges in 6 full steps.
  const Vector x0 = x;
  const double tolerance = std::max(s.atol, s.rtol * reference);
  double best = std::numeric_limits<double>::infinity(), best_scale = 1;
  for (double scale : {1.0, 0.5, 0.25, 0.125, 0.0}) {
    x_trial = scale * x0;
    ++stats.residual_evaluations;
    if (!problem.residual(x_trial, r_trial) || !(r_trial.norm() < best)) continue;
    best = r_trial.norm(), best_scale = scale;
    x = x_trial, r = r_trial;
    if (best <= tolerance) break;
  }
  if (!std::isfinite(best)) {
    stats.failure = "the start of the Newton iteration is inadmissible";
    return stats;
  }
  if (s.trace) std::fprintf(stderr, "start: %g x predictor, |R| %.6e\n", best_scale, best);
  stats.first_residual = stats.last_residual = r.norm();
  stats.tolerance = std::max(s.atol, s.rtol * reference);
  SparseMatrix J;
  Eigen::SparseLU<SparseMatrix> lu;
  bool have_lu = false;
  bool fresh_jacobian = false;  // rebuild when the last iteration reduced ||R|| by less than 10x
  double previous = std::numeric_limits<double>::infinity();
  for (;; ++stats.iterations) {
    const double norm = r.norm();
    stats.last_residual = norm;
    if (!std::isfinite(norm)) {
      stats.failure = "non-finite residual";
      return stats;
    }
    if (norm <= stats.tolerance) {
      stats.converged = true;
      return stats;
    }
    if (stats.iterations >= s.max_iterations) {
      stats.failure = fmt::format("no convergence in {} Newton iterations", s.max_iterations);
      return stats;
    }
    fresh_jacobian = !have_lu || norm > 0.1 * previous;
    previous = norm;
    bool accepted = false;
    double newton_update = std::numeric_limits<double>::infinity();  // ||dx|| of the last finite Newton direction
    for (int attempt = 0; attempt < 2 && !accepted; ++attempt) {
      if (fresh_jacobian || attempt > 0) {  // a fresh Jacobian at the current iterate when the old one is stale
        if (!finite_difference_jacobian(problem, x, r, J, stats)) break;
        timed(stats.factor_seconds, [&] { lu.compute(J); });
        have_lu = lu.info() == Eigen::Success;
        if (!have_lu) break;
      }
      JacobianOperator A(problem, x, r, stats);
      Eigen::GMRES<JacobianOperator, LuPreconditioner> gmres;
      gmres.setTolerance(s.linear_rtol);
      gmres.setMaxIterations(s.max_linear_iterations);
      gmres.set_restart(s.restart);
      gmres.compute(A);
      gmres.preconditioner().set(&lu);
      const Vector dx = gmres.solve(Vector(-r));
      stats.linear_iterations += static_cast<int>(gmres.iterations());
      if (!dx.allFinite()) continue;
      newton_update = dx.norm();
      // backtracking: halve while inadmissible or without sufficient decrease (Armijo, 1e-4)
      double alpha = 1;
      int inadmissible = 0;
      for (int k = 0; k < 12; ++k, alpha *= 0.5) {
        x_trial = x + alpha * dx;
        ++stats.residual_evaluations;
        const bool ok = problem.residual(x_trial, r_trial);
        inadmissible += ok ? 0 : 1;
        if (ok && r_trial.norm() <= (1 - 1e-4 * alpha) * norm) {
          accepted = true;
          break;
        }
      }
      if (s.trace) {
        Index worst = 0;
        r_trial.cwiseAbs().maxCoeff(&worst);
        std::fprintf(stderr,
                     "newton %d: |R| %.6e -> %.6e alpha %g (%d inadmissible) |dx| %.3e gmres %d fresh %d worst dof %ld "
                     "|r| %.3e\n",
                     stats.iterations, norm, r_trial.norm(), alpha, inadmissible, dx.norm(),
                     static_cast<int>(gmres.iterations()), int(fresh_jacobian || attempt > 0), static_cast<long>(worst),
                     std::abs(r_trial[worst]));
      }
      if (accepted) {
        x = x_trial;
        r = r_trial;
      }
    }
    // Levenberg-Marquardt: (J + mu diag|J|) dx = -R directly from the LU, mu growing, while Newton's direction
    // (along which the line search found no decrease) fails: the step turns toward a scaled gradient-like one.
    if (!accepted && J.rows() == n) {
      const double current = r.norm();
      Vector diagonal = J.diagonal().cwiseAbs();
      for (double mu : {1e-4, 1e-2, 1.0, 1e2}) {
        SparseMatrix regularised = J;
        for (Index k = 0; k < n; ++k)
          regularised.coeffRef(static_cast<int>(k), static_cast<int>(k)) += mu * diagonal[k];
        Eigen::SparseLU<SparseMatrix> lm;
        timed(stats.factor_seconds, [&] { lm.compute(regularised); });
        if (lm.info() != Eigen::Success) continue;
        const Vector dx = lm.solve(Vector(-r));
        x_trial = x + dx;
        ++stats.residual_evaluations;
        if (dx.allFinite() && problem.residual(x_trial, r_trial) && r_trial.norm() < current) {
          x = x_trial;
          r = r_trial;
          accepted = true;
          have_lu = false;  // the next iteration builds a fresh Jacobian
          break;
        }
      }
    }
    if (!accepted && newton_update <= s.step_rtol * x.norm()) {
      stats.converged = stats.at_rounding_floor = true;
      return stats;
    }
    if (!accepted) {
      stats.failure = "neither the line search along the Newton direction nor a Levenberg-Marquardt step reduced ||R||";
      return stats;
    }
  }
}

}  // namespace mpm::implicit
