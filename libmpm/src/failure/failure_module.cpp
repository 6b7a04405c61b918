// Failure and erosion at the end of every step (failure/failure_module.hpp).
#include "mpm/failure/failure_module.hpp"

#include <fmt/format.h>

#include <Eigen/Eigenvalues>
#include <cmath>

#include "mpm/core/state_archive.hpp"
#include "mpm/particles/field_keys.hpp"
#include "mpm/schemes/axisymmetric.hpp"

namespace mpm {

template <int Dim>
FailureModule<Dim>::FailureModule(std::vector<BodyFailure> bodies, Real cfl) : bodies_(std::move(bodies)), cfl_(cfl) {
  for (const auto& b : bodies_) {
    FailureBooks books;
    books.body = b.body;
    books_.push_back(books);
  }
}

template <int Dim>
bool FailureModule<Dim>::erodes() const {
  for (const auto& b : bodies_)
    if (b.criteria.action == FailureAction::erode) return true;
  return false;
}

template <int Dim>
void FailureModule<Dim>::measure(const Body<Dim>& body, const FailureCriteria& c, const GridGeometry<Dim>& g) {
  const ParticleSet<Dim>& p = body.particles;
  const auto n = static_cast<std::size_t>(p.size());
  measures_.assign(n, FailureMeasures{});
  const Material<Dim>& material = *body.material;
  const auto read = [&](const char* field, Real FailureMeasures::*member) {
    values_.clear();
    if (!material.append_output(field, p, values_) || values_.size() != n)
      throw std::logic_error(fmt::format("failure: the material of body '{}' gives no {}", body.name, field));
    for (std::size_t i = 0; i < n; ++i) measures_[i].*member = values_[i];
  };
  if (c.needs_damage()) read("damage", &FailureMeasures::damage);
  if (c.needs_plastic_strain()) read("plastic_strain", &FailureMeasures::plastic_strain);
  const Real* hoop = axisym::hoop_stretch_of(p);
  if (c.needs_time_step() && !material.particle_wave_speeds(p, wave_speed_))
    throw std::logic_error(fmt::format("failure: the material of body '{}' gives no wave speed", body.name));
  for (std::size_t k = 0; k < n; ++k) {
    const auto i = static_cast<Index>(k);
    FailureMeasures& m = measures_[k];
    m.volume_ratio = axisym::volume_ratio(p, i, hoop);
    const SymTensor<Dim>& s = p.stress[i];
    m.mean_stress = (s.c[0] + s.c[1] + s.c[2]) / 3;
    if (c.needs_principal_strain()) {
      // ln(lambda_max), lambda^2 the eigenvalues of b = F F^T; the out-of-plane stretch is F_tt (axisymmetric) or 1
      const Mat<Dim> F = p.F[i];
      const Mat<Dim> b = F * F.transpose();
      const Real largest = Eigen::SelfAdjointEigenSolver<Mat<Dim>>(b, Eigen::EigenvaluesOnly).eigenvalues().maxCoeff();
      Real stretch = std::sqrt(std::max(largest, Real(0)));
      if constexpr (Dim < 3) stretch = std::max(stretch, hoop ? hoop[i] : Real(1));
      m.principal_strain = std::log(stretch);
    }
    if (c.needs_principal_stress())
      m.principal_stress =
          Eigen::SelfAdjointEigenSolver<Mat3>(s.full(), Eigen::EigenvaluesOnly).eigenvalues().maxCoeff();
    if (c.needs_time_step()) {
      Real dt = std::numeric_limits<Real>::infinity();
      for (int d = 0; d < Dim; ++d) dt = std::min(dt, g.h[d] / (wave_speed_[k] + std::abs(p.v[i][d])));
      m.time_step = cfl_ * dt;
    }
  }
}

template <int Dim>
void FailureModule<Dim>::end_of_step(StepContext<Dim>& ctx) {
  std::vector<RemovedBook> step(bodies_.size());
  std::vector<std::int64_t> counts(bodies_.size() * (failure_criterion_count + 1), 0);
  bool any = false, eroded = false;
  for (std::size_t k = 0; k < bodies_.size(); ++k) {
    const BodyFailure& bf = bodies_[k];
    Body<Dim>& body = ctx.bodies[static_cast<std::size_t>(bf.body)];
    ParticleSet<Dim>& p = body.particles;
    if (p.size() == 0) continue;
    measure(body, bf.criteria, ctx.grid.geometry);
    const auto& failed = p.field(keys::failed);
    fail_.clear();
    erode_.clear();
    std::int64_t* count = counts.data() + k * (failure_criterion_count + 1);
    for (Index i = 0; i < p.size(); ++i) {
      if (failed[static_cast<std::size_t>(i)] != 0) continue;  // already carries only pressure
      const auto criterion = first_met(bf.criteria, measures_[static_cast<std::size_t>(i)]);
      if (!criterion) continue;
      ++count[static_cast<int>(*criterion)];
      (bf.criteria.action == FailureAction::erode ? erode_ : fail_).push_back(i);
    }
    if (!fail_.empty()) {
      body.material->mark_failed(p, fail_);
      count[failure_criterion_count] += static_cast<std::int64_t>(fail_.size());
      any = true;
    }
    if (!erode_.empty()) {
      RemovedBook* into = &step[k];
      remover_.remove(body, std::span<const std::vector<Index>>(&erode_, 1), std::span<RemovedBook* const>(&into, 1),
                      ctx.settings.gravity, ctx.hooks.all());
      any = eroded = true;
    }
  }
  if (ctx.comm) {  // every rank's failures: the same books on every rank
    const std::array<bool, 2> flags{any, eroded};
    any = ctx.comm->any(flags[0]);
    if (!any) return;
    eroded = ctx.comm->any(flags[1]);
    reduce_books(*ctx.comm, step);
    ctx.comm->sum(std::span<std::int64_t>(counts));
  } else if (!any) {
    return;
  }
  for (std::size_t k = 0; k < bodies_.size(); ++k) {
    books_[k].eroded.merge(step[k]);
    const std::int64_t* count = counts.data() + k * (failure_criterion_count + 1);
    for (int c = 0; c < failure_criterion_count; ++c) books_[k].failed_by[static_cast<std::size_t>(c)] += count[c];
    books_[k].failed_in_place += count[failure_criterion_count];
  }
  if (eroded) {  // the next time step is the remaining particles' (the same formula on every rank)
    WaveSpeedBound<Dim> bound;
    for (const auto& b : ctx.bodies) bound.merge(b.material->wave_speed_bound(b.particles));
    ctx.wave_speed.max_speed = bound.max_speed;
  }
}

template <int Dim>
Real FailureModule<Dim>::removed_energy() const {
  ExactSum e;
  for (const auto& b : books_) b.eroded.add_total_energy(e);
  return e.value();
}

template <int Dim>
RemovedBook FailureModule<Dim>::eroded() const {
  RemovedBook all;
  for (const auto& b : books_) all.merge(b.eroded);
  return all;
}

template <int Dim>
std::vector<std::string> FailureModule<Dim>::summary(const std::vector<std::string>& body_names) const {
  std::vector<std::string> lines;
  for (const auto& b : books_) {
    std::string by;
    for (int c = 0; c < failure_criterion_count; ++c)
      if (const std::int64_t n = b.failed_by[static_cast<std::size_t>(c)]; n > 0)
        by += fmt::format("{}{} {}", by.empty() ? "" : ", ", criterion_name(static_cast<FailureCriterion>(c)), n);
    if (by.empty()) continue;
    const EnergyBalance e = b.eroded.value();
    lines.push_back(
        fmt::format("failure of body '{}': {} particles eroded, {} carry only pressure ({}); eroded mass "
                    "{:.6g} kg, kinetic energy {:.6g} J, total energy {:.6g} J",
                    body_names.at(static_cast<std::size_t>(b.body)), b.eroded.particle_count(), b.failed_in_place, by,
                    e.mass, e.kinetic, e.total()));
  }
  return lines;
}

template <int Dim>
void FailureModule<Dim>::save_state(StateArchive& archive, const std::string& prefix) const {
  for (const auto& b : books_) {
    const std::string name = fmt::format("{}body_{}/", prefix, b.body);
    save_book(archive, name + "eroded/", b.eroded);
    std::vector<std::int64_t> counts(b.failed_by.begin(), b.failed_by.end());
    counts.push_back(b.failed_in_place);
    archive.put_values<std::int64_t>(name + "failed_by", counts);
  }
}

template <int Dim>
void FailureModule<Dim>::restore_state(const StateArchive& archive, const std::string& prefix) {
  for (auto& b : books_) {
    const std::string name = fmt::format("{}body_{}/", prefix, b.body);
    restore_book(archive, name + "eroded/", b.eroded);
    b.failed_by = {};
    b.failed_in_place = 0;
    if (!archive.contains(name + "failed_by")) continue;
    const auto counts = archive.values<std::int64_t>(name + "failed_by");
    if (counts.size() != failure_criterion_count + 1)
      throw ArchiveError(
          fmt::format("{}failed_by: expected {} values, found {}", name, failure_criterion_count + 1, counts.size()));
    std::copy(counts.begin(), counts.end() - 1, b.failed_by.begin());
    b.failed_in_place = counts.back();
  }
}

template class FailureModule<1>;
template class FailureModule<2>;
template class FailureModule<3>;

}  // namespace mpm
