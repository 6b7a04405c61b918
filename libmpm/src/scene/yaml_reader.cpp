#include "mpm/scene/yaml_reader.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <system_error>

#include "mpm/core/closest_name.hpp"
#include "mpm/core/expression.hpp"
#include "mpm/core/units.hpp"
#include "mpm/scene/scene_error.hpp"

namespace mpm::io {

YAML::Mark mark_of(const YAML::Node& node, const YAML::Mark& fallback) {
  return !node.IsDefined() || node.IsNull() || node.Mark().is_null() ? fallback : node.Mark();
}

std::string describe(const YAML::Node& node) {
  switch (node.Type()) {
    case YAML::NodeType::Scalar:
      return "'" + node.Scalar() + "'";
    case YAML::NodeType::Sequence:
      return "a list";
    case YAML::NodeType::Map:
      return "a map";
    default:
      return "nothing";
  }
}

std::optional<double> parse_number(std::string_view text) {
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  double value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || !std::isfinite(value)) return std::nullopt;
  return value;
}

SourceLocation YamlReader::location(const YAML::Mark& mark) const {
  if (mark.is_null()) return {file_, 0, 0};
  return {file_, mark.line + 1, mark.column + 1};
}

void YamlReader::fail(const YAML::Mark& mark, const std::string& key, const std::string& message) const {
  throw SceneError(location(mark), key, message);
}

void YamlReader::fail(const YamlValue& value, const std::string& message) const {
  fail(value.mark, value.path, message);
}

namespace {

/// An expression of a unit system's x, y, z (lengths) and t (a time), with its value in the system's unit of
/// `key_unit`, rewritten as one of SI's: each variable divided by its unit's size in SI, the whole multiplied by the
/// system's unit of the key in the key's unit. Numbers (with their exponents) and other names are kept as written.
std::string expression_in_si(const std::string& text, const units::UnitSystem& system, std::string_view key_unit) {
  const auto variable_in_si = [&](std::string_view name) -> std::optional<std::string> {
    if (name == "x" || name == "y" || name == "z") return fmt::format("({}/1e{})", name, system.length);
    if (name == "t") return fmt::format("(t/1e{})", system.time);
    return std::nullopt;
  };
  const auto word = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
  std::string out;
  out.reserve(2 * text.size());
  for (std::size_t i = 0; i < text.size();) {
    const char c = text[i];
    std::size_t end = i + 1;
    if (std::isdigit(static_cast<unsigned char>(c)) || c == '.') {  // a number literal, exponent included
      while (end < text.size() && (std::isdigit(static_cast<unsigned char>(text[end])) || text[end] == '.')) ++end;
      if (end < text.size() && (text[end] == 'e' || text[end] == 'E')) {
        std::size_t e = end + 1;
        if (e < text.size() && (text[e] == '+' || text[e] == '-')) ++e;
        if (e < text.size() && std::isdigit(static_cast<unsigned char>(text[e]))) {
          end = e;
          while (end < text.size() && std::isdigit(static_cast<unsigned char>(text[end]))) ++end;
        }
      }
      out.append(text, i, end - i);
    } else if (word(c)) {
      while (end < text.size() && word(text[end])) ++end;
      const std::string_view name(text.data() + i, end - i);
      const auto replaced = variable_in_si(name);
      out.append(replaced ? *replaced : std::string(name));
    } else {
      out += c;
    }
    i = end;
  }
  const units::Unit wanted = units::parse_unit(key_unit);
  const int exponent = system.exponent(wanted.dimension);
  if (exponent == 0) return out;  // the system's unit of the value is SI's: the key's own unit
  const int shift = exponent - wanted.decimal_exponent;
  return wanted.factor == 1 ? fmt::format("1e{}*({})", shift, out)
                            : fmt::format("1e{}/{}*({})", shift, wanted.factor, out);
}

}  // namespace

double YamlReader::number(const YamlValue& value) const {
  if (value.node.IsScalar())
    if (const auto x = units::split_number(value.node.Scalar())) {
      if (x->unit.empty()) return x->number;
      fail(value, fmt::format("expected a plain number (this key has no unit), got '{}'", value.node.Scalar()));
    }
  fail(value, "expected a number, got " + describe(value.node));
}

