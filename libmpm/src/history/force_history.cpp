// `type: force` (docs/scene-reference.md#histories): the total force on one body from everything that holds or
// pushes it — grid faces, rigid planes and bodies, other bodies (through the contact module or through a shared
// velocity field), damping — at every interval, whether or not it touches anything. Measured as the body's rate of
// change of linear momentum less its loads (gravity and body forces): per step,
//   F dt = Σ_p m_p (v_p^{n+1} − v_p^n) − dt Σ_p m_p (g + b_p),
// the particle momenta summed exactly (so the row is the same for any particle order, thread and rank count). The
// internal forces of a body sum to zero over its nodes (partition of unity, Σ_I ∇N_I = 0), so what is left is
// what the rest of the world did; the reaction histories measure the same forces from the other side (the nodal
// forces of a face, the contact corrections), and the tests hold the two against each other.
#include <fmt/format.h>

#include <span>

#include "history_support.hpp"
#include "mpm/core/exact_sum.hpp"
#include "mpm/particles/field_keys.hpp"
#include "mpm/sets/particle_sets.hpp"

namespace mpm::history {
namespace {
// The helpers are named in a namespace of this file's own, so that the folder's sources also compile as
// one translation unit (scripts/tidy.sh).
namespace body_force {

struct ForceSpec {
  std::vector<int> bodies;  ///< the body, or the set's bodies
  std::uint32_t mask = 0;   ///< a particle set's bit (`set:`); 0: every particle of the body
};

std::any parse(const YamlReader& reader, const YamlMap& entry, const SceneDescription& scene) {
  ForceSpec s;
  const auto body = entry.find("body"), set = entry.find("set");
  if ((body ? 1 : 0) + (set ? 1 : 0) != 1)
    reader.fail(entry.self().mark, entry.self().path, "give exactly one of body and set (a particle set)");
  if (body) {
    s.bodies = {read_body(reader, *body, scene)};
  } else {
    const int k = read_set(reader, *set, scene);
    s.mask = set_bit(k);
    s.bodies = scene.sets[static_cast<std::size_t>(k)].bodies;
    if (s.bodies.empty())
      for (int b = 0; b < static_cast<int>(scene.bodies.size()); ++b) s.bodies.push_back(b);
  }
  return s;
}

/// The body's momentum at the start of each step and after its particle update, and the impulse since the last
/// row. The particle update is final after the stress update of every explicit scheme (after_stress), before
/// erosion and outflow remove particles at the end of the step; a scheme that has no such phase (implicit)
/// removes none, and is measured at the end of the step.
template <int Dim>
class ForceRecorder final : public Module<Dim> {
 public:
  ForceRecorder(std::vector<int> bodies, std::uint32_t mask) : bodies_(std::move(bodies)), mask_(mask) {}
  std::string_view name() const override { return "force history"; }
  std::string why_not_distributed() const override { return {}; }  // exact sums reduced over the ranks
  unsigned phases() const override { return phase_before_step | phase_after_stress | phase_end_of_step; }

  void before_step(StepContext<Dim>& ctx) override {
    start_ = momentum(ctx);
    measured_ = false;
  }
  void after_stress(StepContext<Dim>& ctx) override {
    measure(ctx);
    measured_ = true;
  }
  void end_of_step(StepContext<Dim>& ctx) override {
    if (!measured_) measure(ctx);
  }

  /// The mean force since the last call (zero before the first step), and a new interval.
  Vec<Dim> take_mean() {
    Vec<Dim> mean = span_ > 0 ? Vec<Dim>(impulse_ / span_) : Vec<Dim>::Zero();
    impulse_.setZero();
    span_ = 0;
    return mean;
  }
  void save(StateArchive& archive, const std::string& prefix) const {
    archive.put_values<Real>(prefix + "impulse", std::span<const Real>(impulse_.data(), Dim));
    archive.put_number(prefix + "span", span_);
  }
  void restore(const StateArchive& archive, const std::string& prefix) {
    const auto impulse = archive.values<Real>(prefix + "impulse");
    if (impulse.size() != Dim)
      throw ArchiveError("'" + prefix + "impulse': not a force history's impulse of this dimension");
    for (int d = 0; d < Dim; ++d) impulse_[d] = impulse[d];
    span_ = archive.number(prefix + "span");
  }

