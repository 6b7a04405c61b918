// Distributed runs give the bits of one process (docs/distributed.md §5). Started by ctest under
// `mpirun -np K` (K = 2..4) with `--threads T`: every rank builds the same scene, the ranks run it distributed
// (Simulation::distribute), rank 0 also runs it alone; after every step the energy audit (the values energy.csv
// prints) and the time must be byte-equal, and at the end every particle of every body (all its fields, found by
// id wherever it ended) byte-equal to the one-process run's. With `--reassign` the slabs are dealt to the ranks
// at random before every step (the same draw on every rank): results must not depend on the assignment.
// Exit status 0 when every case agrees on every rank, 1 otherwise (mpirun returns the worst).
#include <fmt/format.h>
#include <tbb/global_control.h>

#include <unistd.h>

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <numeric>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "mpm/app/modules.hpp"
#include "mpm/app/scene_builder.hpp"
#include "mpm/diagnostics/energy_sentinel.hpp"
#include "mpm/distributed/mpi_communicator.hpp"
#include "mpm/scene/scene_loader.hpp"
#include "mpm/schemes/scheme_registry.hpp"

namespace {

struct Case {
  std::string name;
  std::string file;  ///< under examples/
  int dimension = 2;
  int steps = 40;
  std::string scheme = "musl";  ///< a registered scheme
  std::string shape = "linear";
  mpm::VelocityTransfer transfer = mpm::VelocityTransfer::flip;
  int coarsen = 1;    ///< cells this many times larger than the example's (fewer particles)
  int rebalance = 0;  ///< steps between the balance checks (Simulation::set_rebalance_interval), 0 none
  /// Changes to the example's text (modules: contact, thermal), applied before it is parsed; none when empty.
  std::function<std::string(std::string)> edit{};
  /// Whether to compare the contact force CSV (`contact.force_file`, written in the output directory).
  std::string force_file{};
  /// Whether only the schemes' scatters exchange ghost nodes (the halo model's count is then checked); modules
  /// add scatters of their own (contact normals, thermal capacities), which the model below does not count.
  bool halo_model = true;
  /// On 2 ranks with the bisection's tiles: some body scatters must go without exchange (every body apart from the
  /// cut: TileBins::exchange), checked with the bits.
  bool expect_skips = false;
};

/// `text` with `from` replaced by `to` (every occurrence; at least one must exist).
std::string replaced(std::string text, const std::string& from, const std::string& to) {
  std::size_t at = text.find(from);
  if (at == std::string::npos) throw std::logic_error("test scene: '" + from + "' not found");
  for (; at != std::string::npos; at = text.find(from, at + to.size())) text.replace(at, from.size(), to);
  return text;
}

std::string file_bytes(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

/// id -> every field's bytes (the serial layout's fields, by name), per body.
using BodyFields = std::vector<std::vector<std::string>>;  ///< per body: the names of its fields (bodies differ)
using ParticleBytes = std::vector<std::map<std::uint32_t, std::string>>;

template <int Dim>
std::vector<std::byte> pack_bodies(const mpm::Simulation<Dim>& sim, const BodyFields& body_fields) {
  std::vector<std::byte> out;
  for (std::size_t k = 0; k < sim.bodies().size(); ++k) {
    const auto& p = sim.bodies()[k].particles;
    const auto& fields = body_fields[k];
    std::vector<mpm::Index> all(static_cast<std::size_t>(p.size()));
    for (mpm::Index i = 0; i < p.size(); ++i) all[static_cast<std::size_t>(i)] = i;
    const auto count = static_cast<std::int64_t>(p.size());
    const std::size_t at = out.size();
    out.resize(at + sizeof count);
    std::memcpy(out.data() + at, &count, sizeof count);
    for (const auto& f : fields) p.pack_field(f, all, out);
  }
  return out;
}

template <int Dim>
void unpack_bodies(const mpm::Simulation<Dim>& sim, const BodyFields& body_fields, const std::vector<std::byte>& in,
                   ParticleBytes& into) {
  into.resize(sim.bodies().size());
  std::size_t at = 0;
  for (std::size_t b = 0; b < sim.bodies().size(); ++b) {
    std::int64_t count = 0;
    std::memcpy(&count, in.data() + at, sizeof count);
    at += sizeof count;
    std::vector<std::string> record(static_cast<std::size_t>(count));
    std::vector<std::uint32_t> ids(static_cast<std::size_t>(count));
    for (const auto& f : body_fields[b]) {
      const std::size_t bpp = [&] {
        for (const auto& l : sim.bodies()[b].particles.field_layout())
          if (l.name == f) return l.bytes_per_particle();
        return std::size_t{0};
      }();
      for (std::int64_t i = 0; i < count; ++i) {
        const char* bytes = reinterpret_cast<const char*>(in.data() + at + static_cast<std::size_t>(i) * bpp);
        record[static_cast<std::size_t>(i)].append(bytes, bpp);
        if (f == "id") std::memcpy(&ids[static_cast<std::size_t>(i)], bytes, sizeof(std::uint32_t));
      }
      at += static_cast<std::size_t>(count) * bpp;
    }
    for (std::int64_t i = 0; i < count; ++i)
      into[b][ids[static_cast<std::size_t>(i)]] = std::move(record[static_cast<std::size_t>(i)]);
  }
}

/// The audit and the time after a step, as the bytes energy.csv's numbers come from.
template <int Dim>
std::string audit_bytes(const mpm::Simulation<Dim>& sim) {
  const mpm::EnergyBalance e = sim.energy();
  const double values[] = {sim.time(), e.kinetic,     e.strain,      e.gravity,     e.plastic_work,
                           e.thermal,  e.momentum[0], e.momentum[1], e.momentum[2], e.mass};
  return std::string(reinterpret_cast<const char*>(values), sizeof values);
}

template <int Dim>
bool run_case(const Case& c, const std::shared_ptr<mpm::distributed::MpiCommunicator>& comm, bool reassign,
              const std::filesystem::path& scratch) {
  const std::string path = std::string(MPM_SOURCE_DIR) + "/examples/" + c.file;
  mpm::SceneDescription scene = c.edit ? mpm::parse_scene(c.edit(file_bytes(path)), path) : mpm::load_scene(path);
  scene.solver.scheme = c.scheme;
  scene.solver.shape_function = c.shape;
  scene.solver.velocity_transfer = c.transfer;
  for (int d = 0; d < c.dimension; ++d) {
    scene.grid.cell_size[d] *= c.coarsen;
    scene.grid.cells[d] /= c.coarsen;
  }
  const int rank = comm->rank();
  // The one-process reference, on rank 0.
  std::vector<std::string> serial_audit;
  ParticleBytes serial;
  BodyFields fields;
  const std::filesystem::path serial_output = scratch / "serial", distributed_output = scratch / "distributed";
  {
    scene.output.directory = serial_output.string();
    auto sim = mpm::app::build_simulation<Dim>(scene);
    for (const auto& b : sim->bodies()) {
      fields.emplace_back();
      for (const auto& l : b.particles.field_layout()) fields.back().push_back(l.name);
    }
    if (rank == 0) {
      for (int s = 0; s < c.steps; ++s) {
        sim->advance(sim->next_time_step());
        serial_audit.push_back(audit_bytes(*sim));
      }
      unpack_bodies(*sim, fields, pack_bodies(*sim, fields), serial);
    }
  }
  scene.output.directory = distributed_output.string();
  auto sim = mpm::app::build_simulation<Dim>(scene);
  sim->distribute(comm);
  sim->set_rebalance_interval(c.rebalance);
  const std::vector<int> first_owners = sim->halo()->owners();
  std::mt19937 rng(42);  // the same draws on every rank
  bool ok = true;
  std::size_t halo_bytes = 0, model_bytes = 0;
  // The halo model (TileHalo::model_bytes_per_scatter, the plan's nodes): per step, exchanging body and scatter (a
  // body with no particle in a tile that writes shared nodes does not exchange: Simulation::exchanging_bodies).
  const int scatters = mpm::find_scheme(c.scheme)->traits.scatters_per_step;
  std::size_t skipped = 0;  // body scatters without exchange
  // Steps whose grid kernels visited fewer nodes than the rank holds (sparse tiles on a rank, §5.11)
  int sparse_steps = 0;
  auto model_step = [&] {
    skipped += (sim->bodies().size() - sim->exchanging_bodies()) * static_cast<std::size_t>(scatters);
    return sim->exchanging_bodies() * scatters * sim->halo()->model_bytes_per_scatter(sizeof(mpm::NodeRecord<Dim>));
  };
  for (int s = 0; s < c.steps; ++s) {
    if (reassign) {
      // Every tile to a rank drawn at random (each rank at least one tile): no boxes, ghost nodes everywhere.
      const std::size_t tiles = sim->halo()->owners().size();
      const int ranks = comm->size();
      std::vector<int> owner(tiles);
      for (auto& o : owner) o = static_cast<int>(rng() % static_cast<unsigned>(ranks));
      std::vector<std::size_t> first(tiles);
      std::iota(first.begin(), first.end(), std::size_t{0});
      std::shuffle(first.begin(), first.end(), rng);
      for (int r = 0; r < ranks; ++r) owner[first[static_cast<std::size_t>(r)]] = r;
      sim->reassign_tiles(owner);
    }
    model_bytes += model_step();
    sim->advance(sim->next_time_step());
    const mpm::Index nodes = sim->grid().size();
    const mpm::NodeRuns visited = sim->active_tiles().nodes();
    if (!visited.all && visited.count(nodes) < sim->halo()->held_nodes().count(nodes)) ++sparse_steps;
    const std::string audit = audit_bytes(*sim);
    if (rank == 0 && audit != serial_audit[static_cast<std::size_t>(s)]) {
      if (ok) fmt::print("{}: the audit after step {} differs from one process'\n", c.name, s + 1);
      ok = false;
    }
  }
  halo_bytes = sim->halo_bytes_sent();
  if (c.halo_model && halo_bytes != model_bytes) {
    fmt::print("{}: rank {} sent {} halo bytes, the model counts {}\n", c.name, rank, halo_bytes, model_bytes);
    ok = false;
  }
  if (c.expect_skips && !reassign && comm->size() == 2 && skipped == 0) {
    fmt::print("{}: rank {}: every body scatter exchanged, though both bodies stay away from the cut\n", c.name, rank);
    ok = false;
  }
  if (c.expect_skips && !reassign && sparse_steps == 0) {
    fmt::print("{}: rank {}: the grid kernels visited every node the rank holds at every step\n", c.name, rank);
    ok = false;
  }
  std::vector<std::vector<std::byte>> out(static_cast<std::size_t>(comm->size()));
  out[0] = pack_bodies(*sim, fields);
  const auto in = comm->all_to_all(std::move(out));
  if (rank == 0) {
    ParticleBytes distributed(sim->bodies().size());
    for (const auto& buffer : in) unpack_bodies(*sim, fields, buffer, distributed);
    for (std::size_t b = 0; b < serial.size(); ++b) {
      if (distributed[b].size() != serial[b].size()) {
        fmt::print("{}: body {} has {} particles on the ranks, {} in one process\n", c.name, b, distributed[b].size(),
                   serial[b].size());
        ok = false;
        continue;
      }
      int differing = 0;
      for (const auto& [id, bytes] : serial[b]) {
        const auto it = distributed[b].find(id);
        if (it == distributed[b].end() || it->second != bytes) ++differing;
      }
      if (differing > 0) {
        fmt::print("{}: {} particles of body {} differ from one process'\n", c.name, differing, b);
        ok = false;
      }
    }
    fmt::print(
        "{} ({} ranks{}{}): {} steps, {} particles, {} fields each, halo {} B sent by rank 0{}: {}\n", c.name,
        comm->size(), reassign ? ", tiles dealt at random every step" : "",
        sim->halo()->owners() != first_owners ? ", rebalanced" : "", c.steps,
        [&] {
          std::size_t n = 0;
          for (const auto& m : serial) n += m.size();
          return n;
        }(),
        fields.front().size(), halo_bytes, c.halo_model ? " (= model)" : "", ok ? "identical bits" : "DIFFERENT");
    if (c.expect_skips) fmt::print("  body scatters without exchange on rank 0: {}\n", skipped);
    if (!c.force_file.empty()) {
      const std::string serial_csv = file_bytes(serial_output / c.force_file);
      const bool same = !serial_csv.empty() && serial_csv == file_bytes(distributed_output / c.force_file);
      fmt::print("{}: the force CSV ({} bytes) {}\n", c.name, serial_csv.size(),
                 same ? "is byte-equal" : "DIFFERS (or is empty)");
      ok = ok && same;
    }
  }
  return comm->any(!ok) == false;
}

}  // namespace

/// Counts the collectives a run calls (the messages of the halo pass through uncounted): the engine promises one
/// reduction per step.
class CountingCommunicator final : public mpm::Communicator {
 public:
  explicit CountingCommunicator(std::shared_ptr<mpm::Communicator> inner) : inner_(std::move(inner)) {}
  int rank() const override { return inner_->rank(); }
  int size() const override { return inner_->size(); }
  void sum(std::span<mpm::ExactSum> s) override { ++reductions, inner_->sum(s); }
  void max(std::span<double> v) override { ++reductions, inner_->max(v); }
  void min(std::span<double> v) override { ++reductions, inner_->min(v); }
  bool any(bool flag) override { return ++reductions, inner_->any(flag); }
  void sum(std::span<std::int64_t> v) override { ++reductions, inner_->sum(v); }
  void exchange(std::span<const Outgoing> sends, std::span<const Incoming> receives) override {
    inner_->exchange(sends, receives);
  }
  std::unique_ptr<Transfer> start_send(const Outgoing& m) override { return inner_->start_send(m); }
  std::unique_ptr<Transfer> start_receive(const Incoming& m) override { return inner_->start_receive(m); }
  std::vector<std::vector<std::byte>> all_to_all(std::vector<std::vector<std::byte>> out) override {
    ++all_to_alls;
    return inner_->all_to_all(std::move(out));
  }
  void broadcast(std::vector<std::byte>& bytes, int root) override { ++others, inner_->broadcast(bytes, root); }
  void barrier() override { ++others, inner_->barrier(); }
  [[noreturn]] void abort(int status) override {
    inner_->abort(status);
    std::abort();  // not reached: the inner abort ends the job
  }
  long reductions = 0, all_to_alls = 0, others = 0;

