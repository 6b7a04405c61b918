#pragma once
/// \file umat_tangent_check.hpp
/// `mpm material-test --check` for a UMAT: its DDSDDE against finite differences of its own STRESS, at every step of a
/// path. DSTRAN's component k is moved by +-h (h = 1e-7; engineering shear) and DFGRD1 with it, F_{n+1} <- (I + h E_k)
/// F_{n+1} (E_k the tensor of that component), everything else of the call (the rotated stress, STATEV, DROT) kept:
/// the derivative the tangent stands for. A step where a perturbation crosses a kink of the law (the onset of
/// yield) has different one-sided slopes; the tangent is compared with the central and both one-sided differences and
/// the closest counts.

#include <utility>
#include <vector>

#include "mpm/user_material/user_material.hpp"

namespace mpm::user_material {

struct TangentCheck {
  double difference = 0;    ///< the largest |DDSDDE - finite difference| over the steps, relative to max |DDSDDE|
  double time = 0;          ///< s, the step's end where it is
  int row = 0, column = 0;  ///< 1-based DDSDDE indices of it
  int steps = 0;            ///< steps checked
};

/// Drives one point of `material` (interface umat) through the deformation gradients `path` ((time, F) after each
/// step from F = I at t = 0) and checks its tangent at every step (see the file comment).
TangentCheck check_umat_tangent(UserMaterial<3>& material, const std::vector<std::pair<double, Mat3>>& path);

}  // namespace mpm::user_material
