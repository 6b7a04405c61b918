// The `mpm` command line program: `mpm run SCENE [--restart FILE|DIR]`, `mpm check SCENE`, `mpm particles INPUT`,
// `mpm reference [--keys|--section PATH|--materials|--output-fields|--history-kinds|--energy-hints] [FILE]`, `mpm diff
// RUN_A RUN_B`, `mpm verify SCENE`, `mpm checkpoint FILE`, `mpm material-test --scene S --material NAME`. Exit statuses
// in run_scene.hpp.
#include <tbb/global_control.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <memory>
#include <new>
#include <optional>
#include <string>
#include <system_error>

#include "mpm/app/checkpoint_command.hpp"
#include "mpm/app/diff_command.hpp"
#include "mpm/app/material_test_command.hpp"
#include "mpm/app/modules.hpp"
#include "mpm/app/out_of_memory.hpp"
#include "mpm/app/parallel_launch.hpp"
#include "mpm/app/particles_command.hpp"
#include "mpm/app/rank_report.hpp"
#include "mpm/app/reference_command.hpp"
#include "mpm/app/run_checkpoints.hpp"
#include "mpm/app/run_scene.hpp"
#include "mpm/app/verify_command.hpp"
#include "mpm/checkpoint/checkpoint_file.hpp"
#include "mpm/core/stability_error.hpp"
#include "mpm/scene/scene_error.hpp"
#include "mpm/scene/scene_loader.hpp"
#ifdef MPM_WITH_MPI
#include "mpm/distributed/mpi_communicator.hpp"
#endif

namespace {

/// `--steps`: a whole number >= 1 (the message names what was given; CLI11 prefixes the option).
std::string check_steps(const std::string& text) {
  long long n = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), n);
  if (error != std::errc() || end != text.data() + text.size() || n < 1)
    return "expected a whole number of steps >= 1, got '" + text + "'";
  return "";
}

/// `--end-time`: a positive finite number of seconds.
std::string check_end_time(const std::string& text) {
  char* end = nullptr;
  const double t = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size() || !std::isfinite(t) || !(t > 0))
    return "expected a positive end time in seconds, got '" + text + "'";
  return "";
}

/// "rank R: ", the prefix of a message that one rank of a distributed run prints alone.
std::string fmt_rank(int rank) { return "rank " + std::to_string(rank) + ": "; }

/// CLI11's PositiveNumber / NonNegativeNumber with a message a user can read: "must be > 0, got 0" rather than a
/// range up to 1.8e308 printed in full.
CLI::Validator number_at_least_zero(bool strictly) {
  return CLI::Validator(
      [strictly](std::string& text) -> std::string {
        double value = 0;
        const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
        if (error != std::errc() || end != text.data() + text.size()) return "expected a number, got '" + text + "'";
        if (strictly ? value > 0 : value >= 0) return "";
        return std::string("must be ") + (strictly ? "> 0" : ">= 0") + ", got " + text;
      },
      strictly ? "POSITIVE" : "NONNEGATIVE");
}
const CLI::Validator positive_number = number_at_least_zero(true);
const CLI::Validator non_negative_number = number_at_least_zero(false);

}  // namespace

