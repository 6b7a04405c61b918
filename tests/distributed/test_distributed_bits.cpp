// Distributed runs give the bits of one process (issue 18, docs/distributed.md §5). Started by ctest under
// `mpirun -np K` (K = 2..4) with `--threads T`: every rank builds the same scene, the ranks run it distributed
// (Simulation::distribute), rank 0 also runs it alone; after every step the energy audit (the values energy.csv
// prints) and the time must be byte-equal, and at the end every particle of every body (all its fields, found by
// id wherever it ended) byte-equal to the one-process run's. With `--reassign` the slabs are dealt to the ranks
// at random before every step (the same draw on every rank): results must not depend on the assignment.
// Exit status 0 when every case agrees on every rank, 1 otherwise (mpirun returns the worst).
#include <fmt/format.h>
#include <tbb/global_control.h>

#include <cstring>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "mpm/app/modules.hpp"
#include "mpm/app/scene_builder.hpp"
#include "mpm/distributed/mpi_communicator.hpp"
#include "mpm/scene_loader.hpp"

namespace {

struct Case {
  std::string name;
  std::string file;  ///< under examples/
  int dimension = 2;
  int steps = 40;
  mpm::SchemeKind scheme = mpm::SchemeKind::musl;
  std::string shape = "linear";
  mpm::VelocityTransfer transfer = mpm::VelocityTransfer::flip;
  int coarsen = 1;    ///< cells this many times larger than the example's (fewer particles)
  int rebalance = 0;  ///< steps between the balance checks (Simulation::set_rebalance_interval), 0 none
};

/// id -> every field's bytes (the serial layout's fields, by name), per body.
using ParticleBytes = std::vector<std::map<std::uint32_t, std::string>>;

template <int Dim>
std::vector<std::byte> pack_bodies(const mpm::Simulation<Dim>& sim, const std::vector<std::string>& fields) {
  std::vector<std::byte> out;
  for (const auto& b : sim.bodies()) {
    const auto& p = b.particles;
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
void unpack_bodies(const mpm::Simulation<Dim>& sim, const std::vector<std::string>& fields,
                   const std::vector<std::byte>& in, ParticleBytes& into) {
  into.resize(sim.bodies().size());
  std::size_t at = 0;
  for (std::size_t b = 0; b < sim.bodies().size(); ++b) {
    std::int64_t count = 0;
    std::memcpy(&count, in.data() + at, sizeof count);
    at += sizeof count;
    std::vector<std::string> record(static_cast<std::size_t>(count));
    std::vector<std::uint32_t> ids(static_cast<std::size_t>(count));
    for (const auto& f : fields) {
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
bool run_case(const Case& c, const std::shared_ptr<mpm::distributed::MpiCommunicator>& comm, bool reassign) {
  mpm::SceneDescription scene = mpm::load_scene(std::string(MPM_SOURCE_DIR) + "/examples/" + c.file);
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
  std::vector<std::string> fields;
  {
    auto sim = mpm::app::build_simulation<Dim>(scene);
    for (const auto& l : sim->bodies().front().particles.field_layout()) fields.push_back(l.name);
    if (rank == 0) {
      for (int s = 0; s < c.steps; ++s) {
        sim->advance(sim->next_time_step());
        serial_audit.push_back(audit_bytes(*sim));
      }
      unpack_bodies(*sim, fields, pack_bodies(*sim, fields), serial);
    }
  }
  auto sim = mpm::app::build_simulation<Dim>(scene);
  sim->distribute(comm);
  sim->set_rebalance_interval(c.rebalance);
  const std::vector<int> first_slabs = sim->halo()->first_slab();
  std::mt19937 rng(42);  // the same draws on every rank
  bool ok = true;
  std::size_t halo_bytes = 0, model_bytes = 0;
  // The halo model (SlabHalo::model_bytes_per_scatter): per step, body and scatter, one message per rank boundary.
  const int scatters = c.scheme == mpm::SchemeKind::usl ? 1 : 2;
  auto model_step = [&] {
    return sim->bodies().size() * scatters * sim->halo()->model_bytes_per_scatter(sizeof(mpm::NodeRecord<Dim>));
  };
  for (int s = 0; s < c.steps; ++s) {
    if (reassign) {
      const int slabs = sim->halo()->slab_count(), ranks = comm->size();
      std::vector<int> cuts;
      for (int k = 1; k < slabs; ++k) cuts.push_back(k);
      std::shuffle(cuts.begin(), cuts.end(), rng);
      cuts.resize(static_cast<std::size_t>(ranks - 1));
      std::sort(cuts.begin(), cuts.end());
      std::vector<int> first{0};
      first.insert(first.end(), cuts.begin(), cuts.end());
      first.push_back(slabs);
      sim->reassign_slabs(first);
    }
    model_bytes += model_step();
    sim->advance(sim->next_time_step());
    const std::string audit = audit_bytes(*sim);
    if (rank == 0 && audit != serial_audit[static_cast<std::size_t>(s)]) {
      if (ok) fmt::print("{}: the audit after step {} differs from one process'\n", c.name, s + 1);
      ok = false;
    }
  }
  halo_bytes = sim->halo_bytes_sent();
  if (halo_bytes != model_bytes) {
    fmt::print("{}: rank {} sent {} halo bytes, the model counts {}\n", c.name, rank, halo_bytes, model_bytes);
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
        "{} ({} ranks{}{}): {} steps, {} particles, {} fields each, halo {} B sent by rank 0 (= model): {}\n", c.name,
        comm->size(), reassign ? ", slabs dealt at random every step" : "",
        sim->halo()->first_slab() != first_slabs ? ", rebalanced" : "", c.steps,
        [&] {
          std::size_t n = 0;
          for (const auto& m : serial) n += m.size();
          return n;
        }(),
        fields.size(), halo_bytes, ok ? "identical bits" : "DIFFERENT");
  }
  return comm->any(!ok) == false;
}

}  // namespace

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
  using mpm::SchemeKind;
  using mpm::VelocityTransfer;
  const std::vector<Case> cases = {
      {"2D USL linear FLIP (two disks)", "02_two_disks/scene.yaml", 2, 60, SchemeKind::usl, "linear"},
      {"2D MUSL cubic APIC (two disks)", "02_two_disks/scene.yaml", 2, 40, SchemeKind::musl, "cubic_bspline",
       VelocityTransfer::apic},
      {"2D USF quadratic (two disks)", "02_two_disks/scene.yaml", 2, 40, SchemeKind::usf, "quadratic_bspline"},
      {"2D MUSL linear FLIP (dam break, fluid)", "12_dam_break/scene.yaml", 2, 40, SchemeKind::musl, "linear"},
      {"2D USL GIMP (dam break, fluid)", "12_dam_break/scene.yaml", 2, 30, SchemeKind::usl, "gimp"},
      {"2D TLMPM cubic B-spline (two disks)", "02_two_disks/scene.yaml", 2, 40, SchemeKind::tlmpm, "cubic_bspline"},
      {"3D TLMPM linear (Johnson-Cook Taylor anvil)", "05_taylor_anvil/musl.yaml", 3, 20, SchemeKind::tlmpm, "linear",
       VelocityTransfer::flip, 2},
      {"3D USL GIMP (Johnson-Cook Taylor anvil)", "05_taylor_anvil/musl.yaml", 3, 20, SchemeKind::usl, "gimp",
       VelocityTransfer::flip, 2},
      {"3D MUSL linear (Johnson-Cook Taylor anvil, rebalanced every 5 steps)", "05_taylor_anvil/musl.yaml", 3, 30,
       SchemeKind::musl, "linear", VelocityTransfer::flip, 2, 5},
  };
  bool ok = true;
  for (const auto& c : cases) {
    try {
      ok = (c.dimension == 2 ? run_case<2>(c, comm, reassign) : run_case<3>(c, comm, reassign)) && ok;
    } catch (const std::exception& e) {
      fmt::print("{}: rank {}: {}\n", c.name, comm->rank(), e.what());
      comm->abort(1);
    }
  }
  return ok ? 0 : 1;
}
