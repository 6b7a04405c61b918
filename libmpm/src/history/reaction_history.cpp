// `type: reaction` (docs/scene-reference.md#histories): the force (and moment about a point) that a grid face
// with a velocity condition, a rigid plane or a rigid body exerts on the bodies, as the mean over the interval
// since the previous row (impulse / time). Faces: from the nodal forces of every step on the constrained nodes
// (GridBoundary::reactions), summed exactly; planes and rigid bodies: from the module that holds them
// (reaction_provider.hpp; contact/). The accumulation is a module built only for a reaction history.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <Eigen/Geometry>

#include "history_support.hpp"
#include "mpm/boundary/face_condition_kind.hpp"
#include "mpm/core/closest_name.hpp"
#include "mpm/core/exact_sum.hpp"
#include "mpm/simulation/reaction_provider.hpp"

namespace mpm::history {
namespace {
// The helpers are named in a namespace of this file's own, so that the folder's sources also compile as
// one translation unit (scripts/tidy.sh).
namespace reaction {

struct ReactionSpec {
  int face = -1;            ///< a grid face (order of GridDescription::face_names), or -1
  int on = -1;              ///< `on:` the force the contact exerts on this body (its index), or -1
  std::string from;         ///< with `on`: only the force from this partner (a body or a rigid plane)
  std::string partner;      ///< a rigid plane's or rigid body's name (`plane:` / `body:`), when face < 0
  std::string partner_key;  ///< "plane" or "body", for messages
  std::optional<std::array<double, 3>> moment_about;  ///< m
};

std::any parse(const YamlReader& reader, const YamlMap& entry, const SceneDescription& scene) {
  ReactionSpec s;
  const auto face = entry.find("face"), plane = entry.find("plane"), body = entry.find("body"), on = entry.find("on"),
             from = entry.find("from"), set = entry.find("set");
  if ((face ? 1 : 0) + (plane ? 1 : 0) + (body ? 1 : 0) + (on ? 1 : 0) + (set ? 1 : 0) != 1)
    reader.fail(entry.self().mark, entry.self().path,
                "give exactly one of face (a grid face with a velocity condition), plane (a rigid plane), body (a "
                "rigid body), set (a particle set with a velocity condition) or on (the contact force on a body)");
  if (from && !on) reader.fail(*from, "from is for the contact force on a body (on: BODY, from: PARTNER)");
  if (on) {
    s.on = read_body(reader, *on, scene);
    if (from) {
      s.from = reader.name(*from);
      if (s.from == scene.bodies[static_cast<std::size_t>(s.on)].name)
        reader.fail(*from, fmt::format("a body exerts no contact force on itself ('{}')", s.from));
    }
  } else if (face) {
    std::vector<std::string> faces(
        GridDescription::face_names.begin(),
        GridDescription::face_names.begin() + 2 * static_cast<std::ptrdiff_t>(scene.dimension));
    const std::string name = reader.choice(*face, faces);
    s.face = static_cast<int>(std::find(faces.begin(), faces.end(), name) - faces.begin());
    if (!face_traits(scene.grid.boundary[static_cast<std::size_t>(s.face)]).holds_velocity)
      reader.fail(*face, fmt::format("face {} has no velocity condition (grid.boundary.{}: fixed, slip or a "
                                     "velocity), so nothing holds the bodies there",
                                     name, name));
  } else if (set) {
    const int k = read_set(reader, *set, scene);
    const bool held = std::any_of(scene.conditions.begin(), scene.conditions.end(), [&](const auto& c) {
      return c.set == k &&
             std::any_of(c.velocity.begin(), c.velocity.end(), [](const auto& v) { return v.has_value(); });
    });
    s.partner = scene.sets[static_cast<std::size_t>(k)].name;
    s.partner_key = "set";
    if (!held)
      reader.fail(*set, fmt::format("set '{}' has no velocity condition (conditions: [{{set: {}, velocity: [...]}}]), "
                                    "so nothing holds it",
                                    s.partner, s.partner));
  } else if (plane) {
    s.partner = reader.name(*plane);
    s.partner_key = "plane";
  } else {
    s.partner = scene.bodies[static_cast<std::size_t>(read_body(reader, *body, scene))].name;
    s.partner_key = "body";
  }
  if (const auto about = entry.find("moment_about")) {
    if (scene.dimension == 1) reader.fail(*about, "a 1D run has no moment");
    if (scene.grid.coordinates == Coordinates::axisymmetric)  // the rings' forces: an axial resultant on the axis
      reader.fail(*about,
                  "an axisymmetric run has no moment: the forces of a full revolution have an axial "
                  "resultant on the axis, with no moment about any point");
    s.moment_about = reader.vector(*about, scene.dimension, io::Range::any(), "m");
  }
  return s;
}

/// The impulse of the reaction since the last row, accumulated every step.
template <int Dim>
class ReactionRecorder final : public Module<Dim> {
 public:
  /// `on` >= 0: the contact force on body `on` from `partner` (-1: all), else partner `partner`'s reaction.
  ReactionRecorder(int face, const ReactionProvider<Dim>* provider, int partner, const Vec3& about, int on = -1)
      : face_(face), provider_(provider), partner_(partner), about_(about), on_(on) {}
  /// A face's: the share 1 − α of the condition's impulse on the mapped velocities that the particles take
  /// (α the FLIP fraction; 0 for APIC and PolyPIC, whose particle velocity is Σ N v~).
  void set_pic_share(Real share) { pic_share_ = share; }
  std::string_view name() const override { return "reaction history"; }
  /// A face's reaction is summed over the nodes this rank owns and reduced; a partner's is the contact module's,
  /// the same on every rank.
  std::string why_not_distributed() const override { return {}; }
  unsigned phases() const override { return face_ >= 0 ? phase_grid_velocity : phase_end_of_step; }

