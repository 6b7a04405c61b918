#pragma once
/// \file yaml_reader.hpp
/// The one checked reader of scene YAML, used by every section: the core's (scene_loader.cpp) and each
/// module's (SceneExtension::parse). Every accessor checks the YAML type and the value and otherwise throws a
/// SceneError `FILE:LINE:COLUMN: KEY: message` located at the value and naming its dotted key path; so every
/// section reports unknown, duplicate and missing keys, wrong types ("expected a number, got 'soft'") and
/// out-of-range values the same way.

#include <yaml-cpp/yaml.h>

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "mpm/core/enum_names.hpp"
#include "mpm/core/range.hpp"
#include "mpm/core/units.hpp"
#include "mpm/scene/scene.hpp"

namespace mpm::io {

/// A YAML node together with its dotted key path and the place to report it at.
struct YamlValue {
  YAML::Node node;
  std::string path;  ///< e.g. "bodies[1].shape.radius"
  YAML::Mark mark;   ///< of the node; of its key when the node is empty (yaml-cpp has no mark for it)
};

/// The mark to report `node` at. yaml-cpp places an empty value (`key:`) at the next token, which can be
/// lines away, so empty values are reported at `fallback` (their key).
YAML::Mark mark_of(const YAML::Node& node, const YAML::Mark& fallback);

/// What a node is, for "expected X, got Y" messages: 'text', a list, a map or nothing.
std::string describe(const YAML::Node& node);

/// A finite number written as `text` (leading '+' allowed), without a unit, or nothing.
std::optional<double> parse_number(std::string_view text);

class YamlMap;

/// Typed access to the values of one scene file.
class YamlReader {
 public:
  /// `file` names the scene in messages.
  explicit YamlReader(std::string file) : file_(std::move(file)) {}

  const std::string& file() const { return file_; }
  /// The unit system of the scene's bare numbers (`units:`; SI unless set): number(), vector() and expression()
  /// read a bare number in the system's unit of the key's dimension and return it in the key's SI unit.
  void set_unit_system(const units::UnitSystem& system) { system_ = &system; }
  const units::UnitSystem& unit_system() const { return *system_; }
  /// The 1-based place of `mark` in the file (line 0 when unknown).
  SourceLocation location(const YAML::Mark& mark) const;

  [[noreturn]] void fail(const YAML::Mark& mark, const std::string& key, const std::string& message) const;
  [[noreturn]] void fail(const YamlValue& value, const std::string& message) const;

  /// A finite number, without a unit ("expected a plain number (this key has no unit), got '5 mm'").
  double number(const YamlValue& value) const;
  /// A finite number in `range`, in the key's SI unit `unit` ("Pa", "kg/m^3", "-" or "" for a ratio): a bare number
  /// is taken as given; a number with a unit (`210 GPa`, `7.85 g/cm^3`; core/units.hpp) is converted to `unit`, and
  /// refused when its dimension is another ("expected a length (m), got a pressure (GPa)") or the unit is unknown.
  double number(const YamlValue& value, const Range& range, std::string_view unit) const;
  /// An integer >= minimum.
  int integer(const YamlValue& value, int minimum) const;
  /// A scalar, as text.
  std::string string(const YamlValue& value) const;
  /// A non-empty scalar, as text.
  std::string name(const YamlValue& value) const;
  /// One of `allowed`: "invalid value 'x'; valid values: a, b".
  std::string choice(const YamlValue& value, const std::vector<std::string>& allowed) const;
  /// One of the names of the enum E (enum_names.hpp).
  template <NamedEnum E>
  E choice(const YamlValue& value) const {
    return *enum_from_name<E>(choice(value, enum_names<E>()));
  }
  /// true/false (also yes/no, on/off as YAML allows).
  bool boolean(const YamlValue& value) const;
  /// The entries of a list; with `length`, exactly that many. `what` names the entries in messages, `each` says
  /// what an entry stands for when the length is wrong ("expected a list of 2 numbers (one per axis), got 3
  /// entries"; nothing in parentheses when empty).
  std::vector<YamlValue> list(const YamlValue& value, std::optional<std::size_t> length, std::string_view what,
                              std::string_view each = "one per axis") const;
  /// A number or a list of `dimension` numbers: the value for each axis.
  std::vector<YamlValue> per_axis(const YamlValue& value, int dimension, std::string_view what) const;
  /// A list of `dimension` numbers in `range`, padded with zeros to 3.
  std::array<double, 3> vector(const YamlValue& value, int dimension, const Range& range, std::string_view unit) const;
  /// A number or a muparser expression of `variables`, as expression text (numbers in shortest form). A number with
  /// a unit (`-800 m/s`) is converted to the key's unit `unit` as number() does; an expression is in that unit. In
  /// a unit system other than SI the expression is in the system's units, of the variables x, y, z (lengths) and t
  /// (a time) in them too: the text returned evaluates it so, in SI.
  std::string expression(const YamlValue& value, const std::vector<std::string>& variables,
                         std::string_view unit) const;
  /// `value` as a map (fails unless it is one, with plain and distinct keys).
  YamlMap map(const YamlValue& value) const;

 private:
  std::string file_;
  const units::UnitSystem* system_ = &units::unit_systems().front();
};

/// A YAML map being read: finds keys, rejects unknown and duplicate ones, reports missing ones.
class YamlMap {
 public:
  struct Entry {
    std::string key;
    YAML::Mark key_mark;
    YamlValue value;
  };

  /// Fails unless `value` is a map with plain, distinct keys ("duplicate key (first given at line N)").
  YamlMap(const YamlReader& reader, YamlValue value);

  /// Fails on the first key not in `allowed`: "unknown <noun> 'k'<context>; valid <noun>s: ...".
  void allow(const std::vector<std::string>& allowed, std::string_view noun = "key",
             std::string_view context = "") const;
  /// The value of `key`, if given.
  std::optional<YamlValue> find(std::string_view key) const;
  /// The value of `key`; if it is absent, fails at this map with "missing required <noun> '<key>'<detail>".
  YamlValue required(std::string_view key, std::string_view noun = "key", std::string_view detail = "") const;

  /// The entries in the order of the file.
  const std::vector<Entry>& entries() const { return entries_; }
  /// The map itself.
  const YamlValue& self() const { return self_; }
  /// The dotted path of `key` in this map.
  std::string path_of(std::string_view key) const;

 private:
  const Entry* find_entry(std::string_view key) const;

  const YamlReader& reader_;
  YamlValue self_;
  std::vector<Entry> entries_;
};

}  // namespace mpm::io
