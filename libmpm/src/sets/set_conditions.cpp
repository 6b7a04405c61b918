// The conditions on particle sets (sets/set_conditions.hpp; docs/theory.md §17).
#include "mpm/sets/set_conditions.hpp"

#include <algorithm>
#include <cstring>
#include <span>

#include <Eigen/Geometry>

#include "mpm/core/exact_sum.hpp"
#include "mpm/parallel/communicator.hpp"
#include "mpm/particles/field_keys.hpp"
#include "mpm/sets/particle_sets.hpp"
#include "mpm/shape/shape_functions.hpp"

namespace mpm {
namespace {

/// Appends to `marked` the nodes (of `g`) that the particles of `body` in the sets of `mask` reach with a non-zero
/// weight, each once (`flag`, one byte per node, is left as it was found: zero).
template <int Dim>
using NodeMarker = void (*)(const Body<Dim>& body, const GridGeometry<Dim>& g, std::uint32_t mask, bool reference,
                            std::vector<std::uint8_t>& flag, std::vector<Index>& marked);

template <int Dim, class Shape>
void mark_nodes(const Body<Dim>& body, const GridGeometry<Dim>& g, std::uint32_t mask, bool reference,
                std::vector<std::uint8_t>& flag, std::vector<Index>& marked) {
  const auto& p = body.particles;
  if (!p.has_field(keys::particle_sets)) return;
  const auto& bits = p.field(keys::particle_sets);
  const VecU<Dim>* x = reference ? p.field(keys::reference_position<Dim>).data() : p.x.data();
  Stencil<Dim, Shape> st;
  const ParticleDomain<Dim, Shape> domain(p);
  const std::size_t first = marked.size();
  for (Index i = 0; i < p.size(); ++i) {
    if ((bits[static_cast<std::size_t>(i)] & mask) == 0) continue;
    st.compute(x[i], g, domain(i));
    for (int a = 0; a < st.count; ++a) {
      const Index n = st.node[a];
      if (st.w[a] == 0 || flag[static_cast<std::size_t>(n)]) continue;
      flag[static_cast<std::size_t>(n)] = 1;
      marked.push_back(n);
    }
  }
  for (std::size_t k = first; k < marked.size(); ++k) flag[static_cast<std::size_t>(marked[k])] = 0;
}

template <int Dim>
NodeMarker<Dim> node_marker(const std::string& shape_function) {
  NodeMarker<Dim> marker = nullptr;
  dispatch_shape(shape_function, [&]<class Shape>() {
    if constexpr (shape_exists_in<Shape, Dim>) marker = &mark_nodes<Dim, Shape>;
  });
  return marker;
}

/// The nodes of one held set on one grid (the shared grid, or a body's own under contact).
template <int Dim>
struct HeldNodes {
  Grid<Dim>* grid = nullptr;
  std::vector<int> bodies;                ///< the set's bodies that map to this grid
  std::vector<Index> nodes;               ///< sorted, joined over the ranks
  std::vector<std::array<Real, Dim>> jm;  ///< per node: the mapped stage's impulse (eq. 13.2), N s
};

/// One component's prescribed value: a constant (no evaluation per node) or an expression of x, y, z, t.
struct Prescribed {
  int component = 0;
  std::shared_ptr<Expression> expression;  ///< null: the constant
  Real constant = 0;
  bool moving = false;  ///< not identically zero: it does work
  template <int Dim>
  Real at(const Vec<Dim>& x, Real t) const {
    if (!expression) return constant;
    Vec3 p = Vec3::Zero();
    p.template head<Dim>() = x;
    return (*expression)(p[0], p[1], p[2], t);
  }
};

template <int Dim>
class SetConditions final : public Module<Dim>, public ReactionProvider<Dim> {
 public:
  SetConditions(std::vector<HeldSet> held, std::vector<LoadedSet> loaded, NodeMarker<Dim> marker, bool reference,
                Real pic_share)
      : held_(std::move(held)),
        loaded_(std::move(loaded)),
        marker_(marker),
        reference_(reference),
        pic_share_(pic_share) {
    for (const auto& h : held_) {
      std::vector<Prescribed> components;
      for (int c = 0; c < Dim; ++c) {
        const auto& e = h.velocity[static_cast<std::size_t>(c)];
        if (!e) continue;
        Prescribed k;
        k.component = c;
        if (e->is_constant()) {
          k.constant = e->constant_value();
        } else {
          k.expression = e;
        }
        k.moving = k.expression != nullptr || k.constant != 0;
        components.push_back(std::move(k));
      }
      prescribed_.push_back(std::move(components));
    }
    reactions_.resize(held_.size());
    work_.assign(held_.size(), 0);
  }

