#pragma once
/// \file newton_krylov.hpp
/// Newton-Krylov for NonlinearProblem, started at the point of least ||R|| among s x (s = 1, 1/2, 1/4, 1/8, 0;
/// x the given predictor): each Newton direction from Eigen's restarted GMRES (unsupported module,
/// shipped with Eigen) on the matrix-free operator J v = [R(x + e v) - R(x)]/e, preconditioned by the
/// sparse LU of a finite-difference Jacobian built column group by column group (the problem's colouring),
/// then a backtracking line search that halves the step while R is inadmissible (det F <= 0, Theta <= 0) or
/// ||R|| does not decrease (Armijo, 1e-4). The lumped mass alone (2 M_L / dt^2) was too weak a preconditioner
/// once the stiffness dominates (dt far above the explicit bound); the Jacobian is rebuilt when a direction
/// fails. Everything is serial or in a fixed order: the same bits for any thread count.

#include <string>

#include "mpm/implicit/nonlinear_problem.hpp"

namespace mpm::implicit {

struct NewtonSettings {
  Real rtol = 1e-10;  ///< relative to `reference` (solve())
  Real atol = 0;
  int max_iterations = 25;
  Real linear_rtol = 1e-4;
  int max_linear_iterations = 200;
  int restart = 50;
  /// The Newton update is negligible when ||dx|| <= step_rtol ||x|| (PETSc SNES's "stol", same default). When
  /// no step reduces ||R|| any more and the last Newton update was negligible, ||R|| has reached the floor at
  /// which its evaluation rounds (the terms it sums are ~1e10 times larger than R there): the iterate is
  /// accepted as converged at that floor instead of failing a tolerance below what R can resolve.
  Real step_rtol = 1e-8;
  /// Print each Newton iteration (residual, line search, GMRES count, worst degree of freedom) to stderr
  /// (`solver.implicit.newton_trace`): for diagnosing a solve that does not converge.
  bool trace = false;
};

struct NewtonStats {
  int iterations = 0;            ///< Newton iterations
  int linear_iterations = 0;     ///< GMRES iterations, all Newton iterations together
  int residual_evaluations = 0;  ///< calls of R (Jacobian columns, Krylov products and line search included)
  int jacobians = 0;             ///< finite-difference Jacobians built and factorised
  Real first_residual = 0;       ///< ||R(x_0)||
  Real last_residual = 0;        ///< ||R|| at the returned x
  Real tolerance = 0;            ///< max(atol, rtol * reference)
  double residual_seconds = 0;   ///< wall time in R (Jacobian columns, Krylov products, line search)
  double factor_seconds = 0;     ///< wall time in the sparse LU factorisations
  bool converged = false;
  bool at_rounding_floor = false;  ///< converged by the negligible update (step_rtol), above the tolerance
  std::string failure;             ///< why not, when not converged
};

/// Drives R(x) to ||R|| <= max(atol, rtol * reference) from the predictor x (overwritten with the last accepted
/// iterate), or to where no step reduces ||R|| while the Newton update is negligible (step_rtol). x = 0 must be
/// admissible; the iteration starts at the admissible s x (s = 1, 1/2, 1/4, 1/8, 0) of least ||R||, or at x
/// itself when it converges there.
NewtonStats solve_newton_krylov(NonlinearProblem& problem, Vector& x, Real reference, const NewtonSettings& settings);

}  // namespace mpm::implicit
