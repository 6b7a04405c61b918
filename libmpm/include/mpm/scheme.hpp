#pragma once
/// \file scheme.hpp
/// A time-integration scheme advances every body by one step. Explicit schemes (USL, MUSL) are
/// templates on dimension and shape function; the scene picks one instantiation once (make_scheme).

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "mpm/module.hpp"

namespace mpm {

template <int Dim>
class Scheme {
 public:
  virtual ~Scheme() = default;
  virtual std::string_view name() const = 0;
  virtual std::string_view shape_function() const = 0;
  /// Slab thickness the shape function needs for the race-free scatter.
  virtual int slab_cells() const = 0;
  /// Cells an axis needs at least with this shape function.
  virtual int min_cells() const = 0;
  /// One full step: transfers, grid update, boundary conditions, particle update, stress update.
  virtual void advance(StepContext<Dim>& ctx) = 0;
};

/// "usl" or "musl" with "linear" or "cubic_bspline"; throws std::invalid_argument listing valid names.
template <int Dim>
std::unique_ptr<Scheme<Dim>> make_scheme(const std::string& scheme, const std::string& shape_function);

/// Names accepted by make_scheme.
std::vector<std::string> scheme_names();
std::vector<std::string> shape_function_names();

}  // namespace mpm
