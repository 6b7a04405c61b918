#pragma once
/// \file removal/removed_particles.hpp
/// Particles that leave the run, and their books: what an outflow face (boundary/grid_boundary.hpp) and erosion
/// (failure/failure_module.hpp) share. A removed particle is packed into a body of its own and audited as
/// Simulation::energy() audits every body (energy_audit.hpp: one exactly summed term per particle), so that the
/// books are the same bits for any thread count, particle order and rank count, and remaining + removed = initial
/// for mass and momentum to round-off (docs/theory.md §8, eq. 8.4).

#include <span>
#include <string>
#include <vector>

#include "mpm/parallel/communicator.hpp"
#include "mpm/particles/body.hpp"
#include "mpm/simulation/energy.hpp"
#include "mpm/simulation/module.hpp"

namespace mpm {

class StateArchive;

/// The audit of the particles removed by one cause (a face, a material's erosion) since t = 0.
struct RemovedBook {
  EnergySums sums;  ///< of the removed particles, as they were at the end of the step they left in
  ExactSum particles;
  EnergyBalance value() const { return sums.value(); }
  double particle_count() const { return particles.value(); }
  /// J: kinetic + strain + gravity potential + plastic work of what left (EnergyBalance::total()): the energy the
  /// sentinel's balance adds back (eq. 8.4).
  void add_total_energy(ExactSum& e) const;
  /// Adds `o`'s terms.
  void merge(const RemovedBook& o);
};

/// Every rank's books merged, the same on every rank (one exact sum per term).
void reduce_books(Communicator& comm, std::span<RemovedBook> books);
/// `book` as entries `prefix`TERM (state_archive.hpp; checkpoints and the guard's snapshots).
void save_book(StateArchive& archive, const std::string& prefix, const RemovedBook& book);
/// Reads what save_book wrote at `prefix`; false (and `book` empty) when the archive has no such book (a checkpoint
/// of a run without it).
bool restore_book(const StateArchive& archive, const std::string& prefix, RemovedBook& book);

/// Removes particles from bodies and books them. Keeps, per body, an empty particle set with the body's fields, into
/// which the leaving particles are packed (the same bytes as a checkpoint or a migration: particle_set.hpp).
template <int Dim>
class ParticleRemover {
 public:
  /// Removes from `body` the particles of every group (groups[k]: ascending, disjoint indices) and adds the audit
  /// of group k, under `gravity` with the shares of `modules` (heat), to *books[k]; the other particles keep their
  /// order. Returns how many particles left.
  Index remove(Body<Dim>& body, std::span<const std::vector<Index>> groups, std::span<RemovedBook* const> books,
               const Vec<Dim>& gravity, const std::vector<std::shared_ptr<Module<Dim>>>& modules);

 private:
  std::vector<ParticleSet<Dim>> empty_sets_;  ///< by body index
  std::vector<Index> stay_;
  std::vector<char> leaving_;
};

}  // namespace mpm
