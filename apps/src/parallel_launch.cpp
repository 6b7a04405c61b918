// Refusing a start under a parallel launcher (parallel_launch.hpp).
#include "mpm/app/parallel_launch.hpp"

#include <fmt/format.h>

#include <charconv>
#include <cstring>

namespace mpm::app {
namespace {

std::optional<long> whole_number(const char* text) {
  if (text == nullptr) return std::nullopt;
  long n = 0;
  const char* end = text + std::strlen(text);
  const auto [at, error] = std::from_chars(text, end, n);
  if (error != std::errc() || at != end || n < 0) return std::nullopt;
  return n;
}

}  // namespace

std::optional<ParallelLaunch> parallel_launch(const std::function<const char*(const char*)>& environment) {
  struct Launcher {
    const char* size;
    const char* rank;
  };
  static constexpr Launcher launchers[] = {
      {"OMPI_COMM_WORLD_SIZE", "OMPI_COMM_WORLD_RANK"},
      {"PMI_SIZE", "PMI_RANK"},
      {"SLURM_STEP_NUM_TASKS", "SLURM_PROCID"},
  };
  for (const Launcher& l : launchers) {
    const std::optional<long> size = whole_number(environment(l.size));
    if (!size || *size <= 1) continue;
    ParallelLaunch launch;
    launch.size = *size;
    launch.rank = whole_number(environment(l.rank)).value_or(0);
    launch.variable = l.size;
    return launch;
  }
  return std::nullopt;
}

std::optional<long> ranks_on_node(const std::function<const char*(const char*)>& environment) {
  for (const char* name : {"OMPI_COMM_WORLD_LOCAL_SIZE", "MPI_LOCALNRANKS", "SLURM_NTASKS_PER_NODE"})
    if (const std::optional<long> n = whole_number(environment(name)); n && *n >= 1) return n;
  return std::nullopt;
}

std::string parallel_launch_refusal(const ParallelLaunch& launch) {
  return fmt::format(
      "mpm was started as {} processes ({}={}), but it was built without MPI: a scene runs in one process, "
      "and {} copies would each compute the whole scene and overwrite each other's output (rebuild with "
      "libopenmpi-dev installed for distributed runs). Start one process and give it the cores: mpm run SCENE "
      "--threads N",
      launch.size, launch.variable, launch.size, launch.size);
}

}  // namespace mpm::app
