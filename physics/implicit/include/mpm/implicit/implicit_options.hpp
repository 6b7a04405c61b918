#pragma once
/// \file implicit_options.hpp
/// The keys of `solver.implicit:` (docs/scene-reference.md, solver.implicit), with the defaults.

#include <array>
#include <string_view>
#include <utility>

#include "mpm/core/enum_names.hpp"
#include "mpm/core/types.hpp"

namespace mpm::implicit {

/// The volumetric part of the stress: the three-field Q1/P0 form per cell, eqs. (88c)-(88e), or Theta = J per
/// particle (no mixed field).
enum class VolumetricMode { mixed_cell, pointwise };

struct ImplicitOptions {
  Real newton_rtol = 1e-10;  ///< ||R|| <= newton_rtol R_ref (R_ref: residual_reference, newton_solver.hpp)
  Real newton_atol = 0;      ///< N (force units of the residual), or ||R|| <= newton_atol
  int max_newton_iterations = 25;
  Real linear_rtol = 1e-4;  ///< GMRES relative tolerance
  int max_linear_iterations = 200;
  int gmres_restart = 50;
  Real mass_rtol = 1e-12;  ///< conjugate-gradient tolerance of the projection (87), relative to ||sum N pi||
  VolumetricMode volumetric = VolumetricMode::mixed_cell;
  /// A node whose particles cover less than this fraction of a cell's volume (sum N^A V_p / h^dim) is weak: its
  /// components are extrapolated from two nodes further in (free_dofs.hpp; docs/theory.md §15). 0: none.
  Real weak_node_fraction = 0.1;
  /// Print every Newton iteration, the weak-node split of each step and, when a solve fails, the degrees of
  /// freedom where the residual stays, to stderr. Diagnostics only: the results are the same bits.
  bool newton_trace = false;
};

}  // namespace mpm::implicit

template <>
struct mpm::EnumNames<mpm::implicit::VolumetricMode> {
  static constexpr std::array<std::pair<mpm::implicit::VolumetricMode, std::string_view>, 2> table{
      {{mpm::implicit::VolumetricMode::mixed_cell, "mixed_cell"},
       {mpm::implicit::VolumetricMode::pointwise, "pointwise"}}};
};
