#pragma once
/// \file parallel_launch.hpp
/// A start as one of several processes of a parallel launcher (mpirun, mpiexec, srun). A build with MPI runs
/// `mpm run` distributed over them; a build without would run N copies of the whole scene that overwrite
/// each other's output, so it refuses such a start (exit 2) before reading anything; the first process says why.

#include <functional>
#include <optional>
#include <string>

namespace mpm::app {

struct ParallelLaunch {
  long size = 1;         ///< processes the launcher started
  long rank = 0;         ///< this one's index among them (0 when the launcher does not say)
  std::string variable;  ///< the environment variable that gave the size
};

/// The launch as the launchers' environment describes it: OpenMPI's OMPI_COMM_WORLD_SIZE/RANK, the PMI
/// (MPICH, Intel MPI) PMI_SIZE/RANK, and Slurm's SLURM_STEP_NUM_TASKS/SLURM_PROCID (set by srun for a job step;
/// not SLURM_NTASKS, which a batch script also holds when it starts one process). Nothing when the size is
/// absent, not a whole number, or 1.
std::optional<ParallelLaunch> parallel_launch(const std::function<const char*(const char*)>& environment);

/// The processes the launcher started on this node (OMPI_COMM_WORLD_LOCAL_SIZE, MPI_LOCALNRANKS,
/// SLURM_NTASKS_PER_NODE), when it says: the default threads of a rank share the node's cores among them.
std::optional<long> ranks_on_node(const std::function<const char*(const char*)>& environment);

/// The CPUs this process may run on: its affinity mask, which a launcher narrows when it binds ranks (OpenMPI binds
/// each rank to one core by default for up to two ranks, and to a socket beyond). Nothing where the system does not
/// say.
std::optional<long> cpus_this_process_may_use();

/// The threads of `mpm run` and what to tell the user about them.
struct ThreadChoice {
  int threads = 0;      ///< 0: the default of one process (TBB's: every CPU the process may use)
  std::string warning;  ///< empty, or one line (without "warning: ") on a choice that wastes or shares cores
};

/// `requested`: --threads (0 = default). `cores`: the node's online CPUs. `ranks_on_node`: the ranks sharing the node
/// (0 = not a distributed run). `allowed`: cpus_this_process_may_use(). A distributed run defaults to the node's
/// cores shared by its ranks, but never to more than the CPUs its binding allows (threads beyond them share a core
/// and gain nothing: measured, a 2D USL run bound to one core ran 2 threads at 0.94x of 1; docs/PERFORMANCE.md).
ThreadChoice choose_threads(int requested, long cores, long ranks_on_node, std::optional<long> allowed);

/// The refusal: the count, the variable, what to do instead.
std::string parallel_launch_refusal(const ParallelLaunch& launch);

}  // namespace mpm::app