  void on_grid_velocity(StepContext<Dim>& ctx, GridStage stage) override {
    if (stage == GridStage::mapped) {  // the momentum the condition sets on v(t): theory eq. 13.2
      mapped_ = {};
      if (pic_share_ > 0)
        mapped_ = face_sum(ctx, [&](const auto& f) {
          ctx.boundary.mapped_impulses(face_, ctx.grid.node, ctx.settings.mass_cutoff, ctx.time, f, ctx.active_nodes);
        });
      return;
    }
    if (stage != GridStage::updated) return;  // the nodal forces of the step are final here in every scheme
    Reaction<Dim> step = face_sum(ctx, [&](const auto& f) {  // eq. 13.1
      ctx.boundary.reactions(face_, ctx.grid.node, ctx.settings.gravity, ctx.settings.mass_cutoff, ctx.time, ctx.dt, f,
                             ctx.active_nodes);
    });
    // What the particles take of the mapped stage's impulse (none with FLIP): a force over the step.
    step.force += pic_share_ / ctx.dt * mapped_.force;
    step.first_moment += pic_share_ / ctx.dt * mapped_.first_moment;
    accumulate(step, ctx.dt);
  }

  void end_of_step(StepContext<Dim>& ctx) override {
    Reaction<Dim> step = on_ >= 0 ? provider_->last_contact_force(on_, partner_) : provider_->last_reaction(partner_);
    Vec3 f = Vec3::Zero();
    f.template head<Dim>() = step.force;
    step.first_moment -= about_.cross(f);  // about the point instead of the origin
    accumulate(step, ctx.dt);
  }

  /// The impulse accumulated since the last row, for a checkpoint (History::save_state, under the history's
  /// own name: the recorders of several reaction histories share one module name, so not Module::save_state).
  void save_impulse(StateArchive& archive, const std::string& prefix) const {
    archive.put_values<Real>(prefix + "impulse_force", std::span<const Real>(impulse_.force.data(), Dim));
    archive.put_values<Real>(prefix + "impulse_moment", std::span<const Real>(impulse_.first_moment.data(), 3));
    archive.put_number(prefix + "span", span_);
  }
  void restore_impulse(const StateArchive& archive, const std::string& prefix) {
    const auto force = archive.values<Real>(prefix + "impulse_force");
    const auto moment = archive.values<Real>(prefix + "impulse_moment");
    if (force.size() != Dim || moment.size() != 3)
      throw ArchiveError("'" + prefix + "impulse_force': not a reaction history's impulse of this dimension");
    for (int d = 0; d < Dim; ++d) impulse_.force[d] = force[d];
    for (int k = 0; k < 3; ++k) impulse_.first_moment[k] = moment[k];
    span_ = archive.number(prefix + "span");
  }

