#include "mpm/core/units.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <numbers>
#include <system_error>
#include <vector>

#include "mpm/core/closest_name.hpp"

namespace mpm::units {
namespace {

// The base quantities, in the order of Dimension::exponent.
constexpr int kg = 0, m = 1, s = 2, K = 3, rad = 4;

constexpr Dimension dim(int mass, int length, int time, int temperature = 0, int angle = 0) {
  return {{mass, length, time, temperature, angle}};
}

struct Base {
  std::string_view symbol;
  double factor;  ///< its size in SI units of its dimension is factor x 10^decimal_exponent
  int decimal_exponent;
  Dimension dimension;
  bool prefixable;
};

/// The symbols a unit is made of. A prefix is never tried before the whole symbol, so `min` is a minute, not a
/// milli-inch, and `Pa` a pascal.
constexpr std::array bases{
    Base{"m", 1, 0, dim(0, 1, 0), true},
    Base{"g", 1, -3, dim(1, 0, 0), true},
    Base{"s", 1, 0, dim(0, 0, 1), true},
    Base{"K", 1, 0, dim(0, 0, 0, 1), true},
    Base{"N", 1, 0, dim(1, 1, -2), true},
    Base{"Pa", 1, 0, dim(1, -1, -2), true},
    Base{"J", 1, 0, dim(1, 2, -2), true},
    Base{"W", 1, 0, dim(1, 2, -3), true},
    Base{"Hz", 1, 0, dim(0, 0, -1), true},
    Base{"bar", 1, 5, dim(1, -1, -2), true},
    Base{"t", 1, 3, dim(1, 0, 0), true},   // tonne (the mm-t-s system's mass: t/mm^3, N, MPa)
    Base{"L", 1, -3, dim(0, 3, 0), true},  // litre
    Base{"rad", 1, 0, dim(0, 0, 0, 0, 1), true},
    Base{"min", 60, 0, dim(0, 0, 1), false},
    Base{"h", 3600, 0, dim(0, 0, 1), false},
    Base{"deg", std::numbers::pi / 180, 0, dim(0, 0, 0, 0, 1), false},
    Base{"degrees", std::numbers::pi / 180, 0, dim(0, 0, 0, 0, 1), false},
    Base{"\u00b0", std::numbers::pi / 180, 0, dim(0, 0, 0, 0, 1), false},  // °
};

struct Prefix {
  std::string_view symbol;
  int decimal_exponent;
};

constexpr std::array prefixes{
    Prefix{"p", -12},     Prefix{"n", -9}, Prefix{"u", -6}, Prefix{"\u00b5", -6},  // µ, the micro sign
    Prefix{"\u03bc", -6},                                                          // μ, the Greek mu
    Prefix{"m", -3},      Prefix{"c", -2}, Prefix{"k", 3},  Prefix{"M", 6},       Prefix{"G", 9}, Prefix{"T", 12},
};

/// Every symbol a scene may write: the bases, and the prefixed ones (for "did you mean").
std::vector<std::string> all_symbols() {
  std::vector<std::string> names;
  for (const Base& b : bases) {
    names.emplace_back(b.symbol);
    if (!b.prefixable) continue;
    for (const Prefix& p : prefixes)
      if (p.symbol.size() == 1) names.push_back(std::string(p.symbol) + std::string(b.symbol));
  }
  return names;
}

bool same_ignoring_case(std::string_view a, std::string_view b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
           return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
         });
}

/// Words a scene may write for a unit that is not a symbol here, and what to write instead.
struct Hint {
  std::string_view word;
  std::string_view hint;
};
constexpr std::array hints{
    Hint{"cc", " (did you mean 'cm^3'?)"},
    Hint{"sec", " (did you mean 's'?)"},
    Hint{"secs", " (did you mean 's'?)"},
    Hint{"msec", " (did you mean 'ms'?)"},
    Hint{"usec", " (did you mean 'us'?)"},
    Hint{"hr", " (did you mean 'h'?)"},
    Hint{"hrs", " (did you mean 'h'?)"},
    Hint{"mins", " (did you mean 'min'?)"},
    Hint{"C", " (temperatures are absolute: K)"},
    Hint{"degC", " (temperatures are absolute: K)"},
    Hint{"\u00b0C", " (temperatures are absolute: K)"},
    Hint{"psi", " (imperial units are not read: write SI)"},
    Hint{"ksi", " (imperial units are not read: write SI)"},
    Hint{"lb", " (imperial units are not read: write SI)"},
    Hint{"lbf", " (imperial units are not read: write SI)"},
    Hint{"in", " (imperial units are not read: write SI)"},
    Hint{"ft", " (imperial units are not read: write SI)"},
};

