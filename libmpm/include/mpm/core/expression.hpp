#pragma once
/// \file expression.hpp
/// Scalar math expressions of space and time from scene files ("0.1*sin(2*_pi*t)", "0.2*x", "3"),
/// evaluated with muparser. The text is parsed once, at construction; evaluation is then cheap.

#include <memory>
#include <string>
#include <vector>

namespace mpm {

/// A muparser expression of the variables x, y, z (m) and t (s).
///
/// Only the variables named at construction may appear in the text; the others are still passed to
/// operator() but ignored. Built-in muparser functions (sin, cos, exp, sqrt, abs, min, max, ...),
/// operators (+ - * / ^, comparisons, `?:`) and constants (_pi, _e) are available.
///
/// Copying re-parses the text (muparser binds variable addresses, which live inside the object);
/// moving is cheap (a moved-from Expression may only be assigned to or destroyed). Evaluation writes the variables into
/// the object, so one Expression must not be evaluated from several threads at the same time: give each thread its own
/// copy.
class Expression {
 public:
  /// Parses `text`. Throws std::invalid_argument (with muparser's message) on a syntax error, on a
  /// variable that is not in `variables`, or on a `variables` entry other than x, y, z, t.
  explicit Expression(const std::string& text, const std::vector<std::string>& variables = {"x", "y", "z", "t"});
  Expression(const Expression& other);
  Expression(Expression&& other) noexcept;
  Expression& operator=(const Expression& other);
  Expression& operator=(Expression&& other) noexcept;
  ~Expression();

  /// Value at position (x, y, z) and time t.
  double operator()(double x, double y, double z, double t) const;
  /// Value at position p = (x, y, z) and time t.
  double evaluate(const double (&p)[3], double t) const { return (*this)(p[0], p[1], p[2], t); }

  /// True when the expression uses no variable (e.g. "2*_pi"): its value never changes.
  bool is_constant() const;
  /// The value of a constant expression (for a non-constant one: its value at x = y = z = t = 0).
  double constant_value() const;

  /// The text as given.
  const std::string& text() const;
  /// The variables the text may use, as given.
  const std::vector<std::string>& variables() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace mpm