  std::string_view name() const override { return "set conditions"; }
  std::string why_not_distributed() const override { return {}; }  // nodes joined over ranks, sums exact
  unsigned phases() const override {
    return (held_.empty() ? 0u : unsigned{phase_grid_velocity}) | (loaded_.empty() ? 0u : unsigned{phase_before_step});
  }

  std::vector<std::string> reaction_partners() const override {
    std::vector<std::string> names;
    names.reserve(held_.size());
    for (const auto& h : held_) names.push_back(h.name);
    return names;
  }
  Reaction<Dim> last_reaction(int k) const override { return reactions_[static_cast<std::size_t>(k)]; }
  std::optional<Real> last_work(int k) const override { return work_[static_cast<std::size_t>(k)]; }

  /// b_p = F(t) / M_set on the loaded sets' particles (zero on the other particles of their bodies).
  void before_step(StepContext<Dim>& ctx) override {
    std::vector<ExactSum> mass(loaded_.size());
    for (std::size_t s = 0; s < loaded_.size(); ++s)
      for (const int b : loaded_[s].bodies) {
        const auto& p = ctx.bodies[static_cast<std::size_t>(b)].particles;
        const auto& bits = p.field(keys::particle_sets);
        for (Index i = 0; i < p.size(); ++i)
          if (bits[static_cast<std::size_t>(i)] & loaded_[s].mask) mass[s] += p.mass[i];
      }
    if (ctx.comm) ctx.comm->sum(std::span<ExactSum>(mass));
    for (const auto& s : loaded_)
      for (const int b : s.bodies) {
        auto& field = ctx.bodies[static_cast<std::size_t>(b)].particles.field(keys::body_force<Dim>);
        std::fill(field.begin(), field.end(), VecU<Dim>::Zero());
      }
    for (std::size_t s = 0; s < loaded_.size(); ++s) {
      const Real m = mass[s].value();
      if (!(m > 0)) continue;  // every particle of the set has left the run
      Vec<Dim> a = Vec<Dim>::Zero();
      for (int c = 0; c < Dim; ++c)
        if (const auto& f = loaded_[s].force[static_cast<std::size_t>(c)]) a[c] = (*f)(0, 0, 0, ctx.time) / m;
      for (const int b : loaded_[s].bodies) {
        auto& p = ctx.bodies[static_cast<std::size_t>(b)].particles;
        const auto& bits = p.field(keys::particle_sets);
        auto& field = p.field(keys::body_force<Dim>);
        for (Index i = 0; i < p.size(); ++i)
          if (bits[static_cast<std::size_t>(i)] & loaded_[s].mask) field[static_cast<std::size_t>(i)] += a;
      }
    }
  }

  void on_grid_velocity(StepContext<Dim>& ctx, GridStage stage) override {
    if (stage == GridStage::mapped) {
      mark(ctx);
      for (std::size_t k = 0; k < held_.size(); ++k) hold_mapped(ctx, k);
    } else if (stage == GridStage::updated) {
      for (std::size_t k = 0; k < held_.size(); ++k) hold_updated(ctx, k);
    } else {
      for (std::size_t k = 0; k < held_.size(); ++k)
        for_each_held_node(k, [&](HeldNodes<Dim>& h, std::size_t, Index n, const NodeRecord<Dim>&, const Vec<Dim>& x) {
          for (const auto& c : prescribed_[k])
            h.grid->velocity[n].mapped[c.component] = c.at<Dim>(x, ctx.time + ctx.dt);
        });
    }
  }

 private:
  static Vec<Dim> position(const Grid<Dim>& g, Index n) { return g.geometry.node_position(g.geometry.node_indices(n)); }
  static Grid<Dim>& grid_of(Body<Dim>& body, Grid<Dim>& shared) {
    return body.separate_grid ? *body.separate_grid : shared;
  }