/// " (did you mean 'GPa'?)", " (did you mean 'MPa' or 'mPa'?)" or nothing.
std::string suggestion(std::string_view word) {
  for (const Hint& h : hints)
    if (h.word == word) return std::string(h.hint);
  const auto names = all_symbols();
  std::vector<std::string> same_letters;
  for (const auto& n : names)
    if (same_ignoring_case(n, word)) same_letters.push_back("'" + n + "'");
  if (!same_letters.empty()) return fmt::format(" (did you mean {}?)", fmt::join(same_letters, " or "));
  return did_you_mean(word, names);
}

const std::string& known_units() {
  static const std::string text =
      "units are SI symbols, with a prefix p n u (or µ) m c k M G T: m g s K N Pa J W Hz bar t (tonne) L (litre) "
      "rad; and min h deg without one";
  return text;
}

Unit times(const Unit& a, const Unit& b, int sign) {
  Unit u{sign > 0 ? a.factor * b.factor : a.factor / b.factor, a.decimal_exponent + sign * b.decimal_exponent,
         a.dimension};
  for (std::size_t i = 0; i < u.dimension.exponent.size(); ++i)
    u.dimension.exponent[i] += sign * b.dimension.exponent[i];
  return u;
}

Unit power(const Unit& a, int n) {
  Unit u{std::pow(a.factor, n), a.decimal_exponent * n, a.dimension};
  for (int& e : u.dimension.exponent) e *= n;
  return u;
}

/// A recursive-descent reader of the grammar of units.hpp over one unit text.
class UnitParser {
 public:
  explicit UnitParser(std::string_view text) : text_(text) {}

  Unit parse() {
    Unit u = unit();
    skip_space();
    if (at_end()) return u;
    if (peek() == ')') fail("a ')' without its '('");
    fail(fmt::format("unexpected '{}'", rest()));
  }

 private:
  /// unit := product [ "/" factor ], and nothing that multiplies after the factor.
  Unit unit() {
    Unit u = product();
    skip_space();
    if (at_end() || peek() != '/') return u;
    ++pos_;
    u = times(u, factor(), -1);
    skip_space();
    if (!at_end() && peek() != ')')
      fail(fmt::format("only one factor may follow '/' (write J/(kg K), not J/kg/K or J/kg K), got '{}' after it",
                       rest()));
    return u;
  }

  Unit product() {
    Unit u = factor();
    for (;;) {
      skip_space();
      if (at_end()) return u;
      if (const std::size_t n = multiplication_sign()) {
        pos_ += n;
        u = times(u, factor(), 1);
      } else if (starts_factor()) {  // a space: "Pa s"
        u = times(u, factor(), 1);
      } else {
        return u;
      }
    }
  }

  /// factor := ( symbol | "1" | "(" unit ")" ) [ "^" integer | "²" | "³" ]
  Unit factor() {
    skip_space();
    if (at_end()) fail("a unit symbol is missing at the end");
    Unit u;
    if (peek() == '(') {
      ++pos_;
      u = unit();
      skip_space();
      if (at_end() || peek() != ')') fail("a '(' without its ')'");
      ++pos_;
    } else if (peek() == '1' &&
               (pos_ + 1 == text_.size() || !std::isdigit(static_cast<unsigned char>(text_[pos_ + 1])))) {
      ++pos_;  // the numerator of 1/s
    } else if (is_letter(pos_)) {
      u = symbol();
    } else {
      fail(fmt::format("expected a unit symbol at '{}'", rest()));
    }
    return exponent(u);
  }

  Unit exponent(const Unit& u) {
    skip_space();
    if (text_.substr(pos_).starts_with("\u00b2")) return pos_ += 2, power(u, 2);  // ²
    if (text_.substr(pos_).starts_with("\u00b3")) return pos_ += 2, power(u, 3);  // ³
    if (at_end() || peek() != '^') return u;
    ++pos_;
    skip_space();
    const char* begin = text_.data() + pos_ + (!at_end() && peek() == '+' ? 1 : 0);
    int n = 0;
    const auto [end, error] = std::from_chars(begin, text_.data() + text_.size(), n);
    if (error != std::errc() || end == begin)
      fail(fmt::format("expected an integer power after '^', got '{}'", rest()));
    pos_ = static_cast<std::size_t>(end - text_.data());
    return power(u, n);
  }

