/// \file bench_sparse_grid.cpp
/// Sparse tiles against the dense grid in one process (active_tiles.hpp): the same scene built twice,
/// one simulation visiting only the nodes its particles reach (the default) and one every node
/// (SimulationSettings::sparse_grid = false), stepped in alternating rounds on the same machine so that the
/// machine's drift hits both alike. Prints per case: particles, grid nodes, the nodes the sparse run visited at its
/// last step, wall ms per step and the P2G and grid-update phases of each, and whether the final particles and grids
/// are byte-equal, and the bytes of the node arrays in memory (reserved_pages.hpp). Not a test: timings are never
/// checked (bench/README.md).
///
///   ./build/bench/bench_sparse_grid [--case taylor_anvil|two_disks_200|all] [--steps N] [--rounds N] [--threads N]
///                                   [--cells N]
///
/// Cases: the 3D Taylor anvil (examples/05_taylor_anvil/musl.yaml: MUSL, hat functions) as it is, and the two
/// disks (examples/02_two_disks) at 200 cells per side (`--cells N`: N per side, 4 particles per cell, for the
/// memory of a larger grid, whose rows span more pages).
#include <fmt/format.h>
#include <tbb/global_control.h>

#include <chrono>
#include <cstring>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "bench_options.hpp"
#include "mpm/app/modules.hpp"
#include "mpm/app/scene_builder.hpp"
#include "mpm/scene/scene_loader.hpp"

namespace {

struct Timing {
  double wall = 0, p2g = 0, grid = 0;  // seconds
  int steps = 0;
};

template <int Dim>
void run_steps(mpm::Simulation<Dim>& sim, int steps, Timing& t) {
  const mpm::StepProfile before = sim.profile();
  const auto start = std::chrono::steady_clock::now();
  for (int s = 0; s < steps; ++s) sim.advance(sim.next_time_step());
  t.wall += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  t.p2g += sim.profile()[mpm::StepPhase::p2g] - before[mpm::StepPhase::p2g];
  t.grid += sim.profile()[mpm::StepPhase::grid_update] - before[mpm::StepPhase::grid_update];
  t.steps += steps;
}

template <class T, class Alloc>
bool same_bytes(const std::vector<T, Alloc>& a, const std::vector<T, Alloc>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0;
}

template <int Dim>
void run_case(const std::string& name, const mpm::SceneDescription& scene, int steps, int rounds) {
  auto dense = mpm::app::build_simulation<Dim>(scene);
  auto sparse = mpm::app::build_simulation<Dim>(scene);
  dense->use_sparse_grid(false);
  dense->enable_profiling();
  sparse->enable_profiling();
  Timing warm, d, s;
  run_steps(*dense, 2, warm);
  run_steps(*sparse, 2, warm);
  for (int r = 0; r < rounds; ++r) {  // alternate, so that a slower minute of the machine costs both
    run_steps(*dense, steps, d);
    run_steps(*sparse, steps, s);
  }
  mpm::Index particles = 0;
  for (const auto& b : sparse->bodies()) particles += b.particles.size();
  const mpm::Index nodes = sparse->grid().size();
  const mpm::Index visited = sparse->active_tiles().nodes().count(nodes);
  // Memory first: the byte comparison below reads every page of the sparse arrays, and a page read maps the zero
  // page, which mincore counts as resident (reserved_pages.hpp) though it costs no memory.
  const std::size_t dense_resident = dense->grid().resident_bytes(), sparse_resident = sparse->grid().resident_bytes();
  // Velocities outside the visited nodes are not compared: there the dense grid also holds the face conditions'
  // values, which the sparse grid writes only where a particle can read them.
  bool same = same_bytes(sparse->grid().node, dense->grid().node);
  mpm::for_each_node_in_order(nodes, sparse->active_tiles().nodes(), [&](mpm::Index n) {
    same = same &&
           std::memcmp(&sparse->grid().velocity[n], &dense->grid().velocity[n], sizeof(mpm::NodeVelocity<Dim>)) == 0;
  });
  for (std::size_t b = 0; b < sparse->bodies().size(); ++b)
    same = same && same_bytes(sparse->bodies()[b].particles.x, dense->bodies()[b].particles.x) &&
           same_bytes(sparse->bodies()[b].particles.v, dense->bodies()[b].particles.v);
  const auto ms = [](double seconds, int n) { return 1e3 * seconds / n; };
  fmt::print("{}: {} particles, {} nodes, sparse visits {} ({:.1f}%) at its last step\n", name, particles, nodes,
             visited, 100.0 * static_cast<double>(visited) / static_cast<double>(nodes));
  fmt::print("  dense : {:.3f} ms/step (P2G {:.3f}, grid update {:.3f})\n", ms(d.wall, d.steps), ms(d.p2g, d.steps),
             ms(d.grid, d.steps));
  fmt::print("  sparse: {:.3f} ms/step (P2G {:.3f}, grid update {:.3f}): {:.2f}x the dense step\n", ms(s.wall, s.steps),
             ms(s.p2g, s.steps), ms(s.grid, s.steps), d.wall / s.wall);
  fmt::print("  final particles (x, v) and grid byte-equal: {}\n", same ? "yes" : "NO");
  const auto mib = [](std::size_t bytes) { return static_cast<double>(bytes) / (1 << 20); };
  const auto& g = sparse->grid();
  const std::size_t whole =
      sizeof(mpm::NodeRecord<Dim>) * g.node.size() + sizeof(mpm::NodeVelocity<Dim>) * g.velocity.size();
  fmt::print(
      "  node arrays in memory (mass, momentum, force, velocities): dense {:.2f} MiB, sparse {:.2f} MiB of {:.2f}\n",
      mib(dense_resident), mib(sparse_resident), mib(whole));
}

}  // namespace

