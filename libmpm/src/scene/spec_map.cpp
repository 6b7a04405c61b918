#include "mpm/scene/spec_map.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace mpm::io {
namespace {

std::vector<std::string> allowed_keys(const std::vector<KeySpec>& keys, const std::vector<std::string>& extra) {
  std::vector<std::string> names = key_names(keys);
  names.insert(names.end(), extra.begin(), extra.end());
  return names;
}

/// The default of `spec` of type T (a programming error when the spec has none of that type).
template <class T>
const T& spec_default(const KeySpec& spec) {
  if (const auto* value = std::get_if<T>(&spec.default_value)) return *value;
  throw std::logic_error("scene key '" + spec.name + "' is read with a default it does not declare");
}

}  // namespace

int read_integer(const YamlReader& reader, const YamlValue& value, const Range& range) {
  const bool small = std::isfinite(range.lower) && std::isfinite(range.upper) && range.upper - range.lower <= 4;
  int minimum = std::numeric_limits<int>::min();
  if (!small && std::isfinite(range.lower))
    minimum = static_cast<int>(range.lower_inclusive ? std::ceil(range.lower) : std::floor(range.lower) + 1);
  const int x = reader.integer(value, minimum);
  if (!range.contains(x)) {
    if (small) {
      KeySpec listed{.type = KeyType::integer, .range = range};
      reader.fail(value, fmt::format("must be {}, got {}", key_allowed_text(listed), x));
    }
    reader.fail(value, fmt::format("out of range: must be {}, got {}", range.describe(), x));
  }
  return x;
}

SpecMap::SpecMap(const YamlReader& reader, const YamlValue& value, const std::vector<KeySpec>& keys,
                 const std::vector<std::string>& extra, std::string_view noun, std::string_view context)
    : reader_(reader), keys_(keys), map_(reader, value) {
  allow(extra, noun, context);
}

SpecMap::SpecMap(const YamlReader& reader, const YamlValue& value, const std::vector<KeySpec>& keys, AllowLater)
    : reader_(reader), keys_(keys), map_(reader, value) {}

void SpecMap::allow(const std::vector<std::string>& extra, std::string_view noun, std::string_view context) const {
  map_.allow(allowed_keys(keys_, extra), noun, context);
}

const KeySpec& SpecMap::spec(std::string_view key) const {
  if (const KeySpec* spec = find_key(keys_, key)) return *spec;
  throw std::logic_error(fmt::format("scene key '{}' is read without a spec", key));
}

std::optional<YamlValue> SpecMap::find(std::string_view key) const {
  spec(key);
  return map_.find(key);
}

YamlValue SpecMap::required(std::string_view key) const {
  spec(key);
  return map_.required(key);
}

double SpecMap::number(std::string_view key) const {
  const KeySpec& s = spec(key);
  if (const auto value = s.required ? std::optional(map_.required(key)) : map_.find(key))
    return reader_.number(*value, s.range, s.unit);
  return spec_default<double>(s);
}

std::optional<double> SpecMap::optional_number(std::string_view key) const {
  const KeySpec& s = spec(key);
  if (const auto value = map_.find(key)) return reader_.number(*value, s.range, s.unit);
  return std::nullopt;
}

int SpecMap::integer(std::string_view key) const {
  const KeySpec& s = spec(key);
  if (const auto value = s.required ? std::optional(map_.required(key)) : map_.find(key))
    return read_integer(reader_, *value, s.range);
  return static_cast<int>(spec_default<double>(s));
}

bool SpecMap::boolean(std::string_view key) const {
  const KeySpec& s = spec(key);
  if (const auto value = map_.find(key)) return reader_.boolean(*value);
  return spec_default<bool>(s);
}

std::string SpecMap::name(std::string_view key) const {
  const KeySpec& s = spec(key);
  if (const auto value = s.required ? std::optional(map_.required(key)) : map_.find(key)) return reader_.name(*value);
  return spec_default<std::string>(s);
}

std::string SpecMap::choice(std::string_view key) const {
  const KeySpec& s = spec(key);
  if (const auto value = s.required ? std::optional(map_.required(key)) : map_.find(key))
    return reader_.choice(*value, s.choices);
  return spec_default<std::string>(s);
}

std::string SpecMap::expression(std::string_view key, const std::vector<std::string>& variables) const {
  const KeySpec& s = spec(key);
  if (const auto value = s.required ? std::optional(map_.required(key)) : map_.find(key))
    return reader_.expression(*value, variables, s.unit);
  return spec_default<std::string>(s);
}

}  // namespace mpm::io