 private:
  /// Σ m v, then Σ m (g + b) (the loads), each component summed exactly and reduced over the ranks.
  /// Σ m v (Dim values), then Σ m (g + b) (Dim values).
  static constexpr std::size_t parts = 2 * static_cast<std::size_t>(Dim);

  std::array<Real, parts> momentum(StepContext<Dim>& ctx) const {
    std::array<ExactSum, parts> sums;
    for (const int body : bodies_) {
      const auto& p = ctx.bodies[static_cast<std::size_t>(body)].particles;
      const VecU<Dim>* b = p.has_field(keys::body_force<Dim>) ? p.field(keys::body_force<Dim>).data() : nullptr;
      const std::uint32_t* sets = mask_ != 0 ? p.field(keys::particle_sets).data() : nullptr;
      for (Index i = 0; i < p.size(); ++i) {
        if (sets && (sets[i] & mask_) == 0) continue;
        for (int d = 0; d < Dim; ++d) {
          sums[d] += p.mass[i] * p.v[i][d];
          sums[Dim + d] += p.mass[i] * (ctx.settings.gravity[d] + (b ? b[i][d] : 0));
        }
      }
    }
    if (ctx.comm) ctx.comm->sum(sums);
    std::array<Real, parts> out;
    for (std::size_t k = 0; k < parts; ++k) out[k] = sums[k].value();
    return out;
  }
  void measure(StepContext<Dim>& ctx) {
    const auto end = momentum(ctx);
    // the loads of this step (a body-force module sets b for the step in its own before_step)
    for (int d = 0; d < Dim; ++d) impulse_[d] += (end[d] - start_[d]) - ctx.dt * end[Dim + d];
    span_ += ctx.dt;
  }

  std::vector<int> bodies_;
  std::uint32_t mask_;
  std::array<Real, parts> start_{};
  bool measured_ = false;
  Vec<Dim> impulse_ = Vec<Dim>::Zero();  ///< N s since the last row
  Real span_ = 0;                        ///< s
};

template <int Dim>
class ForceHistory final : public History<Dim> {
 public:
  ForceHistory(std::shared_ptr<ForceRecorder<Dim>> recorder, Coordinates coordinates)
      : recorder_(std::move(recorder)), coordinates_(coordinates) {}
  std::vector<std::string> columns() const override {
    std::vector<std::string> names;
    names.reserve(Dim);
    for (int d = 0; d < Dim; ++d)
      names.push_back(column_name(fmt::format("force_{}", "xyz"[d]), extensive_unit("N", Dim, coordinates_)));
    return names;
  }
  void sample(const Simulation<Dim>&, OutputFieldCache<Dim>&, std::vector<double>& row) override {
    const Vec<Dim> mean = recorder_->take_mean();
    for (int d = 0; d < Dim; ++d) row.push_back(mean[d]);
  }
  void save_state(StateArchive& archive, const std::string& prefix) const override { recorder_->save(archive, prefix); }
  void restore_state(const StateArchive& archive, const std::string& prefix) override {
    recorder_->restore(archive, prefix);
  }

 private:
  std::shared_ptr<ForceRecorder<Dim>> recorder_;
  Coordinates coordinates_;
};

template <int Dim>
std::unique_ptr<History<Dim>> make(const HistoryDescription& h, const SceneDescription& scene, Simulation<Dim>& sim,
                                   std::vector<std::string>&) {
  const auto& s = std::any_cast<const ForceSpec&>(h.spec);
  auto recorder = std::make_shared<ForceRecorder<Dim>>(s.bodies, s.mask);
  sim.add_module(recorder);
  return std::make_unique<ForceHistory<Dim>>(std::move(recorder), scene.grid.coordinates);
}

}  // namespace body_force
}  // namespace

HistoryKind force_kind() {
  using namespace body_force;
  return history_kind(
      "force",
      "the total force on a body or a particle set from supports, contact and other bodies (its rate of change of "
      "momentum less gravity and body forces), mean over the interval, at every interval",
      {"body", "set"}, parse, make<1>, make<2>, make<3>);
}

}  // namespace mpm::history
