#pragma once
/// \file core/kind_table.hpp
/// The table behind every registry of kinds a scene names by a string (schemes, material models, module sections,
/// face conditions, body shapes, history kinds): the core's kinds first, then whatever modules register, each found
/// by its name. Registering a name again replaces its entry. Entries never move (a deque), so the pointers `find` hands
/// out stay valid while modules register more; the mutex makes registration from several threads safe.

#include <deque>
#include <mutex>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace mpm {

/// `Kind` is found by its member `Name` (a std::string: `&Kind::name` unless the kind calls it otherwise).
template <class Kind, auto Name = &Kind::name>
class KindTable {
 public:
  explicit KindTable(std::deque<Kind> core = {}) : kinds_(std::move(core)) {}

  /// Adds `kind`, or replaces the entry of the same name in place.
  void add(Kind kind) {
    std::lock_guard lock(mutex_);
    for (auto& k : kinds_)
      if (k.*Name == kind.*Name) {
        k = std::move(kind);
        return;
      }
    kinds_.push_back(std::move(kind));
  }
  /// The entry named `name`, or nullptr.
  const Kind* find(std::string_view name) const {
    std::lock_guard lock(mutex_);
    for (const auto& k : kinds_)
      if (k.*Name == name) return &k;
    return nullptr;
  }
  /// The names, in registration order (the core's first).
  std::vector<std::string> names() const {
    std::lock_guard lock(mutex_);
    std::vector<std::string> names;
    names.reserve(kinds_.size());
    for (const auto& k : kinds_) names.push_back(k.*Name);
    return names;
  }

 private:
  mutable std::mutex mutex_;
  std::deque<Kind> kinds_;
};

}  // namespace mpm