  /// The nodes each held set's particles reach at the start of the step, per grid, joined over the ranks.
  void mark(StepContext<Dim>& ctx) {
    nodes_.assign(held_.size(), {});
    for (std::size_t k = 0; k < held_.size(); ++k)
      for (const int b : held_[k].bodies) {
        Body<Dim>& body = ctx.bodies[static_cast<std::size_t>(b)];
        Grid<Dim>* g = &grid_of(body, ctx.grid);
        auto it = std::find_if(nodes_[k].begin(), nodes_[k].end(), [&](const auto& h) { return h.grid == g; });
        if (it == nodes_[k].end()) {
          HeldNodes<Dim> slot;
          slot.grid = g;
          nodes_[k].push_back(std::move(slot));
          it = std::prev(nodes_[k].end());
        }
        it->bodies.push_back(b);
        auto& flag = flags_[g];
        flag.resize(static_cast<std::size_t>(g->size()), 0);
        marker_(body, g->geometry, held_[k].mask, reference_, flag, it->nodes);
      }
    for (auto& slots : nodes_)
      for (auto& h : slots) std::sort(h.nodes.begin(), h.nodes.end());
    if (ctx.comm && ctx.comm->size() > 1) join_over_ranks(*ctx.comm);
    for (auto& slots : nodes_)
      for (auto& h : slots) h.jm.assign(h.nodes.size(), {});
  }

  /// Every rank marks the nodes of the particles it holds; a node reached from a particle on another rank is held
  /// too: the lists are exchanged and merged (in the same order on every rank).
  void join_over_ranks(Communicator& comm) {
    std::vector<std::byte> mine;
    for (const auto& slots : nodes_)
      for (const auto& h : slots) {
        const auto count = static_cast<std::int64_t>(h.nodes.size());
        const std::size_t at = mine.size();
        mine.resize(at + sizeof(count) + h.nodes.size() * sizeof(Index));
        std::memcpy(mine.data() + at, &count, sizeof(count));
        if (count > 0) std::memcpy(mine.data() + at + sizeof(count), h.nodes.data(), h.nodes.size() * sizeof(Index));
      }
    const auto received =
        comm.all_to_all(std::vector<std::vector<std::byte>>(static_cast<std::size_t>(comm.size()), mine));
    for (auto& slots : nodes_)
      for (auto& h : slots) h.nodes.clear();
    for (const auto& bytes : received) {
      std::size_t at = 0;
      for (auto& slots : nodes_)
        for (auto& h : slots) {
          std::int64_t count = 0;
          std::memcpy(&count, bytes.data() + at, sizeof(count));
          at += sizeof(count);
          const std::size_t first = h.nodes.size();
          h.nodes.resize(first + static_cast<std::size_t>(count));
          if (count > 0)
            std::memcpy(h.nodes.data() + first, bytes.data() + at, static_cast<std::size_t>(count) * sizeof(Index));
          at += static_cast<std::size_t>(count) * sizeof(Index);
        }
    }
    for (auto& slots : nodes_)
      for (auto& h : slots) {
        std::sort(h.nodes.begin(), h.nodes.end());
        h.nodes.erase(std::unique(h.nodes.begin(), h.nodes.end()), h.nodes.end());
      }
  }

  /// f(slot, j, node, its record, its position) for every held node of set k that has mass (the others have no
  /// velocity to hold), in the order of the joined lists.
  template <class F>
  void for_each_held_node(std::size_t k, F&& f) {
    for (auto& h : nodes_[k])
      for (std::size_t j = 0; j < h.nodes.size(); ++j) {
        const Index n = h.nodes[j];
        const NodeRecord<Dim>& r = h.grid->node[n];
        if (r.mass > 0) f(h, j, n, r, position(*h.grid, n));
      }
  }

  /// v(t) on the held nodes; the impulse m_I v(t) − p_I of each (eq. 13.2) kept for the updated stage.
  void hold_mapped(StepContext<Dim>& ctx, std::size_t k) {
    const Real cutoff = ctx.settings.mass_cutoff;
    for_each_held_node(k, [&](HeldNodes<Dim>& h, std::size_t j, Index n, const NodeRecord<Dim>& r, const Vec<Dim>& x) {
      for (const auto& c : prescribed_[k]) {
        const Real v = c.at<Dim>(x, ctx.time);
        if (r.mass > cutoff) h.jm[j][static_cast<std::size_t>(c.component)] = r.mass * v - r.momentum[c.component];
        h.grid->velocity[n].mapped[c.component] = v;
      }
    });
  }

