// `mpm` started under a parallel launcher (apps/include/mpm/app/parallel_launch.hpp). A build without MPI refuses
// with exit 2 on every process before anything is read or written, explained once (by the first process); a build
// with MPI runs `mpm run` distributed and refuses the other commands likewise. A single process, and a Slurm batch
// script's SLURM_NTASKS alone, run as usual. The last test starts it under OpenMPI's real mpirun.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <string>

#include "mpm/app/parallel_launch.hpp"
#include "run_mpm.hpp"

namespace fs = std::filesystem;

namespace {

using cli::mpm;
using cli::scratch;

const std::string scene = (fs::path(MPM_SOURCE_DIR) / "examples" / "02_two_disks" / "scene.yaml").string();

std::optional<mpm::app::ParallelLaunch> launch_of(const std::map<std::string, std::string>& environment) {
  return mpm::app::parallel_launch([&](const char* name) -> const char* {
    const auto it = environment.find(name);
    return it == environment.end() ? nullptr : it->second.c_str();
  });
}

TEST(ParallelLaunch, EachLaunchersVariablesAreRead) {
  auto l = launch_of({{"OMPI_COMM_WORLD_SIZE", "4"}, {"OMPI_COMM_WORLD_RANK", "3"}});
  ASSERT_TRUE(l);
  EXPECT_EQ(l->size, 4);
  EXPECT_EQ(l->rank, 3);
  EXPECT_EQ(l->variable, "OMPI_COMM_WORLD_SIZE");
  l = launch_of({{"PMI_SIZE", "2"}, {"PMI_RANK", "1"}});
  ASSERT_TRUE(l);
  EXPECT_EQ(l->size, 2);
  EXPECT_EQ(l->rank, 1);
  l = launch_of({{"SLURM_STEP_NUM_TASKS", "8"}, {"SLURM_PROCID", "0"}, {"SLURM_NTASKS", "8"}});
  ASSERT_TRUE(l);
  EXPECT_EQ(l->variable, "SLURM_STEP_NUM_TASKS");
  EXPECT_EQ(l->rank, 0);
  l = launch_of({{"PMI_SIZE", "3"}});  // no rank variable: counted as the first, so the message is printed
  ASSERT_TRUE(l);
  EXPECT_EQ(l->rank, 0);
}

TEST(ParallelLaunch, OneProcessOrNoLauncherIsNotALaunch) {
  EXPECT_FALSE(launch_of({}));
  EXPECT_FALSE(launch_of({{"OMPI_COMM_WORLD_SIZE", "1"}, {"OMPI_COMM_WORLD_RANK", "0"}}));
  EXPECT_FALSE(launch_of({{"SLURM_NTASKS", "16"}}));  // a batch script that starts one process
  EXPECT_FALSE(launch_of({{"PMI_SIZE", "two"}}));
  EXPECT_FALSE(launch_of({{"PMI_SIZE", "4x"}}));
}

TEST(ParallelLaunch, RanksOnTheNodeAreRead) {
  auto on_node = [](const std::map<std::string, std::string>& environment) {
    return mpm::app::ranks_on_node([&](const char* name) -> const char* {
      const auto it = environment.find(name);
      return it == environment.end() ? nullptr : it->second.c_str();
    });
  };
  EXPECT_EQ(on_node({{"OMPI_COMM_WORLD_LOCAL_SIZE", "3"}}), 3);
  EXPECT_EQ(on_node({{"SLURM_NTASKS_PER_NODE", "16"}}), 16);
  EXPECT_FALSE(on_node({{"OMPI_COMM_WORLD_LOCAL_SIZE", "x"}}));
  EXPECT_FALSE(on_node({}));
}

// The threads of a run (choose_threads): a distributed run shares the node's cores among its ranks but never runs
// more threads than the CPUs its binding leaves it, and a --threads beyond those CPUs is said to gain nothing.
TEST(ParallelLaunch, ThreadsFollowTheCoresAndTheBinding) {
  using mpm::app::choose_threads;
  // One process: TBB's default, silent; 2 threads on 1 allowed CPU (mpirun -np 1 binds to a core): a warning.
  EXPECT_EQ(choose_threads(0, 8, 0, 8).threads, 0);
  EXPECT_EQ(choose_threads(0, 8, 0, 8).warning, "");
  EXPECT_EQ(choose_threads(4, 8, 0, 8).warning, "");
  auto c = choose_threads(2, 2, 0, 1);
  EXPECT_EQ(c.threads, 2);
  EXPECT_NE(c.warning.find("--threads 2, but this process may run on 1 CPU(s) only"), std::string::npos) << c.warning;
  EXPECT_NE(c.warning.find("--bind-to none"), std::string::npos) << c.warning;
  // Distributed, unbound: 64 cores over 4 ranks -> 16 each; bound to one core each -> 1, said once.
  EXPECT_EQ(choose_threads(0, 64, 4, 64).threads, 16);
  EXPECT_EQ(choose_threads(0, 64, 4, 64).warning, "");
  c = choose_threads(0, 64, 2, 1);
  EXPECT_EQ(c.threads, 1);
  EXPECT_NE(c.warning.find("1 thread(s) per rank, not 32"), std::string::npos) << c.warning;
  EXPECT_EQ(choose_threads(0, 64, 2, std::nullopt).threads, 32);  // no affinity known: the node's share
  EXPECT_EQ(choose_threads(0, 2, 4, 2).threads, 1);               // more ranks than cores: one thread each
  // Ranks x threads beyond the node's cores.
  c = choose_threads(2, 2, 2, 2);
  EXPECT_NE(c.warning.find("2 ranks x 2 threads on a node of 2 cores"), std::string::npos) << c.warning;
  EXPECT_EQ(choose_threads(1, 2, 2, 1).warning, "");
}

#ifdef MPM_WITH_MPI
// With MPI only `mpm run` runs distributed; the other commands are refused on every process, explained once. (A
// `mpm run` under a launcher's variables without the launcher would start MPI alone: tested under mpirun below.)
TEST(ParallelLaunch, OnlyRunRunsOnSeveralProcesses) {
  const auto dir = scratch("parallel_launch");
  auto r = mpm("check " + scene, dir, "OMPI_COMM_WORLD_SIZE=4 OMPI_COMM_WORLD_RANK=0");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("only `mpm run` runs on several processes (OMPI_COMM_WORLD_SIZE=4)"), std::string::npos)
      << r.err;
  r = mpm("check " + scene, dir, "OMPI_COMM_WORLD_SIZE=4 OMPI_COMM_WORLD_RANK=2");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "");
  r = mpm("check " + scene, dir, "SLURM_NTASKS=4 OMPI_COMM_WORLD_SIZE=1");
  EXPECT_EQ(r.status, 0) << r.err;
  fs::remove_all(dir);
}

