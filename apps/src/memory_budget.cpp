#include "mpm/app/memory_budget.hpp"

#include <fmt/format.h>
#include <sys/resource.h>

#include <charconv>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>

namespace mpm {
namespace {

std::string read_file(const char* path) {
  std::ifstream in(path);
  if (!in) return {};
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::optional<double> leading_number(std::string_view text) {
  while (!text.empty() && (text.front() == ' ' || text.front() == '\t')) text.remove_prefix(1);
  unsigned long long value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end == text.data()) return std::nullopt;
  return static_cast<double>(value);
}

/// The path of this process's control group in the hierarchy that holds `controller` ("" for v2's unified one),
/// from /proc/self/cgroup ("0::/path" for v2, "N:memory:/path" for v1); "" for the root or when unknown.
std::string cgroup_path(std::string_view controller) {
  std::istringstream lines(read_file("/proc/self/cgroup"));
  for (std::string line; std::getline(lines, line);) {
    const auto first = line.find(':'), second = line.find(':', first + 1);
    if (first == std::string::npos || second == std::string::npos) continue;
    const std::string_view controllers = std::string_view(line).substr(first + 1, second - first - 1);
    if (controllers == controller || (!controller.empty() && controllers.find(controller) != std::string::npos))
      return line.substr(second + 1);
  }
  return {};
}

/// The limit of a control group less its usage: the group's own files, or those of the hierarchy's root (in a
/// container the group's own are usually mounted there). cgroup v2 first (memory.max), then v1
/// (memory.limit_in_bytes, an enormous number when unlimited).
std::optional<double> cgroup_available() {
  const std::string v2 = "/sys/fs/cgroup", v1 = "/sys/fs/cgroup/memory";
  for (const std::string& dir : {v2 + cgroup_path(""), v2}) {
    const auto limit = cgroup_limit_bytes(read_file((dir + "/memory.max").c_str()));
    if (!limit) continue;
    const auto used = leading_number(read_file((dir + "/memory.current").c_str()));
    return std::max(0.0, *limit - used.value_or(0));
  }
  for (const std::string& dir : {v1 + cgroup_path("memory"), v1}) {
    const auto limit = cgroup_limit_bytes(read_file((dir + "/memory.limit_in_bytes").c_str()));
    if (!limit || *limit > 1e18) continue;
    const auto used = leading_number(read_file((dir + "/memory.usage_in_bytes").c_str()));
    return std::max(0.0, *limit - used.value_or(0));
  }
  return std::nullopt;
}

/// `ulimit -v` less the process's current virtual size (VmSize of /proc/self/status).
std::optional<double> address_space_available() {
  rlimit limit{};
  if (getrlimit(RLIMIT_AS, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY) return std::nullopt;
  const auto mapped = meminfo_bytes(read_file("/proc/self/status"), "VmSize");
  return std::max(0.0, static_cast<double>(limit.rlim_cur) - mapped.value_or(0));
}

}  // namespace

std::optional<double> meminfo_bytes(std::string_view meminfo, std::string_view key) {
  for (std::size_t begin = 0; begin < meminfo.size();) {
    std::size_t end = meminfo.find('\n', begin);
    if (end == std::string_view::npos) end = meminfo.size();
    const std::string_view line = meminfo.substr(begin, end - begin);
    if (line.size() > key.size() && line.substr(0, key.size()) == key && line[key.size()] == ':')
      if (const auto kb = leading_number(line.substr(key.size() + 1))) return *kb * 1024;
    begin = end + 1;
  }
  return std::nullopt;
}

std::optional<double> cgroup_limit_bytes(std::string_view text) {
  if (text.rfind("max", 0) == 0) return std::nullopt;
  return leading_number(text);
}

MemoryBudget available_memory() {
  MemoryBudget budget{std::numeric_limits<double>::infinity(), "no memory limit found"};
  auto consider = [&](std::optional<double> bytes, const char* source) {
    if (bytes && *bytes < budget.bytes) budget = {*bytes, source};
  };
  consider(meminfo_bytes(read_file("/proc/meminfo"), "MemAvailable"), "MemAvailable of /proc/meminfo");
  consider(cgroup_available(), "the control group's memory limit less its usage");
  consider(address_space_available(), "ulimit -v less what the process maps");
  return budget;
}

std::string format_bytes(double bytes) {
  if (!std::isfinite(bytes)) return "unlimited";
  const char* units[] = {"B", "kB", "MB", "GB", "TB", "PB", "EB"};
  int u = 0;
  while (bytes >= 1000 && u < 6) {
    bytes /= 1000;
    ++u;
  }
  return u == 0 ? fmt::format("{:.0f} B", bytes) : fmt::format("{:.3g} {}", bytes, units[u]);
}

}  // namespace mpm
