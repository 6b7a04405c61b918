#pragma once
/// \file state_archive.hpp
/// The state of a run as named arrays, in memory and independent of any file format: what the simulation,
/// its modules and the output writer save for a checkpoint and read back on a restart (the HDF5 file is
/// written and read by checkpoint/, which maps one entry to one dataset), and what the stability guard's
/// snapshots keep of the modules. Names are paths ("bodies/disk/stress", "modules/contact/plane_point").

#include <cstdint>
#include <cstring>
#include <map>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "mpm/particles/field_layout.hpp"

namespace mpm {

/// One named array: its element type, its shape (empty for a single value) and its values as bytes in the
/// machine's byte order. `text` marks bytes that are a UTF-8 string (type uint8, shape {length}).
struct ArchivedArray {
  ScalarType type = ScalarType::float64;
  std::vector<std::uint64_t> shape;
  std::vector<std::byte> bytes;
  bool text = false;
  /// Number of values: the product of the shape (1 for a single value).
  std::uint64_t count() const;
};

/// An archive lacks an entry that a restore needs, or holds it with another type or size.
class ArchiveError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class StateArchive {
 public:
  /// Adds (or replaces) an entry. Throws std::invalid_argument if the bytes do not match type and shape.
  void put(const std::string& name, ArchivedArray array);
  void put_text(const std::string& name, std::string_view text);
  void put_number(const std::string& name, double value);
  void put_integer(const std::string& name, std::int64_t value);
  /// `values.size() / components` rows of `components` values (shape {rows, components}, or {rows} when
  /// components is 1).
  template <class T>
  void put_values(const std::string& name, std::span<const T> values, std::size_t components = 1) {
    ArchivedArray a;
    a.type = scalar_type_of<T>();
    a.shape = {static_cast<std::uint64_t>(values.size() / components)};
    if (components != 1) a.shape.push_back(components);
    a.bytes.resize(values.size_bytes());
    if (!values.empty()) std::memcpy(a.bytes.data(), values.data(), values.size_bytes());
    put(name, std::move(a));
  }

  bool contains(std::string_view name) const { return entries_.find(name) != entries_.end(); }
  /// The entry; throws ArchiveError "no entry 'name'".
  const ArchivedArray& at(std::string_view name) const;
  std::string text(std::string_view name) const;
  double number(std::string_view name) const;
  std::int64_t integer(std::string_view name) const;
  /// The values of an entry of scalar type T (ArchiveError for another type).
  template <class T>
  std::vector<T> values(std::string_view name) const {
    const ArchivedArray& a = at(name);
    if (a.type != scalar_type_of<T>()) wrong_type(name, scalar_type_of<T>());
    std::vector<T> out(a.bytes.size() / sizeof(T));
    if (!out.empty()) std::memcpy(out.data(), a.bytes.data(), out.size() * sizeof(T));
    return out;
  }
  /// The names of the direct children of the group `prefix` (ending in '/'), in name order: "bodies/" gives
  /// the body names.
  std::vector<std::string> children(std::string_view prefix) const;
  const std::map<std::string, ArchivedArray, std::less<>>& entries() const { return entries_; }
  /// Total bytes of all values.
  std::uint64_t bytes() const;

 private:
  [[noreturn]] void wrong_type(std::string_view name, ScalarType expected) const;
  std::map<std::string, ArchivedArray, std::less<>> entries_;
};

}  // namespace mpm