/// A build with MPI (MPM_WITH_MPI) must be able to start its distributed runs: a missing launcher fails the tests
/// that need it instead of skipping them, so that a CI image without OpenMPI's mpirun cannot pass them unseen.
bool parallel_launch_mpirun_found() { return std::system("command -v mpirun > /dev/null 2>&1") == 0; }
const char* const parallel_launch_missing_mpirun =
    "this build has MPI (MPM_WITH_MPI) but no mpirun is on PATH: install OpenMPI's launcher (openmpi-bin), or "
    "configure with -DMPM_WITH_MPI=OFF";

/// mpirun -np `np` mpm ARGS, as root; returns the exit status (124: mpirun did not end within 120 s).
int mpirun(int np, const std::string& args, const fs::path& dir, const std::string& environment = "") {
  const std::string cmd = environment +
                          " OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 timeout 120 mpirun "
                          "--oversubscribe -np " +
                          std::to_string(np) + " " + std::string(MPM_EXECUTABLE) + " " + args + " > " +
                          (dir / "stdout").string() + " 2> " + (dir / "stderr").string() + " < /dev/null";
  const int raw = std::system(cmd.c_str());
  return WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
}

TEST(ParallelLaunch, UnderMpirunTheRunIsDistributedAndLogsOnce) {
  ASSERT_TRUE(parallel_launch_mpirun_found()) << parallel_launch_missing_mpirun;
  const auto dir = scratch("parallel_launch_mpirun");
  const fs::path out = dir / "out";
  EXPECT_EQ(mpirun(2, "run " + scene + " --steps 30 --threads 1 -o " + out.string(), dir), 0)
      << cli::slurp(dir / "stderr");
  // The summary on stdout, from rank 0 only.
  const std::string summary = cli::slurp(dir / "stdout");
  const auto done = summary.find("done: 30 steps");
  EXPECT_NE(done, std::string::npos) << summary;
  EXPECT_EQ(summary.find("done:", done + 1), std::string::npos) << "printed by more than one rank:\n" << summary;
  EXPECT_NE(summary.find("416 particles"), std::string::npos) << summary;  // every rank's, as in one process
  EXPECT_EQ(cli::slurp(dir / "stderr").find("done:"), std::string::npos) << cli::slurp(dir / "stderr");
  EXPECT_TRUE(fs::exists(out / "energy.csv"));
  fs::remove_all(dir);
}