  Unit symbol() {
    const std::size_t begin = pos_;
    while (!at_end() && is_letter(pos_)) pos_ += letter_size(pos_);
    const std::string_view word = text_.substr(begin, pos_ - begin);
    if (const Base* b = find_base(word)) return {b->factor, b->decimal_exponent, b->dimension};
    for (const Prefix& p : prefixes)
      if (word.size() > p.symbol.size() && word.starts_with(p.symbol))
        if (const Base* b = find_base(word.substr(p.symbol.size())); b && b->prefixable)
          return {b->factor, p.decimal_exponent + b->decimal_exponent, b->dimension};
    throw UnitError(fmt::format("unknown unit '{}'{}; {}", word, suggestion(word), known_units()));
  }

  static const Base* find_base(std::string_view word) {
    for (const Base& b : bases)
      if (b.symbol == word) return &b;
    return nullptr;
  }

  /// The bytes of a letter at `i`: ASCII letters, µ, μ and °.
  std::size_t letter_size(std::size_t i) const {
    const unsigned char c = static_cast<unsigned char>(text_[i]);
    if (std::isalpha(c)) return 1;
    const std::string_view tail = text_.substr(i);
    for (std::string_view two : {"\u00b5", "\u03bc", "\u00b0"})
      if (tail.starts_with(two)) return two.size();
    return 0;
  }
  bool is_letter(std::size_t i) const { return letter_size(i) > 0; }

  /// The bytes of a multiplication sign at the current place: '*', '.', '·' (0 when none).
  std::size_t multiplication_sign() const {
    if (peek() == '*' || peek() == '.') return 1;
    return text_.substr(pos_).starts_with("\u00b7") ? 2 : 0;
  }
  bool starts_factor() const { return peek() == '(' || peek() == '1' || is_letter(pos_); }

  void skip_space() {
    while (!at_end() && std::isspace(static_cast<unsigned char>(peek()))) ++pos_;
  }
  bool at_end() const { return pos_ >= text_.size(); }
  char peek() const { return text_[pos_]; }
  std::string_view rest() const { return text_.substr(pos_); }

  [[noreturn]] void fail(const std::string& why) const {
    throw UnitError(fmt::format("cannot read the unit '{}': {}", text_, why));
  }

  std::string_view text_;
  std::size_t pos_ = 0;
};

/// Names of the dimensions the scene's keys have (and a few more a slip may give).
struct NamedDimension {
  Dimension dimension;
  std::string_view name;
};

constexpr std::array named_dimensions{
    NamedDimension{dim(0, 0, 0), "a dimensionless number"},
    NamedDimension{dim(0, 1, 0), "a length"},
    NamedDimension{dim(1, 0, 0), "a mass"},
    NamedDimension{dim(0, 0, 1), "a time"},
    NamedDimension{dim(0, 0, 0, 1), "a temperature"},
    NamedDimension{dim(0, 0, 0, 0, 1), "an angle"},
    NamedDimension{dim(0, 2, 0), "an area"},
    NamedDimension{dim(0, 3, 0), "a volume"},
    NamedDimension{dim(1, -1, -2), "a pressure"},
    NamedDimension{dim(1, -3, 0), "a density"},
    NamedDimension{dim(0, 1, -1), "a velocity"},
    NamedDimension{dim(0, 1, -2), "an acceleration"},
    NamedDimension{dim(1, 1, -2), "a force"},
    NamedDimension{dim(1, 2, -2), "an energy"},
    NamedDimension{dim(1, 2, -3), "a power"},
    NamedDimension{dim(0, 0, -1), "a rate"},
    NamedDimension{dim(1, -1, -1), "a viscosity"},
    NamedDimension{dim(0, 2, -2, -1), "a specific heat"},
    NamedDimension{dim(1, 1, -3, -1), "a thermal conductivity"},
    NamedDimension{dim(1, 0, -3, -1), "a heat transfer coefficient"},
    NamedDimension{dim(1, 0, -3), "a heat flux"},
    NamedDimension{dim(1, -1, -3), "a heat source per volume"},
    NamedDimension{dim(0, 0, 0, -1), "a coefficient per kelvin"},
};

}  // namespace

Unit parse_unit(std::string_view text) {
  const auto first = text.find_first_not_of(" \t");
  if (first == std::string_view::npos || text.substr(first) == "-") return {};
  return UnitParser(text).parse();
}