int main(int argc, char** argv) {
  using namespace mpm::app;
  install_terminate_handler();  // an exception escaping a worker thread: a message, not "terminate called..."
  CLI::App cli{
      "mpm: material point method (schemes usl, musl, usf, tlmpm, implicit) with YAML scenes and ParaView "
      "output"};
  cli.set_version_flag("--version", std::string("mpm ") + MPM_VERSION);
  cli.require_subcommand(1);
  std::string scene_file;
  std::string output_dir;
  int threads = 0;
  bool profile = false;
  long long steps = 0;
  double end_time = 0;
  auto* run_cmd = cli.add_subcommand("run", "run a scene and write .vtu/.pvd/energy.csv output");
  run_cmd->add_option("scene", scene_file, "scene file (YAML)")->required();
  run_cmd->add_option("-o,--output", output_dir, "output directory (overrides output.directory)");
  run_cmd
      ->add_option("--threads", threads,
                   "number of threads (default: all cores; under mpirun: per rank, the node's cores shared by its "
                   "ranks)")
      ->check(positive_number);
  int rebalance_every = 50;
  run_cmd
      ->add_option("--rebalance-every", rebalance_every,
                   "under mpirun: steps between balance checks; the ranks' boxes of tiles are dealt anew when the most "
                   "loaded rank exceeds the mean by more than 10% (0: never; results do not depend on it)")
      ->check(non_negative_number);
  run_cmd->add_flag(
      "--profile", profile,
      "time the phases of every step (P2G, grid update, G2P, stress update, halo, migrate, rebalance, sort, "
      "output, other) and print the breakdown at the end (under mpirun: rank 0's, and the ranks' spread)");
  auto* steps_opt = run_cmd
                        ->add_option("--steps", steps,
                                     "stop after N steps (N >= 1), or at the end time if sooner: to try a scene "
                                     "(the output holds the first and the last frame at least)")
                        ->check(CLI::Validator(check_steps, "N", "steps"));
  auto* end_time_opt =
      run_cmd->add_option("--end-time", end_time, "simulated time to stop at, s (> 0; replaces solver.end_time)")
          ->check(CLI::Validator(check_end_time, "T", "end time"));
  std::string restart;
  run_cmd->add_option("--restart", restart,
                      "continue the checkpoint FILE, or the newest valid one in DIR; the scene may differ only in "
                      "run-control keys (end_time, cfl, output, prescribed boundary velocities): a fork");
  // Test seams of the run path (apps/README.md, "Test seams"), not shown by --help.
  std::string test_signal, test_failure;
  int test_kill_in_checkpoint = 0;
  run_cmd
      ->add_option("--test-signal-at", test_signal,
                   "test only: send this process the signals NAME (INT, TERM, USR1, KILL; NAME+NAME+...) during step "
                   "STEP")
      ->group("");
  run_cmd->add_option("--test-fail-at", test_failure, "test only: rank RANK throws an internal error after step STEP")
      ->group("");
  run_cmd
      ->add_option("--test-kill-in-checkpoint", test_kill_in_checkpoint,
                   "test only: SIGKILL halfway through writing the N-th checkpoint")
      ->check(positive_number)
      ->group("");
  bool exchange_every_scatter = false;
  run_cmd
      ->add_flag("--exchange-every-scatter", exchange_every_scatter,
                 "benchmark only: under mpirun every scatter exchanges ghost nodes, not only those of bodies near a "
                 "cut (the same bits; bench/run_distributed_scaling.sh --baseline)")
      ->group("");
  run_cmd->footer(
      "Signals: SIGINT (Ctrl-C), SIGTERM and SIGUSR1 finish the current step, write a checkpoint and the last frame, "
      "print the command that resumes the run, and exit with 128 + the signal number (130, 143, 138); a second "
      "SIGINT exits at once.\nExit statuses: 0 done, 1 I/O or internal error, 2 bad scene, command line or "
      "checkpoint, 3 stopped by the stability guard, 128 + N stopped by signal N.");
  std::string checkpoint_file;  // `mpm checkpoint FILE`
  auto* checkpoint_cmd =
      cli.add_subcommand("checkpoint", "print what a checkpoint holds (time, step, bodies, fields) and verify it");
  checkpoint_cmd->add_option("file", checkpoint_file, "checkpoint file (.h5)")->required();
  auto* check_cmd = cli.add_subcommand("check", "validate a scene without running it");
  check_cmd->add_option("scene", scene_file, "scene file (YAML)")->required();
  int ranks = 0;
  check_cmd
      ->add_option("--ranks", ranks,
                   "also print what a distributed run on N ranks would hold: tiles, particles per rank, the "
                   "largest useful rank count, ghost nodes and halo bytes per step (docs/distributed.md)")
      ->check(positive_number);
  ParticlesOptions particles;  // `mpm particles`: particle sets of meshes, images and scenes for ParaView
  auto* particles_cmd = cli.add_subcommand("particles", "write the particles of a mesh, an image or a scene (.vtu)");
  particles_cmd->add_option("input", particles.input, "mesh (.stl .obj .off .ply) or image (.png .pgm .vti)");
  particles_cmd->add_option("--scene", particles.scene, "scene: its grid for INPUT, or all its bodies without INPUT");
  particles_cmd->add_option("--spacing", particles.spacing, "grid cell size around INPUT, m")->check(positive_number);
  particles_cmd->add_option("--ppc", particles.particles_per_cell, "particles per cell per axis (default 2)");
  particles_cmd->add_option("--pixel-size", particles.pixel_size, "image pixel size, m")->check(positive_number);
  particles_cmd->add_option("--threshold", particles.threshold, "image: pixels with a value >= threshold");
  particles_cmd->add_option("--label", particles.label, "image: pixels with this value");
  particles_cmd->add_option("--section", particles.section, "mesh: 2D particles of the plane z = section, m");
  particles_cmd->add_option("--scale", particles.scale, "mesh: factor on the coordinates")->check(positive_number);
  particles_cmd->add_option("--domains", particles.domains,
                            "also write CPDI domains to NAME_domains.vtu: lattice or conforming (INPUT), scene "
                            "(the scene's shape function)");
  particles_cmd->add_option("-o,--output", particles.output, "output .vtu file")->required();
  ReferenceOptions reference;  // `mpm reference`: the generated tables of docs/scene-reference.md
  std::string reference_file;
  auto* reference_cmd = cli.add_subcommand("reference",
                                           "print the reference tables generated from the specs (all of them "
                                           "without a flag), or rewrite the generated blocks of FILE "
                                           "(docs/scene-reference.md)");
  reference_cmd->add_flag("--keys", reference.keys, "the keys of every scene section that declares them");
  reference_cmd->add_option("--section", reference.section,
                            "the keys of one section: output, output.checkpoint, bodies, contact.planes, ...");
  reference_cmd->add_flag("--materials", reference.materials, "the material models' parameter tables");
  reference_cmd->add_flag("--output-fields", reference.output_fields, "the particle fields output.fields may name");
  reference_cmd->add_flag("--history-kinds", reference.history_kinds, "the types of output.histories entries");
  reference_cmd->add_flag("--energy-hints", reference.energy_hints,
                          "the documented instabilities the energy sentinel and the flight recorder quote");
  reference_cmd->add_option("file", reference_file, "Markdown file whose generated blocks to rewrite");
  MaterialTestCommandOptions material_test;  // `mpm material-test`: one material point along a prescribed path
  auto* material_test_cmd = cli.add_subcommand(
      "material-test",
      "drive one material point of a scene's material along a path (oedometer, triaxial, simple or cyclic shear, "
      "F(t) from a CSV) and write its stress-strain path as CSV");
  material_test_cmd->add_option("--scene", material_test.scene, "scene file (YAML) with the material")->required();
  material_test_cmd->add_option("--material", material_test.material, "name of the material in the scene")->required();
  material_test_cmd->add_option("--path", material_test.path,
                                "uniaxial_strain, triaxial_compression (default), triaxial_extension, simple_shear, "
                                "cyclic_shear or deformation_csv");
  material_test_cmd->add_option("--csv", material_test.csv,
                                "deformation_csv: rows time,F11,F12,F13,F21,F22,F23,F31,F32,F33 (from F = I at t = 0)");
  material_test_cmd->add_option("--strain", material_test.strain,
                                "final axial log strain (uniaxial, triaxial) or shear strain (simple_shear), "
                                "default 0.05");
  material_test_cmd->add_option("--steps", material_test.steps, "steps of the loading stage (default 1000)");
  material_test_cmd->add_option("--duration", material_test.duration, "time of the loading stage, s (default 1)");
  material_test_cmd->add_option("--confining-pressure", material_test.confining_pressure,
                                "Pa: isotropic consolidation first, then the lateral (triaxial) or normal (shear) "
                                "stress held at it (default 0)");
  material_test_cmd->add_option("--consolidation-steps", material_test.consolidation_steps,
                                "steps of the consolidation (default 10)");
  material_test_cmd->add_option("--amplitude", material_test.amplitude, "cyclic_shear: shear strain amplitude");
  material_test_cmd->add_option("--cycles", material_test.cycles, "cyclic_shear: number of cycles (default 1)");
  material_test_cmd->add_option("-o,--output", material_test.output, "CSV file (default: stdout)");
  material_test_cmd->add_option("--plot", material_test.plot,
                                "also draw the path into this PNG (q, shear, volume, stress path; needs matplotlib)");
  material_test_cmd->add_flag("--check", material_test.check,
                              "after the path: objectivity (the path again with a rigid rotation superposed) and, for "
                              "a UMAT, its tangent against finite differences; exit status 3 when one fails");
  DiffOptions diff;  // `mpm diff`: two output directories compared for regression checks
  std::string diff_a, diff_b;
  auto* diff_cmd = cli.add_subcommand(
      "diff", "compare two output directories field by field, frames and time-stamped rows paired by time");
  diff_cmd->add_option("run_a", diff_a, "first output directory")->required();
  diff_cmd->add_option("run_b", diff_b, "second output directory")->required();
  diff_cmd->add_option("--tolerance", diff.relative, "relative tolerance: |a-b| <= REL * max|a| of the field (0)")
      ->check(non_negative_number);
  diff_cmd->add_option("--absolute", diff.absolute, "absolute tolerance (0)")->check(non_negative_number);
  diff_cmd
      ->add_option("--time-tolerance", diff.time_tolerance,
                   "frames (and CSV rows) are paired when their times differ by at most T x the finer output "
                   "interval of the two runs; the times without a partner are listed (1e-6)")
      ->check(non_negative_number);
  VerifyOptions verify;  // `mpm verify`: solution verification at several resolutions
  std::string verify_output;
  auto* verify_cmd = cli.add_subcommand("verify",
                                        "run a scene at several resolutions and report the observed order, the "
                                        "Richardson extrapolation and the GCI of chosen history values");
  verify_cmd->add_option("scene", scene_file, "scene file (YAML) with output.histories")->required();
  verify_cmd->add_option("--refine", verify.runs, "number of runs (resolutions), >= 2 (default 3)")
      ->check(CLI::Range(2, 12));
  verify_cmd->add_option("--ratio", verify.ratio, "cell size ratio between runs, > 1 (default 2)");
  verify_cmd
      ->add_option("--quantity", verify.quantities,
                   "HISTORY.COLUMN, HISTORY.COLUMN@TIME (s) or HISTORY.COLUMN@START:TIME (the change); repeatable")
      ->required();
  verify_cmd->add_option("--order", verify.order, "assumed order of convergence (needed with --refine 2)");
  verify_cmd->add_option("-o,--output", verify_output, "report directory (default: verify)");
  verify_cmd->add_option("--threads", threads, "number of threads (default: all cores)")->check(positive_number);
  verify_cmd->add_flag(
      "--no-plot", [&](std::int64_t) { verify.plot = false; }, "do not draw verify.png");
  verify_cmd->add_flag("--finest", verify.scene_is_finest,
                       "the scene is the finest run, the others coarser (default: the coarsest, the others finer)");
  try {
    cli.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int status = cli.exit(e);
    return status == 0 ? exit_ok : exit_bad_input;
  }
  std::optional<TestSignal> test_signal_seam;
  std::optional<TestFailure> test_failure_seam;
  if (!test_signal.empty() && !(test_signal_seam = parse_test_signal(test_signal))) {
    std::cerr << "--test-signal-at: expected STEP:NAME[+NAME...] (NAME: INT, TERM, USR1, KILL), got '" << test_signal
              << "'\n";
    return exit_bad_input;
  }
  if (!test_failure.empty() && !(test_failure_seam = parse_test_failure(test_failure))) {
    std::cerr << "--test-fail-at: expected RANK:STEP, got '" << test_failure << "'\n";
    return exit_bad_input;
  }

  // Under mpirun/srun with more than one process: `mpm run` is a distributed run when MPI is built in;
  // anything else is refused on every process, explained by the first.
  std::shared_ptr<mpm::Communicator> world;
  if (const auto launch = parallel_launch([](const char* name) { return std::getenv(name); })) {
#ifdef MPM_WITH_MPI
    if (!run_cmd->parsed()) {
      if (launch->rank == 0)
        std::cerr << "error: only `mpm run` runs on several processes (" << launch->variable << "=" << launch->size
                  << "); start this command as one process\n";
      return exit_bad_input;
    }
    world = std::make_shared<mpm::distributed::MpiCommunicator>(&argc, &argv);
#else
    if (launch->rank == 0) std::cerr << "error: " << parallel_launch_refusal(*launch) << '\n';
    return exit_bad_input;
#endif
  }
  const int rank = world ? world->rank() : 0;
  // --threads is per rank; a distributed run's default is the node's cores shared by its ranks, within the CPUs the
  // launcher's binding leaves each process (parallel_launch.hpp).
  {
    const long cores = std::max(1L, sysconf(_SC_NPROCESSORS_ONLN));
    const long on_node =
        world ? ranks_on_node([](const char* name) { return std::getenv(name); }).value_or(world->size()) : 0;
    const ThreadChoice choice = choose_threads(threads, cores, on_node, cpus_this_process_may_use());
    threads = choice.threads;
    if (rank == 0 && (run_cmd->parsed() || verify_cmd->parsed()) && !choice.warning.empty())
      std::cerr << "warning: " << choice.warning << '\n';
  }
  std::unique_ptr<tbb::global_control> thread_limit;
  if (threads > 0)
    thread_limit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, threads);
  // Results (check's report, the summary of a run) go to stdout, what is said on the way (progress, warnings, notes,
  // errors) to stderr, as Unix tools do: `mpm run SCENE > summary.txt` keeps the summary and still shows the log
  // (README.md, "Output streams"). A distributed run prints from rank 0 (errors thrown on one rank only end the job
  // below). std::cerr is tied to std::cout, so the two keep their order on a terminal or in one file.
  std::ostream null_stream(nullptr);
  std::ostream& out = rank == 0 ? std::cout : null_stream;
  std::ostream& log = rank == 0 ? std::cerr : null_stream;
  if (particles_cmd->parsed()) return particles_command(particles, std::cout, std::cerr);
  if (diff_cmd->parsed()) {
    diff.a = diff_a;
    diff.b = diff_b;
    return diff_command(diff, std::cout, std::cerr);
  }
  if (checkpoint_cmd->parsed()) return checkpoint_command(checkpoint_file, std::cout, std::cerr);
  if (material_test_cmd->parsed()) return material_test_command(material_test, std::cout, std::cerr);
  if (reference_cmd->parsed()) {
    if (!reference_file.empty()) reference.file = reference_file;
    return reference_command(reference, std::cout, std::cerr);
  }
  try {
    register_modules();  // the optional modules' material models, before the scene is read
    if (verify_cmd->parsed()) {
      verify.scene = scene_file;
      if (!verify_output.empty()) verify.output = verify_output;
      return verify_command(verify, std::cout, std::cerr);
    }
    const mpm::SceneDescription scene = mpm::load_scene(scene_file);
    if (check_cmd->parsed()) {
      check_scene(scene, std::cout, std::cerr, ranks);
      return exit_ok;
    }
    RunOptions options;
    if (!output_dir.empty()) options.output_directory = output_dir;
    options.progress = rank == 0 && isatty(STDERR_FILENO);
    options.communicator = world;
    options.profile = profile;
    options.rebalance_every = rebalance_every;
    options.exchange_every_scatter = exchange_every_scatter;
    if (steps_opt->count() > 0) options.steps = steps;
    if (end_time_opt->count() > 0) options.end_time = end_time;
    if (!restart.empty()) options.restart = restart;
    options.test.signal = test_signal_seam;
    options.test.failure = test_failure_seam;
    options.test.kill_in_checkpoint = test_kill_in_checkpoint;
    const RunSummary summary = run_scene(scene, options, out, log);
    return summary.stopped_by_signal != 0 ? 128 + summary.stopped_by_signal : exit_ok;
  } catch (const mpm::SceneError& e) {  // every rank reads the same scene: one message
    log << "error: " << e.what() << missing_module_note(e, missing_modules()) << '\n';
    return exit_bad_input;
  } catch (const RankCountError& e) {
    log << "error: " << e.what() << '\n';
    return exit_bad_input;
  } catch (const RestartError& e) {
    log << "error: " << e.what() << '\n';
    return exit_bad_input;
  } catch (const mpm::checkpoint::CheckpointError& e) {
    log << "error: " << e.what() << '\n';
    return exit_bad_input;
  } catch (const mpm::StabilityError& e) {  // collective: the report is the same on every rank
    log << "error: " << e.what() << "\nThe last good state was written to the output.\n";
    return exit_unstable;
  } catch (const std::bad_alloc&) {
    std::cerr << (world ? fmt_rank(rank) : "") << "error: " << out_of_memory_message() << '\n';
    if (world) world->abort(exit_runtime_error);
    return exit_runtime_error;
  } catch (const std::exception& e) {
    // On one rank only, perhaps: the others would wait for it in a collective, so the job ends here.
    std::cerr << (world ? fmt_rank(rank) : "") << "error: " << e.what() << '\n';
    if (world) world->abort(exit_runtime_error);
    return exit_runtime_error;
  }
}
