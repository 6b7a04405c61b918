// Outflow (boundary/grid_boundary.hpp): the particles beyond an outflow face leave their body at the end of the step,
// and their mass, momentum and energies are booked per face; the books and the first departures are module state
// (checkpoints, the stability guard's snapshots).
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <array>
#include <cstdint>

#include "mpm/boundary/grid_boundary.hpp"
#include "mpm/core/state_archive.hpp"
#include "mpm/simulation/energy_audit.hpp"

namespace mpm {

std::string OutflowNotice::message() const {
  return fmt::format(
      "body {}: {} particle{} left through {} (outflow) at step {} (t = {:.6g} s); what leaves is booked in energy.csv "
      "(columns outflow_{}_*)",
      body, particles, particles == 1 ? "" : "s", face_names[static_cast<std::size_t>(face)], step, time,
      face_names[static_cast<std::size_t>(face)]);
}

template <int Dim>
void GridBoundary<Dim>::end_of_step(StepContext<Dim>& ctx) {
  const std::size_t faces = removals_.size(), bodies = ctx.bodies.size();
  std::vector<RemovedBook> step(faces);
  std::vector<RemovedBook*> into(faces);
  for (std::size_t k = 0; k < faces; ++k) into[k] = &step[k];
  std::vector<std::int64_t> left(faces * bodies, 0);  // per (face, body)
  bool any = false;
  std::vector<std::vector<Index>> leave(faces);
  for (std::size_t b = 0; b < bodies; ++b) {
    Body<Dim>& body = ctx.bodies[b];
    const ParticleSet<Dim>& p = body.particles;
    for (auto& l : leave) l.clear();
    for (Index i = 0; i < p.size(); ++i) {
      std::size_t k = 0;
      while (k < faces && !removals_[k].beyond(p.x[i][removals_[k].axis])) ++k;
      if (k < faces) leave[k].push_back(i);
    }
    for (std::size_t k = 0; k < faces; ++k) left[k * bodies + b] += static_cast<std::int64_t>(leave[k].size());
    any = remover_.remove(body, leave, into, ctx.settings.gravity, ctx.hooks.all()) > 0 || any;
  }
  if (ctx.comm) {  // every rank's departures: the same books on every rank
    if (!ctx.comm->any(any)) return;
    reduce_books(*ctx.comm, step);
    ctx.comm->sum(std::span<std::int64_t>(left));
  } else if (!any) {
    return;
  }
  for (std::size_t k = 0; k < faces; ++k) {
    books_[k].merge(step[k]);
    for (std::size_t b = 0; b < bodies; ++b) {
      const std::int64_t count = left[k * bodies + b];
      if (count == 0) continue;
      const int face = books_[k].face;
      const std::string& name = ctx.bodies[b].name;
      if (std::any_of(notices_.begin(), notices_.end(),
                      [&](const OutflowNotice& n) { return n.face == face && n.body == name; }))
        continue;
      notices_.push_back({name, face, ctx.step, ctx.time + ctx.dt, static_cast<Index>(count)});
    }
  }
}

template <int Dim>
Real GridBoundary<Dim>::outflow_energy() const {
  ExactSum e;
  for (const auto& b : books_) b.add_total_energy(e);
  return e.value();
}

template <int Dim>
std::vector<std::string> GridBoundary<Dim>::outflow_summary() const {
  std::vector<std::string> lines;
  for (const auto& b : books_) {
    const EnergyBalance e = b.value();
    lines.push_back(
        fmt::format("outflow {}: {:.0f} particles, mass {:.6g} kg, kinetic energy {:.6g} J, total energy "
                    "{:.6g} J",
                    face_names[static_cast<std::size_t>(b.face)], b.particle_count(), e.mass, e.kinetic, e.total()));
  }
  return lines;
}

template <int Dim>
void GridBoundary<Dim>::save_state(StateArchive& archive, const std::string& prefix) const {
  if (books_.empty()) return;
  for (const auto& b : books_)
    save_book(archive, fmt::format("{}outflow/{}/", prefix, face_names[static_cast<std::size_t>(b.face)]), b);
  std::vector<std::int64_t> face, step, particles;
  std::vector<Real> time;
  std::string body;
  for (const auto& n : notices_) {
    face.push_back(n.face);
    step.push_back(n.step);
    particles.push_back(n.particles);
    time.push_back(n.time);
    body += n.body + '\n';
  }
  archive.put_values<std::int64_t>(prefix + "notices/face", face);
  archive.put_values<std::int64_t>(prefix + "notices/step", step);
  archive.put_values<std::int64_t>(prefix + "notices/particles", particles);
  archive.put_values<Real>(prefix + "notices/time", time);
  archive.put_text(prefix + "notices/body", body);
}

template <int Dim>
void GridBoundary<Dim>::restore_state(const StateArchive& archive, const std::string& prefix) {
  // A fork may change a face's condition (grid.boundary), but not which faces let material out: their books are
  // energy.csv's outflow_FACE_* columns, which the continued file has from its first row or not at all.
  std::vector<std::string> saved = archive.children(prefix + "outflow/"), now;
  for (const auto& b : books_) now.push_back(face_names[static_cast<std::size_t>(b.face)]);
  std::sort(saved.begin(), saved.end());
  std::sort(now.begin(), now.end());
  if (saved != now)
    throw ArchiveError(fmt::format(
        "the outflow faces differ: [{}] in the checkpoint, [{}] in the scene; a fork may not add or remove an "
        "outflow face (its books are energy.csv's outflow_FACE_* columns, which the checkpoint's run has or not)",
        fmt::join(saved, ", "), fmt::join(now, ", ")));
  if (books_.empty()) return;
  notices_.clear();
  for (auto& b : books_)
    restore_book(archive, fmt::format("{}outflow/{}/", prefix, face_names[static_cast<std::size_t>(b.face)]), b);
  if (!archive.contains(prefix + "notices/face")) return;
  const auto face = archive.values<std::int64_t>(prefix + "notices/face");
  const auto step = archive.values<std::int64_t>(prefix + "notices/step");
  const auto particles = archive.values<std::int64_t>(prefix + "notices/particles");
  const auto time = archive.values<Real>(prefix + "notices/time");
  const std::string body = archive.text(prefix + "notices/body");
  std::size_t begin = 0;
  for (std::size_t i = 0; i < face.size(); ++i) {
    const std::size_t end = body.find('\n', begin);
    if (end == std::string::npos || step.size() != face.size() || particles.size() != face.size() ||
        time.size() != face.size())
      throw ArchiveError(prefix + "notices: the arrays do not line up");
    notices_.push_back({body.substr(begin, end - begin), static_cast<int>(face[i]), static_cast<Index>(step[i]),
                        time[i], static_cast<Index>(particles[i])});
    begin = end + 1;
  }
}

template void GridBoundary<1>::end_of_step(StepContext<1>&);
template void GridBoundary<2>::end_of_step(StepContext<2>&);
template void GridBoundary<3>::end_of_step(StepContext<3>&);
template Real GridBoundary<1>::outflow_energy() const;
template Real GridBoundary<2>::outflow_energy() const;
template Real GridBoundary<3>::outflow_energy() const;
template std::vector<std::string> GridBoundary<1>::outflow_summary() const;
template std::vector<std::string> GridBoundary<2>::outflow_summary() const;
template std::vector<std::string> GridBoundary<3>::outflow_summary() const;
template void GridBoundary<1>::save_state(StateArchive&, const std::string&) const;
template void GridBoundary<2>::save_state(StateArchive&, const std::string&) const;
template void GridBoundary<3>::save_state(StateArchive&, const std::string&) const;
template void GridBoundary<1>::restore_state(const StateArchive&, const std::string&);
template void GridBoundary<2>::restore_state(const StateArchive&, const std::string&);
template void GridBoundary<3>::restore_state(const StateArchive&, const std::string&);

}  // namespace mpm