 private:
  std::shared_ptr<mpm::Communicator> inner_;
};

/// The two disks, USL hats, 60 steps: exactly one reduction per step (wave speed, guard, migration and the caller's
/// flags together), plus the energy sentinel's audit every 50 steps (EnergySentinel::default_interval: one merge of
/// the energy sums), and one all-to-all per body only on the steps where some particle changes rank.
bool one_reduction_per_step(const std::shared_ptr<mpm::distributed::MpiCommunicator>& comm) {
  mpm::SceneDescription scene = mpm::load_scene(std::string(MPM_SOURCE_DIR) + "/examples/02_two_disks/scene.yaml");
  scene.solver.scheme = "usl";
  auto counting = std::make_shared<CountingCommunicator>(comm);
  auto sim = mpm::app::build_simulation<2>(scene);
  sim->distribute(counting);
  sim->set_rebalance_interval(0);
  sim->set_step_flags([](mpm::Index step, mpm::Real) { return step % 7 == 0 ? 1u : 0u; });
  const int steps = 60;
  const long before = counting->reductions, all_to_alls_before = counting->all_to_alls;
  bool flags_ok = true;
  for (int s = 0; s < steps; ++s) {
    sim->advance(sim->next_time_step());
    flags_ok = flags_ok && sim->step_flags() == ((s + 1) % 7 == 0 ? 1u : 0u);
  }
  const long reductions = counting->reductions - before, all_to_alls = counting->all_to_alls - all_to_alls_before;
  const long bodies = static_cast<long>(sim->bodies().size());
  const long audits = steps / mpm::EnergySentinel<2>::default_interval;
  const bool ok = reductions == steps + audits && all_to_alls % bodies == 0 && all_to_alls < steps * bodies && flags_ok;
  if (!ok || comm->rank() == 0)
    fmt::print(
        "one reduction per step: rank {}: {} reductions ({} steps, {} audits) and {} all-to-alls ({} bodies), "
        "flags {}\n",
        comm->rank(), reductions, steps, audits, all_to_alls, bodies, flags_ok ? "agree" : "DIFFER");
  return ok;
}

int main(int argc, char** argv) {
  auto comm = std::make_shared<mpm::distributed::MpiCommunicator>(&argc, &argv);
  int threads = 1;
  bool reassign = false;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--threads" && i + 1 < argc) threads = std::stoi(argv[++i]);
    if (a == "--reassign") reassign = true;
  }
  mpm::app::register_modules();
  tbb::global_control threads_control(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(threads));
  using mpm::VelocityTransfer;
  // Love & Sulsky's colliding cylinders, explicit, with frictionless contact and a floor with friction the left
  // one reaches (docs/distributed.md §5: contact and its force CSV).
  const auto cylinders_with_contact = [](std::string text) {
    text = replaced(text, "scheme: implicit", "scheme: musl");
    text = replaced(text, "  implicit: {newton_rtol: 1.0e-13}\n", "");
    text = replaced(text, "  dt: 0.015", "  cfl: 0.5");
    return text +
           "contact:\n  planes: [{name: floor, point: [0, -1.02], normal: [0, 1], friction: 0.2}]\n"
           "  force_file: forces.csv\n  force_interval: 0.02\n";
  };
  // The ring crushed between rigid platens (friction, particle-gap onset), the platens 100 times faster so that
  // they touch the ring within the test's steps; no histories (not taken by a distributed run yet).
  const auto ring_crush_fast = [](std::string text) {
    text = replaced(text, "\"-5\"]", "\"-500\"]");
    text = replaced(text, "[\"0\", \"5\"]", "[\"0\", \"500\"]");
    text = replaced(text, "force_interval: 1.0e-5", "force_interval: 2.0e-7");
    return text.substr(0, text.find("  histories:"));
  };
  const auto twice_finer = [](std::string text) { return replaced(text, "  cell_size: 0.05", "  cell_size: 0.025"); };
  // Small disks on a fine grid (100 x 100 cells, 1,256 particles each), far from the cut of 2 ranks.
  const auto small_disks = [](std::string text) {
    text = replaced(text, "  cell_size: 0.05", "  cell_size: 0.01");
    text = replaced(text, "radius: 0.2}", "radius: 0.1}");
    return replaced(text, "  dt: 0.001", "  dt: 0.0002");
  };
  const auto without_grid_output = [](std::string text) { return replaced(text, "  grid: true", "  grid: false"); };
  // A hot block under a cold one, pressed together, with a finite contact conductance: each body has its own
  // nodal temperatures and heat crosses the interface (eqs TC.1-TC.2).
  const auto hot_under_cold = [](const std::string&) {
    return std::string(R"(dimension: 2
grid: {origin: [0, 0], extent: [0.02, 0.04], cell_size: 0.001}
materials:
  hot: {model: linear_elastic, density: 1000, youngs_modulus: 1.0e6, poisson_ratio: 0.3, specific_heat: 1,
        thermal_conductivity: 2}
  cold: {model: linear_elastic, density: 1000, youngs_modulus: 1.0e6, poisson_ratio: 0.3, specific_heat: 1,
         thermal_conductivity: 1}
bodies:
  - {name: hot, material: hot, shape: {type: box, min: [0.002, 0.002], max: [0.018, 0.02]}, particles_per_cell: 2,
     velocity: [0, 1]}
  - {name: cold, material: cold, shape: {type: box, min: [0.002, 0.0205], max: [0.018, 0.038]},
     particles_per_cell: 2}
solver: {scheme: musl, shape_function: linear, cfl: 0.5, end_time: 1}
thermal: {initial_temperature: "y < 0.02 ? 400 : 300"}
contact: {thermal_conductance: 1.0e3, force_file: forces.csv}
)");
  };
  const std::vector<Case> cases = {
      {"2D USL linear FLIP (two disks)", "02_two_disks/scene.yaml", 2, 60, "usl", "linear"},
      {"2D MUSL cubic APIC (two disks)", "02_two_disks/scene.yaml", 2, 40, "musl", "cubic_bspline",
       VelocityTransfer::apic},
      {"2D USF quadratic (two disks)", "02_two_disks/scene.yaml", 2, 40, "usf", "quadratic_bspline"},
      {"2D MUSL linear FLIP (two small disks on 100 x 100 cells: bodies away from the cut exchange nothing)",
       "02_two_disks/scene.yaml", 2, 40, "musl", "linear", VelocityTransfer::flip, 1, 0, small_disks, "", true, true},
      {"2D MUSL linear FLIP (dam break, fluid)", "12_dam_break/scene.yaml", 2, 40, "musl", "linear"},
      {"2D USL GIMP (dam break, fluid)", "12_dam_break/scene.yaml", 2, 30, "usl", "gimp"},
      {"2D TLMPM cubic B-spline (two disks)", "02_two_disks/scene.yaml", 2, 40, "tlmpm", "cubic_bspline"},
      {"3D TLMPM linear (Johnson-Cook Taylor anvil)", "05_taylor_anvil/musl.yaml", 3, 20, "tlmpm", "linear",
       VelocityTransfer::flip, 2},
      {"3D USL GIMP (Johnson-Cook Taylor anvil)", "05_taylor_anvil/musl.yaml", 3, 20, "usl", "gimp",
       VelocityTransfer::flip, 2},
      {"3D MUSL linear (Johnson-Cook Taylor anvil, rebalanced every 5 steps)", "05_taylor_anvil/musl.yaml", 3, 30,
       "musl", "linear", VelocityTransfer::flip, 2, 5},
      {"2D USL CPDI Q4 with tracked corners (two disks at 40 x 40 cells: 4 slabs of 9)", "02_two_disks/scene.yaml", 2,
       40, "usl", "cpdi_q4", VelocityTransfer::flip, 1, 0, twice_finer, "", true},
      {"2D MUSL linear, frictionless contact and a floor with friction (colliding cylinders)",
       "18_colliding_cylinders/scene.yaml", 2, 40, "musl", "linear", VelocityTransfer::flip, 1, 0,
       cylinders_with_contact, "forces.csv", false},
      {"2D USL GIMP, rigid platens, friction, particle-gap onset (ring crush)", "09_ring_crush/scene.yaml", 2, 40,
       "usl", "gimp", VelocityTransfer::flip, 1, 0, ring_crush_fast, "ring_forces.csv", false},
      {"2D MUSL linear heat conduction, held face temperatures (heat plate)", "10_heat_plate/plate.yaml", 2, 40, "musl",
       "linear", VelocityTransfer::flip, 1, 0, without_grid_output, "", false},
      {"3D MUSL linear thermal Taylor anvil (plastic heating, thermal softening)", "11_thermal_taylor/musl.yaml", 3, 20,
       "musl", "linear", VelocityTransfer::flip, 2, 0, nullptr, "", false},
      {"2D MUSL linear, heat across contact with a finite conductance (hot block under a cold one)",
       "02_two_disks/scene.yaml", 2, 40, "musl", "linear", VelocityTransfer::flip, 1, 0, hot_under_cold, "forces.csv",
       false},
  };
  // Each case's output folders (the force CSVs), in the system's temporary folder under rank 0's process id.
  std::vector<std::byte> id(sizeof(int));
  const int pid = static_cast<int>(getpid());
  std::memcpy(id.data(), &pid, sizeof pid);
  comm->broadcast(id, 0);
  int root_pid = 0;
  std::memcpy(&root_pid, id.data(), sizeof root_pid);
  const std::filesystem::path scratch =
      std::filesystem::temp_directory_path() / fmt::format("mpm_distributed_bits_{}", root_pid);
  bool ok = true;
  for (std::size_t k = 0; k < cases.size(); ++k) {
    const Case& c = cases[k];
    const std::filesystem::path folder = scratch / std::to_string(k);
    try {
      ok = (c.dimension == 2 ? run_case<2>(c, comm, reassign, folder) : run_case<3>(c, comm, reassign, folder)) && ok;
    } catch (const std::exception& e) {
      fmt::print("{}: rank {}: {}\n", c.name, comm->rank(), e.what());
      comm->abort(1);
    }
  }
  if (!reassign) ok = one_reduction_per_step(comm) && ok;
  comm->barrier();
  if (comm->rank() == 0) std::filesystem::remove_all(scratch);
  return ok ? 0 : 1;
}
