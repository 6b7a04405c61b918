#include "mpm/core/expression.hpp"

#include <muParser.h>

#include <numbers>
#include <stdexcept>
#include <utility>

namespace mpm {

/// Heap-held so that the variable addresses bound into the parser survive moves of the Expression.
struct Expression::Impl {
  std::string text;
  std::vector<std::string> variables;
  double x = 0, y = 0, z = 0, t = 0;
  mu::Parser parser;
  bool constant = false;
  double constant_value = 0;

  Impl(const std::string& text_, const std::vector<std::string>& variables_) : text(text_), variables(variables_) {
    try {
      for (const auto& name : variables) {
        if (name == "x")
          parser.DefineVar("x", &x);
        else if (name == "y")
          parser.DefineVar("y", &y);
        else if (name == "z")
          parser.DefineVar("z", &z);
        else if (name == "t")
          parser.DefineVar("t", &t);
        else
          throw std::invalid_argument("unsupported expression variable '" + name +
                                      "' (only x, y, z and t are available)");
      }
      // muparser's own _pi and _e carry only 12 digits; use the full double values.
      parser.DefineConst("_pi", std::numbers::pi);
      parser.DefineConst("_e", std::numbers::e);
      parser.SetExpr(text);
      // muparser parses lazily: evaluate once so that syntax errors surface here, not mid-run.
      constant_value = parser.Eval();
      if (parser.GetNumResults() != 1)
        throw std::invalid_argument("expression \"" + text + "\" gives " + std::to_string(parser.GetNumResults()) +
                                    " comma-separated values, expected one");
      constant = parser.GetUsedVar().empty();
    } catch (const mu::Parser::exception_type& e) {
      throw std::invalid_argument("invalid expression \"" + text + "\": " + e.GetMsg());
    }
  }
};

Expression::Expression(const std::string& text, const std::vector<std::string>& variables)
    : impl_(std::make_unique<Impl>(text, variables)) {}

Expression::Expression(const Expression& other)
    : impl_(std::make_unique<Impl>(other.impl_->text, other.impl_->variables)) {}

Expression::Expression(Expression&& other) noexcept = default;

Expression& Expression::operator=(const Expression& other) {
  if (this != &other) impl_ = std::make_unique<Impl>(other.impl_->text, other.impl_->variables);
  return *this;
}

Expression& Expression::operator=(Expression&& other) noexcept = default;

Expression::~Expression() = default;

double Expression::operator()(double x, double y, double z, double t) const {
  Impl& e = *impl_;
  if (e.constant) return e.constant_value;
  e.x = x;
  e.y = y;
  e.z = z;
  e.t = t;
  return e.parser.Eval();
}

bool Expression::is_constant() const { return impl_->constant; }

double Expression::constant_value() const { return impl_->constant_value; }

const std::string& Expression::text() const { return impl_->text; }

const std::vector<std::string>& Expression::variables() const { return impl_->variables; }

}  // namespace mpm
