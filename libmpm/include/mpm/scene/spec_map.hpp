#pragma once
/// \file spec_map.hpp
/// A scene section read through the specs of its keys (key_spec.hpp): the allowed keys, ranges, units, choices
/// and defaults come from the specs, the checks and messages from the one YAML reader (yaml_reader.hpp).

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "mpm/scene/key_spec.hpp"
#include "mpm/scene/yaml_reader.hpp"

namespace mpm::io {

/// A YAML map read through the specs of its keys: the constructor fails on an unknown key (the valid ones are
/// the specs' names) and every accessor takes the value's range, unit, choices and default from its spec, so
/// that messages read as YamlReader's (`FILE:LINE:COLUMN: KEY: message`). Asking for a key without a spec, or
/// for a default the spec does not have, is a programming error (std::logic_error).
class SpecMap {
 public:
  /// `extra` keys are allowed besides the specs' (a material's model parameters); `noun` and `context` word
  /// the unknown-key message as YamlMap::allow does.
  SpecMap(const YamlReader& reader, const YamlValue& value, const std::vector<KeySpec>& keys,
          const std::vector<std::string>& extra = {}, std::string_view noun = "key", std::string_view context = "");
  /// Tag of the constructor that leaves the check of the keys to allow(): for a map whose allowed keys depend on
  /// one of its values (a material's `model`, a history's `type`).
  struct AllowLater {};
  SpecMap(const YamlReader& reader, const YamlValue& value, const std::vector<KeySpec>& keys, AllowLater);
  /// Fails on the first key that is neither a spec's nor in `extra` (YamlMap::allow).
  void allow(const std::vector<std::string>& extra = {}, std::string_view noun = "key",
             std::string_view context = "") const;

  /// The value of `key`, if given.
  std::optional<YamlValue> find(std::string_view key) const;
  /// The value of `key`; fails at this map when it is absent ("missing required key 'k'").
  YamlValue required(std::string_view key) const;

  /// The number given, in the spec's range (the message gives the spec's unit), or the spec's default.
  double number(std::string_view key) const;
  /// The number given, or nothing (for a key whose absence means something else than a value).
  std::optional<double> optional_number(std::string_view key) const;
  /// The whole number given, in the spec's range, or the spec's default. A range of at most five values is
  /// listed in the message ("must be 1, 2 or 3, got 4").
  int integer(std::string_view key) const;
  /// true/false given, or the spec's default.
  bool boolean(std::string_view key) const;
  /// The non-empty text given, or the spec's default.
  std::string name(std::string_view key) const;
  /// One of the spec's choices, or the spec's default.
  std::string choice(std::string_view key) const;
  /// The expression given (a number or muparser text of `variables`), or the spec's default.
  std::string expression(std::string_view key, const std::vector<std::string>& variables) const;

  const YamlMap& map() const { return map_; }
  const YamlReader& reader() const { return reader_; }
  /// The spec of `key` (std::logic_error when there is none).
  const KeySpec& spec(std::string_view key) const;

 private:
  const YamlReader& reader_;
  const std::vector<KeySpec>& keys_;
  YamlMap map_;
};

/// Reads an integer in `range` at `value` (SpecMap::integer's check, for values inside lists).
int read_integer(const YamlReader& reader, const YamlValue& value, const Range& range);

}  // namespace mpm::io
