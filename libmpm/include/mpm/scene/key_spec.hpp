#pragma once
/// \file key_spec.hpp
/// The one declaration of a scene key: its name, type, unit, range, default (or what absence means),
/// description and whether a fork may change it. A section's keys are a list of KeySpecs; the section's
/// reader takes its allowed keys, ranges, units and defaults from them (SpecMap, spec_map.hpp), the scene reference
/// prints its table from them (scene_reference.hpp, `mpm reference --section NAME`), and `mpm run --restart` takes the
/// keys a fork may change from them (run_control_patterns). So a key is written once, as materials' parameters are
/// (ParameterSpec, material_registry.hpp).

#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "mpm/core/range.hpp"

namespace mpm::io {

/// What a key's value is. `list` and `map` may declare the keys of their entries (KeySpec::keys).
enum class KeyType {
  number,      ///< a finite number in KeySpec::range
  integer,     ///< a whole number in KeySpec::range
  boolean,     ///< true or false
  name,        ///< a non-empty text
  choice,      ///< one of KeySpec::choices
  expression,  ///< a number or a muparser expression
  list,        ///< a list; with keys: a list of maps with those keys
  map,         ///< a map; with keys: a section with those keys
  named_map,   ///< a map from names the scene chooses (materials) to entries with KeySpec::keys
};

/// A key's value when the scene omits it: none, a number, a boolean, a text or a list of texts.
using KeyDefault = std::variant<std::monostate, double, bool, std::string, std::vector<std::string>>;

/// One key of a scene section.
struct KeySpec {
  std::string name{};                  ///< YAML key, snake_case
  KeyType type = KeyType::number;      ///< what its value is
  std::string unit{};                  ///< SI unit; "" when it has none, "-" when dimensionless
  Range range = Range::any();          ///< number, integer: admissible values
  std::vector<std::string> choices{};  ///< choice: the valid values, in the order messages list them
  KeyDefault default_value{};          ///< the value the reader gives an absent key
  bool required = false;               ///< the reader fails when it is absent
  /// What absence means, as the reference's Default column words it ("none", "each material's
  /// room_temperature", "2 on every axis"); empty: the default value, or "none".
  std::string absent{};
  std::string description{};  ///< meaning, and what the reference says about the allowed values beyond the range
  /// The reference's Type column when the type's own word says too little ("list of `dimension` numbers").
  std::string type_text{};
  /// The reference's Allowed column when the range or the choices do not say it ("a key of `materials`").
  std::string allowed_text{};
  /// A fork (`mpm run --restart` with a changed scene) may change this key; for a map or a list, everything in it.
  bool run_control = false;
  /// Why a fork may not change this key, as the refusal words it ("the grid is the checkpoint's"); for a map or a
  /// list, the reason of every key in it that declares none of its own and is not run_control. Empty: the
  /// enclosing section's reason, or the general one (fork_rule_for).
  std::string fork_refusal{};
  /// map, list: the keys of the section or of each entry (empty: not declared here).
  std::vector<KeySpec> keys{};

  /// The default as a number (throws std::logic_error when it is not one): for struct defaults and tests.
  double default_number() const;
  /// The default as a text (throws std::logic_error when it is not one).
  const std::string& default_text() const;
};

/// The names of `keys`, in order: the allowed keys of their section.
std::vector<std::string> key_names(const std::vector<KeySpec>& keys);
/// The key named `name`, or nullptr.
const KeySpec* find_key(const std::vector<KeySpec>& keys, std::string_view name);
/// The key at the dotted path `path` below `keys` ("checkpoint.keep"), or nullptr.
const KeySpec* find_key_path(const std::vector<KeySpec>& keys, std::string_view path);

/// The reference's cells of a key: its type, its default (or what absence means, or "required") and its
/// allowed values.
std::string key_type_text(const KeySpec& key);
std::string key_default_text(const KeySpec& key);
std::string key_allowed_text(const KeySpec& key);

/// The keys below `keys` (whose section is at `prefix`, "" for the top) that a fork may change, as the
/// dotted patterns of `mpm run --restart`, with `*` for a list index or an entry's name
/// ("contact.planes.*.velocity").
std::vector<std::string> run_control_patterns(const std::vector<KeySpec>& keys, const std::string& prefix = "");

/// What a fork may do with the keys a pattern matches (a dotted path with `*` for a list index or an entry's
/// name; a pattern matches its key and every key inside it).
struct ForkRule {
  std::string pattern{};
  bool allowed = false;  ///< KeySpec::run_control
  std::string reason{};  ///< KeySpec::fork_refusal, when not allowed
};

/// The rules below `keys` (whose section is at `prefix`): one per key that is run_control or declares a
/// fork_refusal.
std::vector<ForkRule> fork_rules(const std::vector<KeySpec>& keys, const std::string& prefix = "");

/// The rule of `rules` that decides `key` (a dotted path, "[i]" for list indices): the matching pattern with
/// the most parts, a refusal before an allowance of as many parts; nullptr when none matches (a fork may not
/// change the key, for no declared reason).
const ForkRule* fork_rule_for(const std::vector<ForkRule>& rules, const std::string& key);

}  // namespace mpm::io
