#include "mpm/core/state_archive.hpp"

#include <fmt/format.h>

#include <numeric>

namespace mpm {

std::uint64_t ArchivedArray::count() const {
  return std::accumulate(shape.begin(), shape.end(), std::uint64_t{1}, std::multiplies<>());
}

void StateArchive::put(const std::string& name, ArchivedArray array) {
  if (array.count() * scalar_size(array.type) != array.bytes.size())
    throw std::invalid_argument(fmt::format("state archive entry '{}': {} bytes for {} values of {}", name,
                                            array.bytes.size(), array.count(), scalar_type_name(array.type)));
  entries_.insert_or_assign(name, std::move(array));
}

void StateArchive::put_text(const std::string& name, std::string_view text) {
  ArchivedArray a;
  a.type = ScalarType::uint8;
  a.shape = {text.size()};
  a.text = true;
  a.bytes.resize(text.size());
  if (!text.empty()) std::memcpy(a.bytes.data(), text.data(), text.size());
  put(name, std::move(a));
}

void StateArchive::put_number(const std::string& name, double value) {
  ArchivedArray a;
  a.type = ScalarType::float64;
  a.bytes.resize(sizeof value);
  std::memcpy(a.bytes.data(), &value, sizeof value);
  put(name, std::move(a));
}

void StateArchive::put_integer(const std::string& name, std::int64_t value) {
  ArchivedArray a;
  a.type = ScalarType::int64;
  a.bytes.resize(sizeof value);
  std::memcpy(a.bytes.data(), &value, sizeof value);
  put(name, std::move(a));
}

const ArchivedArray& StateArchive::at(std::string_view name) const {
  const auto it = entries_.find(name);
  if (it == entries_.end()) throw ArchiveError(fmt::format("no entry '{}'", name));
  return it->second;
}

std::string StateArchive::text(std::string_view name) const {
  const ArchivedArray& a = at(name);
  if (a.type != ScalarType::uint8) wrong_type(name, ScalarType::uint8);
  std::string s(a.bytes.size(), '\0');
  if (!s.empty()) std::memcpy(s.data(), a.bytes.data(), s.size());
  return s;
}

double StateArchive::number(std::string_view name) const {
  const auto v = values<double>(name);
  if (v.size() != 1) throw ArchiveError(fmt::format("entry '{}' holds {} values, not one", name, v.size()));
  return v[0];
}

std::int64_t StateArchive::integer(std::string_view name) const {
  const auto v = values<std::int64_t>(name);
  if (v.size() != 1) throw ArchiveError(fmt::format("entry '{}' holds {} values, not one", name, v.size()));
  return v[0];
}

std::vector<std::string> StateArchive::children(std::string_view prefix) const {
  std::vector<std::string> out;
  for (auto it = entries_.lower_bound(prefix); it != entries_.end() && it->first.starts_with(prefix); ++it) {
    const std::string_view rest = std::string_view(it->first).substr(prefix.size());
    const std::string child(rest.substr(0, rest.find('/')));
    if (out.empty() || out.back() != child) out.push_back(child);
  }
  return out;
}

std::uint64_t StateArchive::bytes() const {
  std::uint64_t b = 0;
  for (const auto& [name, a] : entries_) b += a.bytes.size();
  return b;
}

void StateArchive::wrong_type(std::string_view name, ScalarType expected) const {
  throw ArchiveError(fmt::format("entry '{}' holds {} values, not {}", name, scalar_type_name(at(name).type),
                                 scalar_type_name(expected)));
}

}  // namespace mpm