std::string describe(const Dimension& dimension) {
  for (const auto& d : named_dimensions)
    if (d.dimension == dimension) return std::string(d.name);
  constexpr std::array<std::string_view, 5> symbols{"kg", "m", "s", "K", "rad"};
  std::string text = "a quantity in";
  for (std::size_t i = 0; i < symbols.size(); ++i)
    if (const int e = dimension.exponent[i])
      text += e == 1 ? fmt::format(" {}", symbols[i]) : fmt::format(" {}^{}", symbols[i], e);
  return text;
}

double Unit::size() const { return factor * std::pow(10.0, decimal_exponent); }

std::optional<NumberWithUnit> split_number(std::string_view text) {
  const auto first = text.find_first_not_of(" \t");
  if (first == std::string_view::npos) return std::nullopt;
  text.remove_prefix(first);
  if (text.front() == '+') text.remove_prefix(1);
  double value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || !std::isfinite(value)) return std::nullopt;
  const auto length = static_cast<std::size_t>(end - text.data());
  std::string_view unit = text.substr(length);
  const auto b = unit.find_first_not_of(" \t"), e = unit.find_last_not_of(" \t");
  unit = b == std::string_view::npos ? std::string_view() : unit.substr(b, e - b + 1);
  return NumberWithUnit{value, text.substr(0, length), unit};
}

namespace {

/// The number written times 10^shift, correctly rounded: the decimal exponent is moved in its text. Beyond the
/// doubles' range: the product in floating point (an infinity, which the reader refuses as not finite, or 0).
double shifted(const NumberWithUnit& value, int shift) {
  if (shift == 0) return value.number;
  std::string significand(value.number_text);
  int exponent = 0;
  if (const auto e = significand.find_first_of("eE"); e != std::string::npos) {
    const char* digits = significand.data() + e + 1;
    if (*digits == '+') ++digits;
    std::from_chars(digits, significand.data() + significand.size(), exponent);
    significand.resize(e);
  }
  const std::string moved = fmt::format("{}e{}", significand, exponent + shift);
  double result = 0;
  const auto [end, error] = std::from_chars(moved.data(), moved.data() + moved.size(), result);
  if (error != std::errc() || end != moved.data() + moved.size()) return value.number * std::pow(10.0, shift);
  return result;
}

}  // namespace

int UnitSystem::exponent(const Dimension& dimension) const {
  return mass * dimension.exponent[0] + length * dimension.exponent[1] + time * dimension.exponent[2];
}

double UnitSystem::length_unit() const { return std::pow(10.0, length); }

const std::vector<UnitSystem>& unit_systems() {
  static const std::vector<UnitSystem> systems{
      {"m-s-kg", 0, 0, 0, "SI: N, Pa, J, kg/m^3"},
      {"mm-ms-g", -3, -3, -3, "N, MPa, mJ (N mm), g/mm^3 (LS-DYNA's mm-ms-g)"},
      {"mm-ms-kg", 0, -3, -3, "kN, GPa, J (kN mm), kg/mm^3"},
      {"mm-s-tonne", 3, -3, 0, "N, MPa, mJ (N mm), tonne/mm^3 (Abaqus' and LS-DYNA's mm-s-t)"},
      {"cm-us-g", -3, -2, -6, "10 MN, Mbar, 100 kJ (10 MN cm), g/cm^3"},
  };
  return systems;
}

const UnitSystem* find_unit_system(std::string_view name) {
  for (const auto& system : unit_systems())
    if (system.name == name) return &system;
  return nullptr;
}

double to_key_unit(const NumberWithUnit& value, std::string_view key_unit, const UnitSystem& system) {
  if (!value.unit.empty() || system.si()) return to_key_unit(value, key_unit);
  const Unit wanted = parse_unit(key_unit);
  const int exponent = system.exponent(wanted.dimension);
  if (exponent == 0) return value.number;  // the system's unit of this dimension is SI's: the key's own unit
  // the number in the system's unit, i.e. times 10^exponent in SI, then in the key's unit
  return shifted(value, exponent - wanted.decimal_exponent) / wanted.factor;
}

double to_key_unit(const NumberWithUnit& value, std::string_view key_unit) {
  const Unit wanted = parse_unit(key_unit);
  if (value.unit.empty()) return value.number;
  const Unit given = parse_unit(value.unit);
  if (given.dimension != wanted.dimension) {
    const bool plain = key_unit.empty() || key_unit == "-";
    throw UnitError(fmt::format("expected {}{}, got {} ({})", describe(wanted.dimension),
                                plain ? "" : fmt::format(" ({})", key_unit), describe(given.dimension), value.unit));
  }
  const double factor = given.factor / wanted.factor;
  return shifted(value, given.decimal_exponent - wanted.decimal_exponent) * factor;
}

}  // namespace mpm::units
