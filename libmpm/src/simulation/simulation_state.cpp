// Simulation::save_state / restore_state: the run's state as named arrays (state_archive.hpp), for checkpoints.
//
// Particles are saved in id order, so that the arrays do not depend on how the particles happen to be stored
// (the periodic sort by cell reorders them, and a rank owns only some), together with the ids in their
// storage order. The restore puts them back in that storage order: the scatter visits particles in storage
// order, and a different order would sum the nodal contributions in another order (other round-off).
//
// A distributed run's checkpoint is the one-process run's: rank 0 gathers every rank's particles and merges them
// by the scatter key, whose order is the one-process storage order (docs/distributed.md §5.3), and leaves the key
// itself out; a restart on any number of ranks then distributes that state anew.
#include <fmt/format.h>

#include <algorithm>
#include <cstring>
#include <numeric>
#include <optional>

#include "mpm/failure/failure_module.hpp"
#include "mpm/simulation/simulation.hpp"

namespace mpm {
namespace {

constexpr const char* storage_order_entry = "storage_order";

/// "bodies/NAME/" with NAME the body's name ('/' replaced), or NAME_INDEX if two names would clash.
template <int Dim>
std::vector<std::string> body_prefixes(const std::vector<Body<Dim>>& bodies) {
  std::vector<std::string> out;
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    std::string name = bodies[b].name;
    std::replace(name.begin(), name.end(), '/', '_');
    if (name.empty() || name == "." || name == ".." ||
        std::find(out.begin(), out.end(), "bodies/" + name + "/") != out.end())
      name += "_" + std::to_string(b);
    out.push_back("bodies/" + name + "/");
  }
  return out;
}

/// The particle indices sorted by id.
template <int Dim>
std::vector<Index> id_order(const ParticleSet<Dim>& p) {
  std::vector<Index> order(static_cast<std::size_t>(p.size()));
  std::iota(order.begin(), order.end(), Index{0});
  std::sort(order.begin(), order.end(), [&](Index i, Index j) { return p.id[i] < p.id[j]; });
  return order;
}

ArchivedArray packed_field(const FieldLayout& layout, std::vector<std::byte> bytes, std::size_t particles) {
  ArchivedArray a;
  a.type = layout.scalar;
  a.shape = {particles};
  if (layout.components != 1 || layout.scalar == ScalarType::opaque) a.shape.push_back(layout.components);
  a.bytes = std::move(bytes);
  return a;
}

}  // namespace

namespace {

/// Rank 0: every rank's particles of `local` in one set, in the order of the scatter key (the one-process storage
/// order). Other ranks: nothing (they send theirs). A collective call.
template <int Dim>
std::optional<ParticleSet<Dim>> gather_on_rank_0(const ParticleSet<Dim>& local, Communicator& comm) {
  std::vector<std::vector<std::byte>> out(static_cast<std::size_t>(comm.size()));
  if (comm.rank() != 0) {
    std::vector<Index> all(static_cast<std::size_t>(local.size()));
    std::iota(all.begin(), all.end(), Index{0});
    const auto count = static_cast<std::int64_t>(all.size());
    out[0].resize(sizeof count);
    std::memcpy(out[0].data(), &count, sizeof count);
    local.pack(all, out[0]);
  }
  const auto in = comm.all_to_all(std::move(out));
  if (comm.rank() != 0) return std::nullopt;
  ParticleSet<Dim> p = local;
  for (const auto& buffer : in) {
    if (buffer.empty()) continue;
    std::int64_t count = 0;
    std::memcpy(&count, buffer.data(), sizeof count);
    p.append_packed(std::span<const std::byte>(buffer).subspan(sizeof count), count);
  }
  const auto& key = p.template field<std::uint64_t>(scatter_key_field);
  std::vector<Index> order(static_cast<std::size_t>(p.size()));
  std::iota(order.begin(), order.end(), Index{0});
  std::sort(order.begin(), order.end(), [&](Index a, Index b) { return key[a] < key[b]; });
  p.gather(order);
  return p;
}

}  // namespace

