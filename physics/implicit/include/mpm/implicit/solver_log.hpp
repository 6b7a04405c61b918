#pragma once
/// \file solver_log.hpp
/// One row of solver.csv: what a step's solves took.

#include "mpm/core/types.hpp"

namespace mpm::implicit {

struct StepRecord {
  Index step = 0;
  Real time = 0;  ///< s, at the end of the step
  int newton_iterations = 0;
  int gmres_iterations = 0;
  int residual_evaluations = 0;
  Real first_residual = 0;           ///< ||R(predictor)||
  Real last_residual = 0;            ///< ||R|| accepted
  double wall_seconds = 0;           ///< the whole step
  double projection_seconds = 0;     ///< mass matrix, free dofs and (87)
  double residual_seconds = 0;       ///< in R, every evaluation (Jacobian columns, Krylov, line search)
  double factorization_seconds = 0;  ///< sparse LU of the finite-difference Jacobian (the rest of Newton: Krylov)
};

}  // namespace mpm::implicit