  /// The mean force and moment since the last call (zero before the first step), and a new interval.
  Reaction<Dim> take_mean() {
    Reaction<Dim> mean;
    if (span_ > 0) {
      mean.force = impulse_.force / span_;
      mean.first_moment = impulse_.first_moment / span_;
    }
    impulse_ = {};
    span_ = 0;
    return mean;
  }

 private:
  /// Σ_I of the values `each` reports (node, component, value) over the face's nodes this rank owns, and their
  /// moment about the history's point, summed exactly and reduced over the ranks.
  template <class Each>
  Reaction<Dim> face_sum(StepContext<Dim>& ctx, Each&& each) const {
    std::array<ExactSum, Dim> force;
    std::array<ExactSum, 3> moment;
    const auto& g = ctx.grid.geometry;
    each(std::function<void(Index, int, Real)>([&](Index n, int c, Real R) {
      if (!ctx.owned_nodes.contains(n)) return;
      force[c] += R;
      Vec3 r = Vec3::Zero(), f = Vec3::Zero();
      r.template head<Dim>() = g.node_position(g.node_indices(n));
      r -= about_;
      f[c] = R;
      const Vec3 m = r.cross(f);
      for (int k = 0; k < 3; ++k) moment[k] += m[k];
    }));
    if (ctx.comm) {  // every rank's nodes
      std::array<ExactSum, Dim + 3> all;
      std::copy(force.begin(), force.end(), all.begin());
      std::copy(moment.begin(), moment.end(), all.begin() + Dim);
      ctx.comm->sum(all);
      std::copy(all.begin(), all.begin() + Dim, force.begin());
      std::copy(all.begin() + Dim, all.end(), moment.begin());
    }
    Reaction<Dim> sum;
    for (int d = 0; d < Dim; ++d) sum.force[d] = force[d].value();
    for (int k = 0; k < 3; ++k) sum.first_moment[k] = moment[k].value();
    return sum;
  }

  void accumulate(const Reaction<Dim>& step, Real dt) {
    impulse_.force += dt * step.force;
    impulse_.first_moment += dt * step.first_moment;
    span_ += dt;
  }

  int face_;
  const ReactionProvider<Dim>* provider_;
  int partner_;
  Vec3 about_;
  int on_;
  Real pic_share_ = 0;     ///< 1 − α: the share of the mapped stage's impulse the particles take (eq. 13.2)
  Reaction<Dim> mapped_;   ///< that impulse in the current step (N s; its moment about the history's point)
  Reaction<Dim> impulse_;  ///< N s (the moment about the history's point)
  Real span_ = 0;          ///< s
};

template <int Dim>
class ReactionHistory final : public History<Dim> {
 public:
  ReactionHistory(std::shared_ptr<ReactionRecorder<Dim>> recorder, bool moment, Coordinates coordinates)
      : recorder_(std::move(recorder)), moment_(moment), coordinates_(coordinates) {}

  std::vector<std::string> columns() const override {
    std::vector<std::string> names;
    names.reserve(Dim + 3);
    const char* axis[] = {"x", "y", "z"};
    for (int d = 0; d < Dim; ++d)
      names.push_back(column_name(std::string("force_") + axis[d], extensive_unit("N", Dim, coordinates_)));
    if (moment_) {
      for (int k = Dim == 2 ? 2 : 0; k < 3; ++k)
        names.push_back(column_name(std::string("moment_") + axis[k], extensive_unit("N m", Dim, coordinates_)));
    }
    return names;
  }

  void sample(const Simulation<Dim>&, OutputFieldCache<Dim>&, std::vector<double>& row) override {
    const Reaction<Dim> mean = recorder_->take_mean();
    for (int d = 0; d < Dim; ++d) row.push_back(mean.force[d]);
    if (moment_)
      for (int k = Dim == 2 ? 2 : 0; k < 3; ++k) row.push_back(mean.first_moment[k]);
  }
  void save_state(StateArchive& archive, const std::string& prefix) const override {
    recorder_->save_impulse(archive, prefix);
  }
  void restore_state(const StateArchive& archive, const std::string& prefix) override {
    recorder_->restore_impulse(archive, prefix);
  }