/// What a distributed run does not take yet is refused on every rank with exit 2, said once, before writing.
TEST(ParallelLaunch, UnderMpirunWhatCannotBeDistributedIsRefusedOnce) {
  ASSERT_TRUE(parallel_launch_mpirun_found()) << parallel_launch_missing_mpirun;
  const auto dir = scratch("parallel_launch_refused");
  const fs::path out = dir / "out";
  // The implicit scheme (its Newton-Krylov solve has no distributed vectors yet).
  const std::string bar = (fs::path(MPM_SOURCE_DIR) / "examples" / "17_love_sulsky_bar" / "implicit.yaml").string();
  EXPECT_EQ(mpirun(2, "run " + bar + " --steps 3 -o " + out.string(), dir), 2);
  std::string err = cli::slurp(dir / "stderr");
  const auto first = err.find("does not run on several ranks yet");
  EXPECT_NE(first, std::string::npos) << err;
  EXPECT_NE(err.find("scheme 'implicit'"), std::string::npos) << err;
  EXPECT_EQ(err.find("does not run on several ranks yet", first + 1), std::string::npos) << err;
  EXPECT_FALSE(fs::exists(out / "energy.csv"));
  // Contact with the density normals (a cell array summed in storage order, without ghost exchange).
  std::ofstream(dir / "density_normals.yaml") << cli::slurp(scene) << "contact: {normals: density}\n";
  EXPECT_EQ(mpirun(2, "run " + (dir / "density_normals.yaml").string() + " --steps 3 -o " + out.string(), dir), 2);
  err = cli::slurp(dir / "stderr");
  EXPECT_NE(err.find("module 'contact' does not run on several ranks yet (normals: density"), std::string::npos) << err;
  EXPECT_FALSE(fs::exists(out / "energy.csv"));
#ifdef MPM_WITH_FLUIDS
  // The incompressible fluid's pressure projection (one global linear system per step).
  std::ofstream(dir / "incompressible.yaml") << R"yaml(dimension: 2
grid: {origin: [0, 0], extent: [0.4, 0.4], cell_size: 0.02, boundary: {x_min: slip, x_max: slip, y_min: slip}}
materials:
  water: {model: incompressible_fluid, density: 1000}
bodies:
  - {name: water, material: water, shape: {type: box, min: [0, 0], max: [0.2, 0.2]}}
solver: {cfl: 0.5, gravity: [0, -9.81], end_time: 0.1}
)yaml";
  EXPECT_EQ(mpirun(2, "run " + (dir / "incompressible.yaml").string() + " --steps 3 -o " + out.string(), dir), 2);
  err = cli::slurp(dir / "stderr");
  EXPECT_NE(err.find("module 'pressure_projection' does not run on several ranks yet"), std::string::npos) << err;
  EXPECT_FALSE(fs::exists(out / "energy.csv"));
#endif
  // More ranks than tiles: the two-disk scene on 4 x 4 cells has 2 tiles (8 cells wide along x, 2 along y).
  std::string coarse = cli::slurp(scene);
  coarse.replace(coarse.find("cell_size: 0.05"), 15, "cell_size: 0.25");
  std::ofstream(dir / "coarse.yaml") << coarse;
  EXPECT_EQ(mpirun(3, "run " + (dir / "coarse.yaml").string() + " --steps 3 --threads 1 -o " + out.string(), dir), 2);
  err = cli::slurp(dir / "stderr");
  EXPECT_NE(err.find("3 ranks for 2 tiles of the scatter"), std::string::npos) << err;
  EXPECT_NE(err.find("start at most 2 ranks"), std::string::npos) << err;
  fs::remove_all(dir);
}

