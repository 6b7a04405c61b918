#include "mpm/scene/key_spec.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cmath>
#include <stdexcept>

namespace mpm::io {
namespace {

/// `text` as code in the reference.
std::string code(const std::string& text) { return "`" + text + "`"; }

/// The values of an integer range of at most five ("1, 2 or 3"), or nothing.
std::optional<std::vector<long long>> few_integers(const Range& range) {
  if (!std::isfinite(range.lower) || !std::isfinite(range.upper)) return std::nullopt;
  const auto first = static_cast<long long>(std::ceil(range.lower));
  const auto last = static_cast<long long>(std::floor(range.upper));
  if (last - first > 4) return std::nullopt;
  std::vector<long long> values;
  for (long long v = first; v <= last; ++v)
    if (range.contains(static_cast<double>(v))) values.push_back(v);
  return values;
}

/// `path` in parts: "a.b[2].c" is a, b, 2, c.
std::vector<std::string> path_parts(const std::string& path) {
  std::vector<std::string> parts;
  std::string part;
  for (const char c : path) {
    if (c == '.' || c == '[' || c == ']') {
      if (!part.empty()) parts.push_back(part);
      part.clear();
    } else {
      part += c;
    }
  }
  if (!part.empty()) parts.push_back(part);
  return parts;
}

}  // namespace

double KeySpec::default_number() const {
  if (const auto* x = std::get_if<double>(&default_value)) return *x;
  throw std::logic_error("scene key '" + name + "' has no default number");
}

const std::string& KeySpec::default_text() const {
  if (const auto* text = std::get_if<std::string>(&default_value)) return *text;
  throw std::logic_error("scene key '" + name + "' has no default text");
}

std::vector<std::string> key_names(const std::vector<KeySpec>& keys) {
  std::vector<std::string> names;
  names.reserve(keys.size());
  for (const auto& key : keys) names.push_back(key.name);
  return names;
}

const KeySpec* find_key(const std::vector<KeySpec>& keys, std::string_view name) {
  for (const auto& key : keys)
    if (key.name == name) return &key;
  return nullptr;
}

const KeySpec* find_key_path(const std::vector<KeySpec>& keys, std::string_view path) {
  const std::size_t dot = path.find('.');
  const KeySpec* key = find_key(keys, path.substr(0, dot));
  if (!key || dot == std::string_view::npos) return key;
  return find_key_path(key->keys, path.substr(dot + 1));
}

std::string key_type_text(const KeySpec& key) {
  if (!key.type_text.empty()) return key.type_text;
  switch (key.type) {
    case KeyType::number:
      return "number";
    case KeyType::integer:
      return "integer";
    case KeyType::boolean:
      return "boolean";
    case KeyType::name:
    case KeyType::choice:
      return "string";
    case KeyType::expression:
      return "number or expression";
    case KeyType::list:
      return key.keys.empty() ? "list" : "list of maps";
    case KeyType::map:
      return "map";
    case KeyType::named_map:
      return "map of named entries";
  }
  return "";
}

std::string key_default_text(const KeySpec& key) {
  if (key.required) return "required";
  if (!key.absent.empty()) return key.absent;
  struct Text {
    const KeySpec& key;
    std::string operator()(std::monostate) const { return "none"; }
    std::string operator()(double x) const { return fmt::format("{}", x); }
    std::string operator()(bool b) const { return code(b ? "true" : "false"); }
    std::string operator()(const std::string& text) const { return code(text); }
    std::string operator()(const std::vector<std::string>& list) const {
      return code(fmt::format("[{}]", fmt::join(list, ", ")));
    }
  };
  return std::visit(Text{key}, key.default_value);
}

std::string key_allowed_text(const KeySpec& key) {
  if (!key.allowed_text.empty()) return key.allowed_text;
  switch (key.type) {
    case KeyType::number:
      return key.range.describe();
    case KeyType::integer:
      if (const auto values = few_integers(key.range); values && values->size() > 1)
        return fmt::format("{} or {}", fmt::join(values->begin(), values->end() - 1, ", "), values->back());
      return key.range.describe();
    case KeyType::boolean:
      return "`true`, `false`";
    case KeyType::choice: {
      std::vector<std::string> quoted;
      for (const auto& c : key.choices) quoted.push_back(code(c));
      return fmt::format("{}", fmt::join(quoted, ", "));
    }
    case KeyType::name:
      return "non-empty";
    case KeyType::expression:
    case KeyType::list:
    case KeyType::map:
    case KeyType::named_map:
      return "";
  }
  return "";
}

std::vector<std::string> run_control_patterns(const std::vector<KeySpec>& keys, const std::string& prefix) {
  std::vector<std::string> patterns;
  for (const auto& key : keys) {
    const std::string path = prefix.empty() ? key.name : prefix + "." + key.name;
    if (key.run_control) {
      patterns.push_back(path);
      continue;
    }
    const auto inner = run_control_patterns(key.keys, key.type == KeyType::map ? path : path + ".*");
    patterns.insert(patterns.end(), inner.begin(), inner.end());
  }
  return patterns;
}

std::vector<ForkRule> fork_rules(const std::vector<KeySpec>& keys, const std::string& prefix) {
  std::vector<ForkRule> rules;
  for (const auto& key : keys) {
    const std::string path = prefix.empty() ? key.name : prefix + "." + key.name;
    if (key.run_control) {
      rules.push_back({path, true, ""});
      continue;
    }
    if (!key.fork_refusal.empty()) rules.push_back({path, false, key.fork_refusal});
    const auto inner = fork_rules(key.keys, key.type == KeyType::map ? path : path + ".*");
    rules.insert(rules.end(), inner.begin(), inner.end());
  }
  return rules;
}

const ForkRule* fork_rule_for(const std::vector<ForkRule>& rules, const std::string& key) {
  const auto k = path_parts(key);
  const ForkRule* best = nullptr;
  std::size_t best_parts = 0;
  for (const auto& rule : rules) {
    const auto p = path_parts(rule.pattern);
    if (p.size() > k.size()) continue;
    bool match = true;
    for (std::size_t i = 0; i < p.size() && match; ++i) match = p[i] == "*" || p[i] == k[i];
    if (!match) continue;
    if (!best || p.size() > best_parts || (p.size() == best_parts && best->allowed && !rule.allowed)) {
      best = &rule;
      best_parts = p.size();
    }
  }
  return best;
}

}  // namespace mpm::io