 private:
  std::shared_ptr<ReactionRecorder<Dim>> recorder_;
  bool moment_;
  Coordinates coordinates_;
};

/// The recorder of the contact force on body s.on (from s.from, or from every partner).
template <int Dim>
std::shared_ptr<ReactionRecorder<Dim>> contact_force_recorder(const HistoryDescription& h, const ReactionSpec& s,
                                                              const Simulation<Dim>& sim, const Vec3& about) {
  for (const auto& m : sim.modules()) {
    const auto* provider = dynamic_cast<const ReactionProvider<Dim>*>(m.get());
    if (!provider || provider->contact_partners().empty()) continue;
    const auto names = provider->contact_partners();
    int partner = -1;
    if (!s.from.empty()) {
      const auto it = std::find(names.begin(), names.end(), s.from);
      if (it == names.end())
        fail(h, "from",
             fmt::format("no body or rigid plane named '{}'{}; bodies and planes: {}", s.from,
                         did_you_mean(s.from, names), fmt::join(names, ", ")));
      partner = static_cast<int>(it - names.begin());
    }
    return std::make_shared<ReactionRecorder<Dim>>(-1, provider, partner, about, s.on);
  }
  fail(h, "on",
       "the contact force on a body needs a contact: section (without one the bodies share one velocity field "
       "and no force between them is defined)");
}

template <int Dim>
std::unique_ptr<History<Dim>> make(const HistoryDescription& h, const SceneDescription& scene, Simulation<Dim>& sim,
                                   std::vector<std::string>&) {
  const auto& s = std::any_cast<const ReactionSpec&>(h.spec);
  Vec3 about = Vec3::Zero();
  if (s.moment_about)
    for (int d = 0; d < Dim; ++d) about[d] = (*s.moment_about)[d];
  std::shared_ptr<ReactionRecorder<Dim>> recorder;
  if (s.face >= 0) {
    recorder = std::make_shared<ReactionRecorder<Dim>>(s.face, nullptr, 0, about);
    recorder->set_pic_share(scene.solver.velocity_transfer == VelocityTransfer::flip ? 1 - scene.solver.flip_fraction
                                                                                     : 1);
  } else if (s.on >= 0) {
    recorder = contact_force_recorder(h, s, sim, about);
  } else {
    std::vector<std::string> known;
    for (const auto& m : sim.modules()) {
      const auto* provider = dynamic_cast<const ReactionProvider<Dim>*>(m.get());
      if (!provider) continue;
      const auto names = provider->reaction_partners();
      const auto it = std::find(names.begin(), names.end(), s.partner);
      if (it != names.end()) {
        recorder = std::make_shared<ReactionRecorder<Dim>>(-1, provider, static_cast<int>(it - names.begin()), about);
        break;
      }
      known.insert(known.end(), names.begin(), names.end());
    }
    if (!recorder)
      fail(
          h, s.partner_key,
          s.partner_key == "set" ? fmt::format("set '{}' holds nothing in this run", s.partner)
          : s.partner_key == "plane"
              ? fmt::format("no rigid plane named '{}'{}", s.partner,
                            known.empty() ? " (the scene has no contact: section with planes)"
                                          : fmt::format("; rigid planes and bodies: {}", fmt::join(known, ", ")))
              : fmt::format("body '{}' is not a rigid body of the contact: section{}", s.partner,
                            known.empty() ? "" : fmt::format("; rigid planes and bodies: {}", fmt::join(known, ", "))));
  }
  sim.add_module(recorder);
  return std::make_unique<ReactionHistory<Dim>>(std::move(recorder), s.moment_about.has_value(),
                                                scene.grid.coordinates);
}

}  // namespace reaction
}  // namespace

HistoryKind reaction_kind() {
  using namespace reaction;
  return history_kind("reaction",
                      "the force (and moment about a point) a grid face with a velocity condition, a rigid plane, a "
                      "rigid body or a held particle set exerts on the bodies, or the contact exerts on one body (from "
                      "one partner or all), "
                      "mean over the interval",
                      {"face", "plane", "body", "set", "on", "from", "moment_about"}, parse, make<1>, make<2>, make<3>);
}

}  // namespace mpm::history