double YamlReader::number(const YamlValue& value, const Range& range, std::string_view unit) const {
  const auto x = value.node.IsScalar() ? units::split_number(value.node.Scalar()) : std::nullopt;
  if (!x) fail(value, "expected a number, got " + describe(value.node));
  double si = 0;
  try {
    si = units::to_key_unit(*x, unit, *system_);
  } catch (const units::UnitError& e) {
    fail(value, e.what());
  }
  const std::string written = !x->unit.empty() ? fmt::format(" ({})", value.node.Scalar())
                              : system_->si()  ? ""
                                               : fmt::format(" ({} in {})", value.node.Scalar(), system_->name);
  if (!std::isfinite(si))
    fail(value, fmt::format("{} is beyond the range of a double in {}", value.node.Scalar(), unit));
  if (!range.contains(si))
    fail(value,
         fmt::format("out of range: must be {}, got {}{}{}", range.describe(unit), si, unit_suffix(unit), written));
  return si;
}

int YamlReader::integer(const YamlValue& value, int minimum) const {
  std::optional<double> x;
  if (value.node.IsScalar()) x = parse_number(value.node.Scalar());
  if (!x || std::floor(*x) != *x) fail(value, "expected an integer, got " + describe(value.node));
  if (*x < minimum) fail(value, fmt::format("out of range: must be >= {}, got {}", minimum, *x));
  if (*x > std::numeric_limits<int>::max()) fail(value, fmt::format("too large: {}", *x));
  return static_cast<int>(*x);
}

std::string YamlReader::string(const YamlValue& value) const {
  if (!value.node.IsScalar()) fail(value, "expected a string, got " + describe(value.node));
  return value.node.Scalar();
}

std::string YamlReader::name(const YamlValue& value) const {
  std::string text = string(value);
  if (text.empty()) fail(value, "must not be empty");
  return text;
}

std::string YamlReader::choice(const YamlValue& value, const std::vector<std::string>& allowed) const {
  const bool ok =
      value.node.IsScalar() && std::find(allowed.begin(), allowed.end(), value.node.Scalar()) != allowed.end();
  if (!ok)
    fail(value, fmt::format("invalid value {}{}; valid values: {}", describe(value.node),
                            value.node.IsScalar() ? did_you_mean(value.node.Scalar(), allowed) : "",
                            fmt::join(allowed, ", ")));
  return value.node.Scalar();
}

bool YamlReader::boolean(const YamlValue& value) const {
  bool b = false;
  if (!value.node.IsScalar() || !YAML::convert<bool>::decode(value.node, b))
    fail(value, "expected true or false, got " + describe(value.node));
  return b;
}

std::vector<YamlValue> YamlReader::list(const YamlValue& value, std::optional<std::size_t> length,
                                        std::string_view what, std::string_view each) const {
  if (!value.node.IsSequence()) {
    if (length) fail(value, fmt::format("expected a list of {} {}, got {}", *length, what, describe(value.node)));
    fail(value, fmt::format("expected a list of {}, got {}", what, describe(value.node)));
  }
  const std::size_t size = value.node.size();
  if (length && size != *length)
    fail(value, fmt::format("expected a list of {} {}{}, got {} {}", *length, what,
                            each.empty() ? "" : fmt::format(" ({})", each), size, size == 1 ? "entry" : "entries"));
  std::vector<YamlValue> items;
  for (std::size_t i = 0; i < size; ++i) {
    const YAML::Node item = value.node[i];
    items.push_back({item, fmt::format("{}[{}]", value.path, i), mark_of(item, value.mark)});
  }
  return items;
}

std::vector<YamlValue> YamlReader::per_axis(const YamlValue& value, int dimension, std::string_view what) const {
  if (value.node.IsScalar()) return std::vector<YamlValue>(dimension, value);
  if (!value.node.IsSequence())
    fail(value, fmt::format("expected a number or a list of {} {}, got {}", dimension, what, describe(value.node)));
  return list(value, dimension, what);
}

std::array<double, 3> YamlReader::vector(const YamlValue& value, int dimension, const Range& range,
                                         std::string_view unit) const {
  std::array<double, 3> result{0, 0, 0};
  const auto items = list(value, dimension, "numbers");
  for (int d = 0; d < dimension; ++d) result[d] = number(items[d], range, unit);
  return result;
}