/// A distributed run's checkpoint is the one-process run's state (rank 0 gathers the particles in the one-process
/// storage order): a run on 3 ranks checkpointed at t = 1, restarted from that checkpoint on 2 ranks, ends in the
/// files of one uninterrupted process, bit for bit (compare_runs.py: energy.csv and every frame); so does a
/// one-process restart of the same checkpoint.
TEST(ParallelLaunch, UnderMpirunACheckpointRestartsOnAnyNumberOfRanks) {
  ASSERT_TRUE(parallel_launch_mpirun_found()) << parallel_launch_missing_mpirun;
  const auto dir = scratch("parallel_launch_checkpoint");
  std::string text = cli::slurp(scene);
  text.replace(text.find("  interval: 0.05"), 16, "  interval: 0.25\n  checkpoint: {interval: 1.0}");
  std::ofstream(dir / "scene.yaml") << text;
  const std::string run = "run " + (dir / "scene.yaml").string() + " --end-time 2 --threads 1 -o ";
  ASSERT_EQ(mpm(run + (dir / "serial").string(), dir).status, 0);
  // 3 ranks stopped at step 1300 (checkpoints at steps 1000 and 1300), continued from step 1000 on 2 ranks
  ASSERT_EQ(mpirun(3, run + (dir / "ranks").string() + " --steps 1300", dir), 0) << cli::slurp(dir / "stderr");
  const fs::path at_1000 = dir / "ranks" / "checkpoints" / "checkpoint_000001000.h5";
  ASSERT_TRUE(fs::exists(at_1000));
  fs::copy_file(at_1000, dir / "checkpoint_000001000.h5");
  ASSERT_EQ(mpirun(2, run + (dir / "ranks").string() + " --restart " + at_1000.string(), dir), 0)
      << cli::slurp(dir / "stderr");
  const std::string compare = "/usr/bin/python3 " + std::string(MPM_SOURCE_DIR) + "/tests/distributed/compare_runs.py ";
  EXPECT_EQ(std::system((compare + (dir / "serial").string() + " " + (dir / "ranks").string() + " > " +
                         (dir / "compare.txt").string())
                            .c_str()),
            0)
      << cli::slurp(dir / "compare.txt");
  // the same checkpoint continued by one process, into a copy of the output as it was at step 1300
  ASSERT_EQ(mpirun(3, run + (dir / "one").string() + " --steps 1300", dir), 0) << cli::slurp(dir / "stderr");
  ASSERT_EQ(mpm(run + (dir / "one").string() + " --restart " + (dir / "checkpoint_000001000.h5").string(), dir).status,
            0);
  EXPECT_EQ(std::system((compare + (dir / "serial").string() + " " + (dir / "one").string() + " > " +
                         (dir / "compare.txt").string())
                            .c_str()),
            0)
      << "(a one-process restart writes .vtu frames after the .pvtu ones; compare_runs.py reads both)\n"
      << cli::slurp(dir / "compare.txt");
  fs::remove_all(dir);
}

/// The stability guard trips on the rank holding the block (thrown out of the grid through +x): every rank rolls
/// back together and exits 3 with the same report, said once, and the last good frame is complete.
TEST(ParallelLaunch, UnderMpirunTheGuardStopsEveryRankWithOneReport) {
  ASSERT_TRUE(parallel_launch_mpirun_found()) << parallel_launch_missing_mpirun;
  const auto dir = scratch("parallel_launch_guard");
  std::ofstream(dir / "scene.yaml") << cli::block_scene("cfl: 0.5, end_time: 1", "[20, 0]");
  const fs::path out = dir / "out";
  EXPECT_EQ(mpirun(3, "run " + (dir / "scene.yaml").string() + " --threads 1 -o " + out.string(), dir), 3)
      << cli::slurp(dir / "stderr");
  const std::string err = cli::slurp(dir / "stderr");
  const auto report = err.find("body 'block', particle ");
  EXPECT_NE(report, std::string::npos) << err;
  EXPECT_EQ(err.find("stability guard:", report + 1), std::string::npos) << "said more than once:\n" << err;
  const std::string pvd = cli::slurp(out / "particles.pvd");
  EXPECT_NE(pvd.find("particles_000001.pvtu"), std::string::npos) << pvd;  // frame 1: the last good state
  for (int r = 0; r < 3; ++r)
    EXPECT_TRUE(fs::exists(out / "particles_000001" / ("particles_000001_" + std::to_string(r) + ".vtu"))) << r;
  // The flight recorder: every rank replays, rank 0 writes the one-process failure/, byte for byte (the particles
  // gathered in the one-process order; the failing particle's nodes from the rank that held it).
  const fs::path serial = dir / "serial";
  const auto one = mpm("run " + (dir / "scene.yaml").string() + " --threads 1 -o " + serial.string(), dir);
  EXPECT_EQ(one.status, 3) << one.err;
  ASSERT_TRUE(fs::exists(serial / "failure" / "particle.csv")) << one.err;
  ASSERT_TRUE(fs::exists(out / "failure" / "particle.csv")) << err;
  EXPECT_FALSE(fs::exists(out / ".failure.partial"));
  int files = 0;
  for (const auto& entry : fs::directory_iterator(serial / "failure")) {
    const std::string name = entry.path().filename().string();
    if (name == "diagnosis.txt") continue;  // names the output directory
    EXPECT_EQ(cli::slurp(entry.path()), cli::slurp(out / "failure" / name)) << name;
    ++files;
  }
  EXPECT_GE(files, 5);  // particle.csv, nodes.csv, particles.pvd and the frames
  EXPECT_GT(cli::slurp(out / "failure" / "nodes.csv").size(), cli::slurp(out / "failure" / "particle.csv").size() / 4);
  fs::remove_all(dir);
}

