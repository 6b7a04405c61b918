#pragma once
/// \file exact_sum.hpp
/// A correctly rounded sum of doubles (Shewchuk 1997, "Adaptive precision floating-point arithmetic"; the
/// algorithm of Python's math.fsum): the result is the exact sum rounded once, so it does not depend on the
/// order of the terms. Histories (reactions, region sums), the energy audit (energy.hpp) and the contact
/// forces use it so that a number is the same for any thread count, any particle order and, later, any
/// number of ranks: partial sums merged (merge()) give the bits of one sum over all the terms.

#include <cmath>
#include <cstddef>
#include <vector>

namespace mpm {

class ExactSum {
 public:
  /// Adds x exactly (the partial sums stay non-overlapping; a few partials in practice).
  void add(double x) {
    if (!std::isfinite(x)) {  // inf/NaN: the ordinary sum propagates them
      special_ += x;
      return;
    }
    std::size_t i = 0;
    for (double y : partials_) {
      if (std::abs(x) < std::abs(y)) std::swap(x, y);
      const double hi = x + y;
      const double lo = y - (hi - x);
      if (lo != 0) partials_[i++] = lo;
      x = hi;
    }
    partials_.resize(i);
    partials_.push_back(x);
  }
  ExactSum& operator+=(double x) {
    add(x);
    return *this;
  }
  /// Adds every term of `o` (its partials are exact pieces of its sum): the result is the sum of both sets.
  void merge(const ExactSum& o) {
    for (double x : o.partials_) add(x);
    special_ += o.special_;
  }
  /// The exact sum rounded to the nearest double (ties to even); 0 for no term.
  double value() const {
    if (special_ != 0 || std::isnan(special_)) return special_;
    std::size_t n = partials_.size();
    if (n == 0) return 0;
    double hi = partials_[--n];
    double lo = 0;
    while (n > 0) {  // add the partials from the top until one is not absorbed
      const double x = hi;
      const double y = partials_[--n];
      hi = x + y;
      lo = y - (hi - x);
      if (lo != 0) break;
    }
    // Round half to even: if the rest has the sign of lo, the tie is broken towards it.
    if (n > 0 && ((lo < 0 && partials_[n - 1] < 0) || (lo > 0 && partials_[n - 1] > 0))) {
      const double y = lo * 2;
      const double x = hi + y;
      if (y == x - hi) hi = x;
    }
    return hi;
  }
  void clear() {
    partials_.clear();
    special_ = 0;
  }

 private:
  std::vector<double> partials_;
  double special_ = 0;
};

}  // namespace mpm
