#pragma once
/// \file memory_budget.hpp
/// How much memory this process may still take: the least of the machine's available memory (MemAvailable of
/// /proc/meminfo), the control group's limit less its usage (cgroup v2 memory.max, v1 memory.limit_in_bytes) and
/// the address-space limit (`ulimit -v`) less what the process already maps. A scene is checked against it before
/// anything is allocated (apps/src/memory_estimate.cpp), so that a scene too big for the machine is refused with
/// its estimate instead of ending in std::bad_alloc or the kernel's out-of-memory killer.

#include <optional>
#include <string>
#include <string_view>

namespace mpm {

struct MemoryBudget {
  double bytes = 0;    ///< what may still be allocated
  std::string source;  ///< which limit gives it, for messages ("MemAvailable of /proc/meminfo", ...)
};

/// The least of the limits above that this machine has (Linux); without any, an unlimited budget.
MemoryBudget available_memory();

/// The value in bytes of `key` (e.g. "MemAvailable") in the text of /proc/meminfo (kB), if present.
std::optional<double> meminfo_bytes(std::string_view meminfo, std::string_view key);

/// A control group's memory limit file (memory.max: a number or "max"); nothing when unlimited or unreadable.
std::optional<double> cgroup_limit_bytes(std::string_view text);

/// Bytes for people: "1.23 GB", "456 MB", "789 kB", "12 B" (powers of 1000).
std::string format_bytes(double bytes);

}  // namespace mpm