/// An internal error on one rank (the hidden test seam --test-fail-at R:S) ends the whole job, never a hang.
TEST(ParallelLaunch, UnderMpirunAnErrorOnOneRankEndsTheJob) {
  ASSERT_TRUE(parallel_launch_mpirun_found()) << parallel_launch_missing_mpirun;
  const auto dir = scratch("parallel_launch_abort");
  const int status =
      mpirun(3, "run " + scene + " --threads 1 -o " + (dir / "out").string() + " --test-fail-at 1:5", dir);
  EXPECT_NE(status, 0);
  EXPECT_NE(status, 124) << "the job hung";
  const std::string err = cli::slurp(dir / "stderr");
  EXPECT_NE(err.find("rank 1: error: debug failure of rank 1 after step 5"), std::string::npos) << err;
  fs::remove_all(dir);
}
#else
TEST(ParallelLaunch, EveryProcessExitsWithTwoAndTheFirstSaysWhy) {
  const auto dir = scratch("parallel_launch");
  const fs::path out = dir / "out";
  auto r = mpm("run " + scene + " -o " + out.string(), dir, "OMPI_COMM_WORLD_SIZE=4 OMPI_COMM_WORLD_RANK=0");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("started as 4 processes (OMPI_COMM_WORLD_SIZE=4)"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("built without MPI"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("--threads"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));  // nothing written
  r = mpm("run " + scene + " -o " + out.string(), dir, "OMPI_COMM_WORLD_SIZE=4 OMPI_COMM_WORLD_RANK=2");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "");  // only the first process explains
  EXPECT_FALSE(fs::exists(out));
  r = mpm("check " + scene, dir, "SLURM_STEP_NUM_TASKS=2 SLURM_PROCID=0");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("(SLURM_STEP_NUM_TASKS=2)"), std::string::npos) << r.err;
  r = mpm("check " + scene, dir, "SLURM_NTASKS=4 OMPI_COMM_WORLD_SIZE=1");
  EXPECT_EQ(r.status, 0) << r.err;
  fs::remove_all(dir);
}

TEST(ParallelLaunch, UnderOpenMpisMpirunNoProcessRuns) {
  // Without MPI the launcher is optional: this test needs it to start two processes.
  if (std::system("command -v mpirun > /dev/null 2>&1") != 0)
    GTEST_SKIP() << "mpirun is not installed (a build without MPI)";
  const auto dir = scratch("parallel_launch_mpirun");
  const fs::path out = dir / "out";
  // timeout: a launcher that hangs fails the test instead of the suite
  const std::string cmd =
      "OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 timeout 120 mpirun "
      "--oversubscribe -np 2 " +
      std::string(MPM_EXECUTABLE) + " run " + scene + " -o " + out.string() + " > " + (dir / "stdout").string() +
      " 2> " + (dir / "stderr").string() + " < /dev/null";
  const int raw = std::system(cmd.c_str());
  ASSERT_TRUE(WIFEXITED(raw));
  EXPECT_NE(WEXITSTATUS(raw), 0);
  EXPECT_NE(WEXITSTATUS(raw), 124) << "mpirun did not finish within 120 s";
  const std::string err = cli::slurp(dir / "stderr");
  const auto first = err.find("started as 2 processes (OMPI_COMM_WORLD_SIZE=2)");
  EXPECT_NE(first, std::string::npos) << err;
  EXPECT_EQ(err.find("started as 2 processes", first + 1), std::string::npos) << "printed more than once:\n" << err;
  EXPECT_FALSE(fs::exists(out));
  fs::remove_all(dir);
}
#endif

}  // namespace
