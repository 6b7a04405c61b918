#pragma once
/// \file enum_names.hpp
/// The one conversion between an option's enum and its scene name. An enum `E` declares its names once, as
/// `template <> struct EnumNames<E> { static constexpr std::array<std::pair<E, std::string_view>, N> table{...}; }`;
/// the reader's choice<E>() (yaml_reader.hpp), its "valid values: ..." message and the output derive from it.

#include <iterator>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace mpm {

/// Specialised per option enum with the `table` of {value, name} pairs, in the order messages list them.
template <class E>
struct EnumNames;

/// An enum with a name table.
template <class E>
concept NamedEnum = requires {
  EnumNames<E>::table;
};

/// The scene name of `value`.
template <NamedEnum E>
constexpr std::string_view enum_name(E value) {
  for (const auto& [e, name] : EnumNames<E>::table)
    if (e == value) return name;
  return {};
}

/// The value named `name`, or nothing.
template <NamedEnum E>
constexpr std::optional<E> enum_from_name(std::string_view name) {
  for (const auto& [e, n] : EnumNames<E>::table)
    if (n == name) return e;
  return std::nullopt;
}

/// Every name, in table order.
template <NamedEnum E>
std::vector<std::string> enum_names() {
  std::vector<std::string> names;
  names.reserve(std::size(EnumNames<E>::table));
  for (const auto& entry : EnumNames<E>::table) names.emplace_back(entry.second);
  return names;
}

}  // namespace mpm