std::string YamlReader::expression(const YamlValue& value, const std::vector<std::string>& variables,
                                   std::string_view unit) const {
  const std::string allowed = fmt::format("{}", fmt::join(variables, ", "));
  if (!value.node.IsScalar() || value.node.Scalar().empty())
    fail(value, fmt::format("expected a number or an expression of {}, got {}", allowed, describe(value.node)));
  const std::string& text = value.node.Scalar();
  // A number, or a number with a unit ("-800 m/s"), is the number in the key's unit; "2 t" with t a variable, or
  // "2*t", is left to muparser.
  std::string unit_problem;  // when the text reads as a number and a word that is not a unit ("-800 m/ss")
  if (const auto x = units::split_number(text)) {
    if (x->unit.empty()) return fmt::format("{}", system_->si() ? x->number : number(value, Range::any(), unit));
    const bool variable = std::find(variables.begin(), variables.end(), x->unit) != variables.end();
    if (!variable) try {
        units::parse_unit(x->unit);  // a unit: of the key's dimension, or refused
        return fmt::format("{}", number(value, Range::any(), unit));
      } catch (const units::UnitError& e) {  // not a unit: muparser's, e.g. "2*t"
        if (!std::ispunct(static_cast<unsigned char>(x->unit.front()))) unit_problem = e.what();
      }
  }
  try {
    const Expression e(text, variables);
    if (e.is_constant() && !std::isfinite(e.constant_value()))
      fail(value, fmt::format("expression \"{}\" evaluates to {}", text, e.constant_value()));
  } catch (const std::invalid_argument& e) {
    fail(value, fmt::format("{} (variables allowed here: {}){}", e.what(), allowed,
                            unit_problem.empty() ? "" : "; as a number with a unit: " + unit_problem));
  }
  return system_->si() ? text : expression_in_si(text, *system_, unit);
}

YamlMap YamlReader::map(const YamlValue& value) const { return YamlMap(*this, value); }

YamlMap::YamlMap(const YamlReader& reader, YamlValue value) : reader_(reader), self_(std::move(value)) {
  if (!self_.node.IsMap()) reader_.fail(self_, "expected a map, got " + describe(self_.node));
  for (auto it = self_.node.begin(); it != self_.node.end(); ++it) {
    const YAML::Node key = it->first;
    const YAML::Mark key_mark = mark_of(key, self_.mark);
    if (!key.IsScalar()) reader_.fail(key_mark, self_.path, "keys must be plain names, got " + describe(key));
    const std::string& name = key.Scalar();
    const std::string path = path_of(name);
    if (const Entry* first = find_entry(name))
      reader_.fail(key_mark, path,
                   fmt::format("duplicate key (first given at line {})", reader_.location(first->key_mark).line));
    entries_.push_back({name, key_mark, {it->second, path, mark_of(it->second, key_mark)}});
  }
}

void YamlMap::allow(const std::vector<std::string>& allowed, std::string_view noun, std::string_view context) const {
  for (const auto& e : entries_)
    if (std::find(allowed.begin(), allowed.end(), e.key) == allowed.end())
      reader_.fail(e.key_mark, e.value.path,
                   fmt::format("unknown {} '{}'{}{}; valid {}s: {}", noun, e.key, context,
                               noun == "face" ? "" : did_you_mean(e.key, allowed),  // y_min in 1D: no slip of x_min
                               noun, fmt::join(allowed, ", ")));
}

std::optional<YamlValue> YamlMap::find(std::string_view key) const {
  if (const Entry* e = find_entry(key)) return e->value;
  return std::nullopt;
}

YamlValue YamlMap::required(std::string_view key, std::string_view noun, std::string_view detail) const {
  if (const Entry* e = find_entry(key)) return e->value;
  reader_.fail(self_.mark, path_of(key), fmt::format("missing required {} '{}'{}", noun, key, detail));
}

std::string YamlMap::path_of(std::string_view key) const {
  return self_.path.empty() ? std::string(key) : self_.path + "." + std::string(key);
}

const YamlMap::Entry* YamlMap::find_entry(std::string_view key) const {
  for (const auto& e : entries_)
    if (e.key == key) return &e;
  return nullptr;
}

}  // namespace mpm::io
