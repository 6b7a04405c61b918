// What the memory budget (memory_budget.hpp) reads from /proc/meminfo and the control group's files, and that the
// machine's budget is positive and at most its MemAvailable.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "mpm/app/memory_budget.hpp"

using namespace mpm;

TEST(MemoryBudget, ReadsMeminfoInKilobytes) {
  const std::string meminfo = "MemTotal:       24576000 kB\nMemFree:         1000 kB\nMemAvailable:   20000000 kB\n";
  EXPECT_EQ(meminfo_bytes(meminfo, "MemAvailable"), 20000000.0 * 1024);
  EXPECT_EQ(meminfo_bytes(meminfo, "MemFree"), 1000.0 * 1024);
  EXPECT_FALSE(meminfo_bytes(meminfo, "Mem"));  // a prefix of a key is not the key
  EXPECT_FALSE(meminfo_bytes(meminfo, "SwapTotal"));
}

TEST(MemoryBudget, ReadsCgroupLimits) {
  EXPECT_EQ(cgroup_limit_bytes("8589934592\n"), 8589934592.0);
  EXPECT_FALSE(cgroup_limit_bytes("max\n"));  // cgroup v2: no limit
  EXPECT_FALSE(cgroup_limit_bytes(""));
}

TEST(MemoryBudget, TheMachinesBudgetIsAtMostItsAvailableMemory) {
  const MemoryBudget budget = available_memory();
  std::ifstream in("/proc/meminfo");
  std::stringstream text;
  text << in.rdbuf();
  const auto available = meminfo_bytes(text.str(), "MemAvailable");
  ASSERT_TRUE(available);
  EXPECT_GT(budget.bytes, 0);
  // MemAvailable moves between the two reads by what other processes do: allow 5%.
  EXPECT_LE(budget.bytes, 1.05 * *available) << budget.source;
}

TEST(MemoryBudget, FormatsBytesForPeople) {
  EXPECT_EQ(format_bytes(12), "12 B");
  EXPECT_EQ(format_bytes(1.5e9), "1.5 GB");
  EXPECT_EQ(format_bytes(2.34e12), "2.34 TB");
}
