// Removed particles and their books (removal/removed_particles.hpp): outflow faces and erosion.
#include "mpm/removal/removed_particles.hpp"

#include <fmt/format.h>

#include <array>
#include <cstdint>

#include "mpm/core/state_archive.hpp"
#include "mpm/simulation/energy_audit.hpp"

namespace mpm {
namespace {

/// The terms of a book in a fixed order (for the reduction over the ranks and the archive).
constexpr int book_terms = 10;
std::array<ExactSum*, book_terms> terms_of(RemovedBook& b) {
  auto& s = b.sums;
  return {&s.kinetic, &s.strain,      &s.gravity,     &s.plastic_work, &s.thermal,
          &s.mass,    &s.momentum[0], &s.momentum[1], &s.momentum[2],  &b.particles};
}
constexpr std::array<const char*, book_terms> term_names{"kinetic",    "strain",   "gravity",    "plastic_work",
                                                         "thermal",    "mass",     "momentum_x", "momentum_y",
                                                         "momentum_z", "particles"};

void put_exact(StateArchive& archive, const std::string& name, const ExactSum& s) {
  const ExactSum::Digits digits = s.carried_digits();
  archive.put_values<std::int64_t>(name + "/digits", std::span<const std::int64_t>(digits.data(), digits.size()));
  archive.put_number(name + "/special", s.special());
}

ExactSum exact(const StateArchive& archive, const std::string& name) {
  const auto values = archive.values<std::int64_t>(name + "/digits");
  ExactSum::Digits digits{};
  if (values.size() != digits.size())
    throw ArchiveError(fmt::format("{}/digits: expected {} values, found {}", name, digits.size(), values.size()));
  std::copy(values.begin(), values.end(), digits.begin());
  return ExactSum::from_digits(digits, archive.number(name + "/special"));
}

}  // namespace

void RemovedBook::add_total_energy(ExactSum& e) const {
  e.merge(sums.kinetic);
  e.merge(sums.strain);
  e.merge(sums.gravity);
  e.merge(sums.plastic_work);
}

void RemovedBook::merge(const RemovedBook& o) {
  sums.merge(o.sums);
  particles.merge(o.particles);
}

void reduce_books(Communicator& comm, std::span<RemovedBook> books) {
  std::vector<ExactSum> all;
  all.reserve(books.size() * book_terms);
  for (auto& b : books)
    for (ExactSum* term : terms_of(b)) all.push_back(*term);
  comm.sum(std::span<ExactSum>(all));
  std::size_t j = 0;
  for (auto& b : books)
    for (ExactSum* term : terms_of(b)) *term = all[j++];
}

void save_book(StateArchive& archive, const std::string& prefix, const RemovedBook& book) {
  RemovedBook copy = book;
  const auto terms = terms_of(copy);
  for (int t = 0; t < book_terms; ++t)
    put_exact(archive, prefix + term_names[static_cast<std::size_t>(t)], *terms[static_cast<std::size_t>(t)]);
}

bool restore_book(const StateArchive& archive, const std::string& prefix, RemovedBook& book) {
  book = {};
  if (!archive.contains(prefix + "mass/digits")) return false;
  const auto terms = terms_of(book);
  for (int t = 0; t < book_terms; ++t)
    *terms[static_cast<std::size_t>(t)] = exact(archive, prefix + term_names[static_cast<std::size_t>(t)]);
  return true;
}

template <int Dim>
Index ParticleRemover<Dim>::remove(Body<Dim>& body, std::span<const std::vector<Index>> groups,
                                   std::span<RemovedBook* const> books, const Vec<Dim>& gravity,
                                   const std::vector<std::shared_ptr<Module<Dim>>>& modules) {
  ParticleSet<Dim>& p = body.particles;
  Index count = 0;
  for (const auto& g : groups) count += static_cast<Index>(g.size());
  if (count == 0) return 0;
  const auto b = static_cast<std::size_t>(body.index);
  if (empty_sets_.size() <= b) empty_sets_.resize(b + 1);
  ParticleSet<Dim>& empty = empty_sets_[b];
  if (empty.field_layout().size() != p.field_layout().size()) {  // once per body: the body's fields, no particle
    empty = p;
    empty.gather({});
  }
  leaving_.assign(static_cast<std::size_t>(p.size()), 0);
  for (std::size_t k = 0; k < groups.size(); ++k) {
    if (groups[k].empty()) continue;
    Body<Dim> gone;  // the leaving particles as a body of their own, audited as Simulation::energy() audits
    gone.name = body.name;
    gone.index = body.index;
    gone.material = body.material;
    gone.particles = empty;
    std::vector<std::byte> bytes;
    p.pack(groups[k], bytes);
    gone.particles.append_packed(bytes, static_cast<Index>(groups[k].size()));
    add_body_energy(gone, gravity, modules, books[k]->sums);
    books[k]->particles += static_cast<double>(groups[k].size());
    for (const Index i : groups[k]) leaving_[static_cast<std::size_t>(i)] = 1;
  }
  stay_.clear();
  for (Index i = 0; i < p.size(); ++i)
    if (!leaving_[static_cast<std::size_t>(i)]) stay_.push_back(i);
  p.gather(stay_);
  return count;
}

template class ParticleRemover<1>;
template class ParticleRemover<2>;
template class ParticleRemover<3>;

}  // namespace mpm
