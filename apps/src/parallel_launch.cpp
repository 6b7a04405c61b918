// Refusing a start under a parallel launcher (parallel_launch.hpp).
#include "mpm/app/parallel_launch.hpp"

#include <fmt/format.h>

#include <sched.h>

#include <algorithm>
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

std::optional<long> cpus_this_process_may_use() {
  cpu_set_t set;
  CPU_ZERO(&set);
  if (sched_getaffinity(0, sizeof(set), &set) != 0) return std::nullopt;
  const int n = CPU_COUNT(&set);
  return n > 0 ? std::optional<long>(n) : std::nullopt;
}

ThreadChoice choose_threads(int requested, long cores, long ranks_on_node, std::optional<long> allowed) {
  ThreadChoice choice{requested, {}};
  cores = std::max(1L, cores);
  const long allowed_cpus = allowed.value_or(cores);
  const char* unbind =
      "the launcher bound this process to them (OpenMPI binds each rank to one core by default for up to two "
      "ranks): start with `mpirun --bind-to none`, or `--map-by slot:PE=T` for T threads per rank";
  if (ranks_on_node > 0) {
    const long share = std::max(1L, cores / ranks_on_node);
    if (requested == 0) {
      choice.threads = static_cast<int>(std::min(share, allowed_cpus));
      if (allowed_cpus < share)
        choice.warning = fmt::format("{} thread(s) per rank, not {}: this process may run on {} CPU(s) only; {}",
                                     choice.threads, share, allowed_cpus, unbind);
      return choice;
    }
    if (static_cast<long>(requested) * ranks_on_node > cores) {
      choice.warning = fmt::format(
          "{} ranks x {} threads on a node of {} cores: the threads compete for the cores (set --threads per rank)",
          ranks_on_node, requested, cores);
      return choice;
    }
  }
  if (requested > allowed_cpus)
    choice.warning = fmt::format("--threads {}, but this process may run on {} CPU(s) only: the threads share them; {}",
                                 requested, allowed_cpus, unbind);
  return choice;
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