template <int Dim>
std::vector<Body<Dim>> Simulation<Dim>::gather_bodies() const {
  std::vector<Body<Dim>> out;
  for (const auto& b : bodies_) {
    std::optional<ParticleSet<Dim>> gathered;
    if (comm_) {
      gathered = gather_on_rank_0(b.particles, *comm_);
      if (!gathered) continue;
    }
    Body<Dim> copy;
    copy.name = b.name;
    copy.index = b.index;
    copy.particles = gathered ? std::move(*gathered) : b.particles;
    copy.material = b.material;
    copy.stretched_domain = b.stretched_domain;
    copy.domain_corners = b.domain_corners;
    out.push_back(std::move(copy));
  }
  return out;
}

template <int Dim>
void Simulation<Dim>::save_state(StateArchive& archive) const {
  archive.put_integer("simulation/dimension", Dim);
  archive.put_number("simulation/time", time_);
  archive.put_integer("simulation/step", step_);
  archive.put_values<Real>("simulation/wave_speed", std::span<const Real>(wave_speed_.max_speed.data(), Dim));
  archive.put_integer("simulation/wave_speed_finite", wave_speed_.finite ? 1 : 0);
  const auto prefixes = body_prefixes(bodies_);
  for (std::size_t b = 0; b < bodies_.size(); ++b) {
    std::optional<ParticleSet<Dim>> gathered;
    if (comm_) {  // a distributed run: rank 0 saves every rank's particles, the others only take part
      gathered = gather_on_rank_0(bodies_[b].particles, *comm_);
      if (!gathered) continue;
    }
    const auto& p = gathered ? *gathered : bodies_[b].particles;
    const std::vector<Index> by_id = id_order(p);
    for (const auto& layout : p.field_layout()) {
      if (layout.name == scatter_key_field) continue;  // a distributed run's own (given anew by distribute())
      if (layout.name == storage_order_entry)
        throw std::logic_error(fmt::format("a particle field may not be named '{}'", storage_order_entry));
      std::vector<std::byte> bytes;
      p.pack_field(layout.name, by_id, bytes);
      archive.put(prefixes[b] + layout.name, packed_field(layout, std::move(bytes), by_id.size()));
    }
    archive.put_values<std::uint32_t>(prefixes[b] + storage_order_entry, p.id);
  }
  for (const auto& m : hooks_.all()) m->save_state(archive, module_prefix(*m));
}