  /// v(t + dt) on the held nodes, and the set's reaction of the step: R dt = Σ_I m_I (v(t + dt) − v(t)) − Δt (f_I +
  /// m_I g) + (1 − α) J_m,I (eq. 17.1), over the nodes this rank owns, summed exactly and reduced; its moment
  /// Σ x_I × R_I and its work Σ R_I · v(x_I, t + dt/2) dt. From the nodal forces, not from the velocity the step
  /// would have given the node: local damping's force at a held node (−α|f| sign v of a velocity that is noise there)
  /// is overridden by the condition and is no force of the bodies on it.
  void hold_updated(StepContext<Dim>& ctx, std::size_t k) {
    const Real cutoff = ctx.settings.mass_cutoff, t1 = ctx.time + ctx.dt, tm = ctx.time + 0.5 * ctx.dt;
    std::array<ExactSum, Dim + 4> sums;  // force (Dim), first moment (3), work
    for_each_held_node(k, [&](HeldNodes<Dim>& h, std::size_t j, Index n, const NodeRecord<Dim>& r, const Vec<Dim>& x) {
      Vec<Dim> impulse = Vec<Dim>::Zero();
      for (const auto& c : prescribed_[k]) {
        const int d = c.component;
        const Real v = c.at<Dim>(x, t1);
        if (r.mass > cutoff)
          impulse[d] = r.mass * (v - c.at<Dim>(x, ctx.time)) -
                       ctx.dt * (r.force[d] + r.mass * ctx.settings.gravity[d]) +
                       pic_share_ * h.jm[j][static_cast<std::size_t>(d)];
        h.grid->velocity[n].updated[d] = v;
      }
      if (!ctx.owned_nodes.contains(n)) return;
      Vec3 x3 = Vec3::Zero(), f3 = Vec3::Zero();
      x3.template head<Dim>() = x;
      f3.template head<Dim>() = impulse;
      const Vec3 moment = x3.cross(f3);
      for (int d = 0; d < Dim; ++d) sums[static_cast<std::size_t>(d)] += impulse[d];
      for (int d = 0; d < 3; ++d) sums[static_cast<std::size_t>(Dim) + static_cast<std::size_t>(d)] += moment[d];
      for (const auto& c : prescribed_[k])
        if (c.moving) sums[Dim + 3] += impulse[c.component] * c.at<Dim>(x, tm);
    });
    if (ctx.comm) ctx.comm->sum(std::span<ExactSum>(sums));
    Reaction<Dim>& out = reactions_[k];
    for (int d = 0; d < Dim; ++d) out.force[d] = sums[static_cast<std::size_t>(d)].value() / ctx.dt;
    for (int d = 0; d < 3; ++d)
      out.first_moment[d] = sums[static_cast<std::size_t>(Dim) + static_cast<std::size_t>(d)].value() / ctx.dt;
    work_[k] = sums[Dim + 3].value();
  }

  std::vector<HeldSet> held_;
  std::vector<LoadedSet> loaded_;
  NodeMarker<Dim> marker_;
  bool reference_;
  Real pic_share_;
  std::vector<std::vector<Prescribed>> prescribed_;  ///< per held set, its held components
  std::vector<std::vector<HeldNodes<Dim>>> nodes_;   ///< per held set, per grid
  std::map<const Grid<Dim>*, std::vector<std::uint8_t>> flags_;
  std::vector<Reaction<Dim>> reactions_;  ///< of the last step, per held set
  std::vector<Real> work_;                ///< J, of the last step, per held set
};

}  // namespace

template <int Dim>
std::shared_ptr<Module<Dim>> make_set_conditions(std::vector<HeldSet> held, std::vector<LoadedSet> loaded,
                                                 const std::string& shape_function, bool total_lagrangian,
                                                 Real pic_share) {
  if (held.empty() && loaded.empty()) return nullptr;
  const NodeMarker<Dim> marker = node_marker<Dim>(shape_function);
  if (!marker) throw std::invalid_argument("set conditions: no shape function '" + shape_function + "'");
  return std::make_shared<SetConditions<Dim>>(std::move(held), std::move(loaded), marker, total_lagrangian, pic_share);
}

template std::shared_ptr<Module<1>> make_set_conditions<1>(std::vector<HeldSet>, std::vector<LoadedSet>,
                                                           const std::string&, bool, Real);
template std::shared_ptr<Module<2>> make_set_conditions<2>(std::vector<HeldSet>, std::vector<LoadedSet>,
                                                           const std::string&, bool, Real);
template std::shared_ptr<Module<3>> make_set_conditions<3>(std::vector<HeldSet>, std::vector<LoadedSet>,
                                                           const std::string&, bool, Real);

}  // namespace mpm
