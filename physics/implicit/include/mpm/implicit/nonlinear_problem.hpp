#pragma once
/// \file nonlinear_problem.hpp
/// The small interface between a nonlinear system R(x) = 0 and the solver that drives it to zero
/// (newton_krylov.hpp; a PETSc SNES backend could implement the same contract later). The scheme's residual
/// (88a) with (88b)-(91) is one (mixed_residual.hpp).

#include <Eigen/Core>
#include <vector>

#include "mpm/core/types.hpp"

namespace mpm::implicit {

using Vector = Eigen::VectorXd;

class NonlinearProblem {
 public:
  virtual ~NonlinearProblem() = default;
  /// Number of unknowns.
  virtual Index size() const = 0;
  /// r = R(x). False when x is inadmissible (det F <= 0, Theta <= 0 or a non-finite value): the solver then
  /// shortens its step.
  virtual bool residual(const Vector& x, Vector& r) = 0;
  /// The sparsity of the Jacobian for a finite-difference approximation of it: groups of columns that share no
  /// row (each perturbed together), and the rows each column can be non-zero in.
  virtual const std::vector<std::vector<Index>>& column_groups() const = 0;
  virtual const std::vector<std::vector<Index>>& column_rows() const = 0;
  /// The size below which an unknown counts as zero, for finite-difference steps (the unknowns' unit).
  virtual Real unknown_scale() const = 0;
};

}  // namespace mpm::implicit
