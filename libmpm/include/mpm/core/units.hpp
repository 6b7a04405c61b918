#pragma once
/// \file units.hpp
/// Numbers with units, as a scene may write them (`youngs_modulus: 210 GPa`, `density: 7.85 g/cm^3`,
/// `end_time: 25 us`): a unit expression parsed to its size in SI units and its dimension, so that the YAML reader
/// (scene/yaml_reader.hpp) converts a value to the SI unit of its key and refuses one of another dimension
/// ("expected a length (m), got a pressure (GPa)"). docs/scene-reference.md, "Units", gives the grammar:
///
///     unit    := product [ "/" factor ]          one solidus; a product after it needs parentheses
///     product := factor { ("*" | "." | "·" | " ") factor }
///     factor  := ( symbol | "1" | "(" unit ")" ) [ "^" integer ]
///     symbol  := [ prefix ] base                 prefixes p n u µ m c k M G T
///     base    := m g s K N Pa J W Hz bar t (tonne) L (litre) rad | min h deg degrees (no prefix)
///
/// Temperatures are absolute (K); degrees Celsius are not a unit here (their zero is not SI's).

#include <array>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace mpm::units {

/// The exponents of a unit's base quantities: mass (kg), length (m), time (s), temperature (K) and plane angle
/// (rad; an angle is kept apart from a plain number so that `90 deg` cannot be given for a ratio).
struct Dimension {
  std::array<int, 5> exponent{};

  bool dimensionless() const { return exponent == std::array<int, 5>{}; }
  bool operator==(const Dimension&) const = default;
};

/// A unit: its size in SI units of its dimension, factor x 10^decimal_exponent (1 GPa = 1 x 10^9 Pa, 1 g/cm^3 =
/// 1 x 10^3 kg/m^3, 1 deg = pi/180 rad). The powers of ten are kept apart so that a value converted with SI prefixes
/// alone is the correctly rounded double of what was written: `7.85 g/cm^3` is exactly 7850, `210 GPa` 210e9.
struct Unit {
  double factor = 1;
  int decimal_exponent = 0;
  Dimension dimension{};

  /// Its size in SI units.
  double size() const;
};

/// A unit that is not one: the message says where and why ("unknown unit 'Gpa' (did you mean 'GPa'?)").
class UnitError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

/// The unit written as `text` (the grammar above); "" and "-" are the dimensionless unit 1. Throws UnitError.
Unit parse_unit(std::string_view text);

/// What a dimension is called in messages: "a pressure", "a length", "a density", ..., "a dimensionless number",
/// or "a quantity in kg m^-1 s^-3" for one without a name.
std::string describe(const Dimension& dimension);

/// A scalar split into its leading number and the unit text after it (trimmed; empty when there is none):
/// "210 GPa" -> {210, "210", "GPa"}, "5mm" -> {5, "5", "mm"}, "1.0e6" -> {1e6, "1.0e6", ""}. Nothing when the text
/// does not start with a finite number (a leading '+' is allowed).
struct NumberWithUnit {
  double number = 0;
  std::string_view number_text;
  std::string_view unit;
};
std::optional<NumberWithUnit> split_number(std::string_view text);

/// A system of units for a scene's bare numbers (`units: mm-ms-g`, docs/scene-reference.md "Units"): its units of
/// mass, length and time as powers of ten of kg, m and s, from which every other unit follows (mm-ms-g: force
/// g mm/ms^2 = 1 N, stress N/mm^2 = 1 MPa, density g/mm^3 = 10^6 kg/m^3). Temperatures and angles are SI's in every
/// system. The program converts to SI as it reads, and computes and writes in SI.
struct UnitSystem {
  std::string_view name;
  int mass = 0;              ///< decimal exponent of its mass unit in kg (g: -3, tonne: 3)
  int length = 0;            ///< of its length unit in m (mm: -3)
  int time = 0;              ///< of its time unit in s (ms: -3)
  std::string_view derived;  ///< its force, stress, energy and density units, for the reference

  /// The decimal exponent of the system's unit of `dimension` in SI units (mm-ms-g: a pressure 6, 1 MPa = 10^6 Pa).
  int exponent(const Dimension& dimension) const;
  bool si() const { return mass == 0 && length == 0 && time == 0; }
  /// Its length unit in m (mm: 1e-3).
  double length_unit() const;
};

/// The systems a scene may name, SI (`m-s-kg`) first.
const std::vector<UnitSystem>& unit_systems();
/// The system named `name`, or nullptr.
const UnitSystem* find_unit_system(std::string_view name);

/// The value converted to the unit `key_unit` of a key (a unit as key specs write it: "Pa", "kg/m^3", "W/(m^2 K)",
/// "degrees", "-" or "" for none): the number itself when no unit is written. A key in degrees takes degrees:
/// `1.5708 rad` is 90. Throws UnitError when the unit is not one or has another dimension: "expected a length (m),
/// got a pressure (GPa)".
double to_key_unit(const NumberWithUnit& value, std::string_view key_unit);
/// The same, with a bare number in `system`'s unit of the key's dimension (correctly rounded: the powers of ten
/// move in the number's text).
double to_key_unit(const NumberWithUnit& value, std::string_view key_unit, const UnitSystem& system);

}  // namespace mpm::units