int main(int argc, char** argv) {
  std::string which = "all";
  int steps = 20, rounds = 3, threads = 1, cells = 200;
  mpm::bench::BenchOptions cli(
      "bench_sparse_grid",
      "[--case taylor_anvil|two_disks_200|all] [--steps N] [--rounds N] [--threads N] [--cells N]");
  cli.option("--case", which).option("--steps", steps).option("--rounds", rounds).option("--cells", cells);
  cli.threads(threads);
  cli.require([&] { return steps >= 1 && rounds >= 1; }, "--steps and --rounds must be >= 1");
  cli.require([&] { return cells >= 20 && cells <= 4000; }, "--cells must be between 20 and 4000");
  cli.require([&] { return which == "all" || which == "taylor_anvil" || which == "two_disks_200"; },
              "--case must be taylor_anvil, two_disks_200 or all");
  if (const auto status = cli.parse(argc, argv)) return *status;
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(threads));
  mpm::app::register_modules();
  const std::string examples = std::string(MPM_SOURCE_DIR) + "/examples/";
  fmt::print("sparse tiles against the dense grid, {} thread(s), {} rounds of {} steps each\n", threads, rounds, steps);
  if (which == "all" || which == "taylor_anvil")
    run_case<3>("taylor_anvil (3D MUSL hat)", mpm::load_scene(examples + "05_taylor_anvil/musl.yaml"), steps, rounds);
  if (which == "all" || which == "two_disks_200") {
    mpm::SceneDescription scene = mpm::load_scene(examples + "02_two_disks/scene.yaml");
    for (int d = 0; d < 2; ++d) {
      scene.grid.cell_size[d] = 1.0 / cells;
      scene.grid.cells[d] = cells;
    }
    // the example's dt is stable down to 200 cells per side (CFL bound 7.9e-3 s there): scaled with h below that
    if (cells > 200 && scene.solver.dt) scene.solver.dt = *scene.solver.dt * 200.0 / cells;
    run_case<2>(fmt::format("two_disks_{} (2D MUSL hat, {} x {} cells)", cells, cells, cells), scene, steps, rounds);
  }
  return 0;
}