template <int Dim>
std::vector<std::string> Simulation<Dim>::restore_state(const StateArchive& archive) {
  if (const auto dim = archive.integer("simulation/dimension"); dim != Dim)
    throw ArchiveError(fmt::format("the checkpoint is of a {}D run, the scene is {}D", dim, Dim));
  std::vector<std::string> notes;
  const auto prefixes = body_prefixes(bodies_);
  const auto saved_bodies = archive.children("bodies/");
  if (saved_bodies.size() != bodies_.size())
    throw ArchiveError(fmt::format("the checkpoint has {} bodies, the scene {}", saved_bodies.size(), bodies_.size()));
  // particles may have left before the checkpoint: through an outflow face, or eroded (failure_module.hpp)
  bool removes_particles = boundary_->removes_particles();
  for (const auto& m : hooks_.all())
    if (const auto* failure = dynamic_cast<const FailureModule<Dim>*>(m.get()); failure && failure->erodes())
      removes_particles = true;
  for (std::size_t b = 0; b < bodies_.size(); ++b) {
    auto& p = bodies_[b].particles;
    const std::string& prefix = prefixes[b];
    if (!archive.contains(prefix + storage_order_entry))
      throw ArchiveError(fmt::format("the checkpoint has no body '{}'", bodies_[b].name));
    const auto storage = archive.values<std::uint32_t>(prefix + storage_order_entry);
    const bool removed = removes_particles && static_cast<Index>(storage.size()) < p.size();
    if (static_cast<Index>(storage.size()) != p.size() && !removed)
      throw ArchiveError(fmt::format("body '{}' has {} particles in the checkpoint and {} in the scene",
                                     bodies_[b].name, storage.size(), p.size()));
    p.gather(id_order(p));  // fields the checkpoint lacks then line up with the ones it restores
    if (removed) {          // particles left (outflow, erosion) before the checkpoint: keep the saved ones, by id
      std::vector<std::uint32_t> saved(storage.begin(), storage.end());
      std::sort(saved.begin(), saved.end());
      std::vector<Index> kept;
      for (const std::uint32_t id : saved) {
        const auto it = std::lower_bound(p.id.begin(), p.id.end(), id);
        if (it == p.id.end() || *it != id)
          throw ArchiveError(
              fmt::format("body '{}': the checkpoint holds particle {}, which the scene lacks", bodies_[b].name, id));
        kept.push_back(it - p.id.begin());
      }
      p.gather(kept);
    }
    const auto layout = p.field_layout();
    for (const auto& f : layout) {
      const std::string name = prefix + f.name;
      if (!archive.contains(name)) {
        notes.push_back(fmt::format("body '{}': field '{}' is not in the checkpoint; it keeps its initial value",
                                    bodies_[b].name, f.name));
        continue;
      }
      const ArchivedArray& a = archive.at(name);
      const std::uint64_t components = a.shape.size() > 1 ? a.shape[1] : 1;
      if (a.type != f.scalar || components != f.components || a.shape.empty() ||
          a.shape[0] != static_cast<std::uint64_t>(p.size()))
        throw ArchiveError(
            fmt::format("body '{}', field '{}': the checkpoint holds {} x {} {}, the run needs {} x {} {}",
                        bodies_[b].name, f.name, a.shape.empty() ? 0 : a.shape[0], components, scalar_type_name(a.type),
                        p.size(), f.components, scalar_type_name(f.scalar)));
      p.unpack_field(f.name, 0, a.bytes);
    }
    for (const auto& saved : archive.children(prefix))
      if (saved != storage_order_entry &&
          std::none_of(layout.begin(), layout.end(), [&](const FieldLayout& f) { return f.name == saved; }))
        notes.push_back(
            fmt::format("body '{}': field '{}' of the checkpoint is not used by this run", bodies_[b].name, saved));
    // The particles are now in id order; put them back in the order they were stored in.
    std::vector<Index> order(storage.size());
    for (std::size_t i = 0; i < storage.size(); ++i) {
      const auto it = std::lower_bound(p.id.begin(), p.id.end(), storage[i]);
      if (it == p.id.end() || *it != storage[i])
        throw ArchiveError(fmt::format("body '{}': the storage order names particle {}, which the checkpoint lacks",
                                       bodies_[b].name, storage[i]));
      order[i] = it - p.id.begin();
    }
    p.gather(order);
  }
  time_ = archive.number("simulation/time");
  step_ = archive.integer("simulation/step");
  const auto speed = archive.values<Real>("simulation/wave_speed");
  if (speed.size() != Dim) throw ArchiveError("simulation/wave_speed: expected one value per axis");
  for (int d = 0; d < Dim; ++d) wave_speed_.max_speed[d] = speed[d];
  wave_speed_.finite = archive.integer("simulation/wave_speed_finite") != 0;
  for (const auto& m : hooks_.all()) m->restore_state(archive, module_prefix(*m));
  near_cut_known_ = false;  // the particles moved: every body exchanges in the next step
  // The grid holds what this simulation wrote before, not the archive's step. With sparse tiles it is zeroed (its
  // pages given back) as a new simulation's, so that a restart does not write every node once; otherwise the next
  // step is dense.
  if (settings_.sparse_grid && !comm_) {
    grid_.clear();
    for (auto& body : bodies_)
      if (body.separate_grid) body.separate_grid->clear();
    active_tiles_.zeroed();
  } else {
    active_tiles_.forget();
  }
  take_snapshot();
  return notes;
}

template std::vector<Body<1>> Simulation<1>::gather_bodies() const;
template std::vector<Body<2>> Simulation<2>::gather_bodies() const;
template std::vector<Body<3>> Simulation<3>::gather_bodies() const;
template void Simulation<1>::save_state(StateArchive&) const;
template void Simulation<2>::save_state(StateArchive&) const;
template void Simulation<3>::save_state(StateArchive&) const;
template std::vector<std::string> Simulation<1>::restore_state(const StateArchive&);
template std::vector<std::string> Simulation<2>::restore_state(const StateArchive&);
template std::vector<std::string> Simulation<3>::restore_state(const StateArchive&);

}  // namespace mpm
