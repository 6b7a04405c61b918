#pragma once
/// \file heat_conduction.hpp
/// Explicit heat conduction on the MPM grid (review §5.3.2, Algorithm 8) and its coupling to the mechanics on
/// the same grid and time step (Algorithm 9). One step, all with the weights at the particle positions of the
/// start of the step (the reference positions with the TLMPM):
///   C_I = sum phi m c (eq. 5.24);  T_I = sum phi (m c T)_p / C_I (eq. 5.25);
///   Q_I = sum V_p [gamma* phi_I + q_p . grad phi_I] - sum_faces q* A_I (eqs 5.21-5.23);
///   T~_I = T_I + dt Q_I / C_I, Dirichlet nodes T_I = T~_I = T*;
///   T_p += sum phi (T~_I - T_I) (FLIP-type), relaxed towards the consistent projection P of T~ over
///   tau = particle_relaxation h^2 rho c / k (docs/theory.md eqs TP.1-TP.2: the FLIP-type update alone keeps the
///   part of an initial jump that maps to nothing on the grid);  T_I^{t+dt} = sum phi (m c T)_p / C_I (second mapping);
///   q_p = -k grad T with grad T = sum grad phi_I T_I^{t+dt}: the flux of the next step comes from the
///   re-mapped grid temperature, not from T~ (the double mapping of Alg. 8).
/// It runs in the phase after P2G, so the stress update of the same step sees T^{t+dt} (Alg. 9). The shared
/// particle field mpm::keys::temperature is the one the plasticity module heats by plastic work (eq. B.13) and reads
/// for Johnson-Cook softening, so conduction, plastic heating and softening act on one temperature.
/// Thermal expansion (eq. 5.26) of linear_elastic bodies: eps_dot^e = eps_dot - (alpha dT/dt) I, applied
/// by subtracting (alpha dT/dt) I from the velocity gradient before the stress update, plus the part of
/// the thermal strain the packed law cannot see (out-of-plane axes in 1D/2D) after it.
/// TLMPM: the grid is the reference configuration; grad T = F^-T grad_0 T and the heat flow uses the
/// pulled-back flux J F^-1 q with the reference volume (the nominal flux, like P for the force).
/// Axisymmetric (Coords): the same equations with the particles' ring masses and volumes (so capacity and
/// conductance are r-weighted; a scalar field has no hoop term), J with F_tt, face fluxes per unit area of the
/// revolved face, and the hoop rate joins the thermal expansion (axisymmetric.hpp).
/// Contact conductance (docs/theory.md eq. TC.1): when a module of the run (contact/) gives a pair of bodies a
/// finite thermal contact conductance h (interface_conductance.hpp), every body maps to its own nodal fields,
/// bodies in perfect contact are merged at their common nodes (which is the shared field), and at a node where a
/// and b with finite h meet, heat Q = h A_I (T_b - T_a) flows from b to a, A_I = |a_I^a - a_I^b|/2 with
/// a_I^k = sum_p V_p grad phi_I (the node's share of the interface); integrated exactly over the step for the
/// two nodal capacities (eq. TC.2). Without a finite conductance the single shared field runs unchanged.

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "mpm/core/expression.hpp"
#include "mpm/core/parallel_chunks.hpp"
#include "mpm/core/state_archive.hpp"
#include "mpm/particles/field_keys.hpp"
#include "mpm/schemes/axisymmetric.hpp"
#include "mpm/shape/shape_functions.hpp"
#include "mpm/shape/stencil.hpp"
#include "mpm/simulation/interface_conductance.hpp"
#include "mpm/simulation/module.hpp"
#include "mpm/thermal/field_keys.hpp"
#include "mpm/thermal/thermal_body.hpp"

namespace mpm::thermal {

/// Nodes of one face of the grid box with their tributary areas (lengths in 2D, 1 in 1D; the revolved face's
/// in axisymmetric coordinates), for the flux.
struct FaceNodes {
  std::vector<Index> node;
  std::vector<Real> area;  ///< m^2 (m in 2D, 1 in 1D)
};

/// The particle domains of the thermal weights: the scheme's (ParticleDomain), except with the TLMPM, whose weights
/// are those of the reference configuration (it caches them at t = 0): a CPDI domain has its corners X_p + (X_c -
/// X_p)(0), not the current x_p + F_p (X_c - X_p), and a cpGIMP domain its half-lengths l_p(0)/2, not l_p(0)/2 F_aa.
template <int Dim, class Shape>
struct ThermalDomain : ParticleDomain<Dim, Shape> {
  ThermalDomain(const ParticleSet<Dim>& p, bool) : ParticleDomain<Dim, Shape>(p) {}
};
template <int Dim, class Shape>
requires Shape::uses_domain struct ThermalDomain<Dim, Shape> {  // GIMP: cpGIMP's l_p(0)/2 F_aa becomes l_p(0)/2
  ParticleDomain<Dim, Shape> current;
  const VecU<Dim>* half0 = nullptr;  ///< l_p(0)/2 (TLMPM only)
  ThermalDomain(const ParticleSet<Dim>& p, bool total_lagrangian) : current(p) {
    if (total_lagrangian) half0 = p.field(mpm::keys::domain_half_length0<Dim>).data();
  }
  Vec<Dim> operator()(Index i) const { return half0 ? Vec<Dim>(half0[i]) : current(i); }
};
template <int Dim, class Shape>
requires Shape::corner_domain struct ThermalDomain<Dim, Shape> {
  ParticleDomain<Dim, Shape> current;
  const VecU<Dim>* X = nullptr;              ///< reference positions (TLMPM only)
  const CornerSet<Dim>* offsets0 = nullptr;  ///< X_c - X_p at t = 0 (TLMPM only; corner tracking is refused there)
  ThermalDomain(const ParticleSet<Dim>& p, bool total_lagrangian) : current(p) {
    if (!total_lagrangian) return;
    X = p.field(mpm::keys::reference_position<Dim>).data();
    offsets0 = p.field(mpm::keys::cpdi_corner_offsets0<Dim>).data();
  }
  CornerSet<Dim> operator()(Index i) const {
    if (!X) return current(i);
    CornerSet<Dim> c;
    for (int k = 0; k < 4; ++k) c[k] = Vec<Dim>(X[i]) + Vec<Dim>(offsets0[i][k]);
    return c;
  }
};

template <int Dim>
struct ConductionSetup {
  std::vector<ThermalBody<Dim>> bodies;  ///< one per body of the scene
  std::string source = "0";              ///< W/m^3, expression of x, y, z, t
  std::array<std::optional<std::string>, 2 * Dim> face_temperature, face_flux;
  std::vector<std::string> region_temperature;  ///< K, expressions of t; particle field keys::thermal_region
  bool total_lagrangian = false;                ///< TLMPM: weights at the reference positions
  /// The particles' relaxation time towards the grid field, in cell diffusion times h^2 rho c / k (eq. TP.1); 0:
  /// none (the FLIP-type update alone).
  Real particle_relaxation = 0;
  int projection_iterations = 1;  ///< Richardson steps of the target's projection (eq. TP.2); 0: T~ itself
};

template <int Dim, class Shape, class Coords = CartesianCoordinates>
class HeatConduction final : public Module<Dim> {
 public:
  HeatConduction(ConductionSetup<Dim> setup, const GridGeometry<Dim>& g)
      : setup_(std::move(setup)), source_(setup_.source) {
    for (int f = 0; f < 2 * Dim; ++f) {
      if (setup_.face_temperature[f])
        face_temperature_[f] = std::make_unique<Expression>(*setup_.face_temperature[f], std::vector<std::string>{"t"});
      if (setup_.face_flux[f])
        face_flux_[f] = std::make_unique<Expression>(*setup_.face_flux[f], std::vector<std::string>{"t"});
      if (face_temperature_[f] || face_flux_[f]) faces_[f] = face_nodes(g, f);
    }
    for (const auto& r : setup_.region_temperature) region_.emplace_back(r, std::vector<std::string>{"t"});
    for (const auto& b : setup_.bodies) expands_ = expands_ || b.expansion != 0;
    shared_.assign(g.node_count(), false);
  }

  std::string_view name() const override { return "heat_conduction"; }
  /// Its scatters name the arrays they write (map_temperature), every other pass is nodal or per particle, and the
  /// thermal energy is a term of the reduced audit.
  std::string why_not_distributed() const override { return {}; }
  unsigned phases() const override { return phase_after_p2g | (expands_ ? phase_after_g2p | phase_after_stress : 0u); }
  std::string_view time_step_bound() const override {
    return "heat conduction (diffusion bound h^2 rho c / (2 dim k))";
  }

  /// min over bodies of h_min^2 rho c / (2 Dim k_max): the explicit diffusion limit (review §5.3.3;
  /// docs/errata.md #13: the paper's 1D step 8e-5 exceeds h^2/(2k) = 5e-5 for 100 cells).
  Real stable_time_step(const std::vector<Body<Dim>>&) const override {
    Real dt = std::numeric_limits<Real>::infinity();
    for (const auto& b : setup_.bodies)
      if (b.max_conductivity > 0)
        dt = std::min(dt, h_min_ * h_min_ * b.density * b.specific_heat / (2 * Dim * b.max_conductivity));
    return dt;
  }
  void set_cell_size(const GridGeometry<Dim>& g) { h_min_ = g.h.minCoeff(); }

  /// Thermal energy sum m c (T - T_ref), J.
  void add_energy(const Body<Dim>& body, EnergySums& e) const override {
    const auto& p = body.particles;
    const auto& T = p.field(mpm::keys::temperature);
    const auto& tb = setup_.bodies[static_cast<std::size_t>(body.index)];
    for (Index i = 0; i < p.size(); ++i) e.thermal += p.mass[i] * tb.specific_heat * (T[i] - tb.reference_temperature);
  }

  /// Whether the first step's flux has been computed: the rest of the module's state is in particle fields
  /// (temperature, heat_flux, temperature_increment) or recomputed every step.
  void save_state(StateArchive& archive, const std::string& prefix) const override {
    archive.put_integer(prefix + "flux_ready", flux_ready_ ? 1 : 0);
    if (expands_) archive.put_number(prefix + "expansion_work", expansion_work_);
  }
  void restore_state(const StateArchive& archive, const std::string& prefix) override {
    flux_ready_ = archive.integer(prefix + "flux_ready") != 0;
    if (expands_) expansion_work_ = archive.number(prefix + "expansion_work");
  }

  /// The grid temperature T_I^{t+dt} of the last step (K; zero on nodes without heat capacity). With a finite
  /// contact conductance: the capacity-weighted mean of the bodies' nodal temperatures.
  const std::vector<Real>& grid_temperature() const { return shared_.temperature; }
  /// Body b's own nodal temperature T_I^{t+dt} (K) when the bodies have their own fields (a finite contact
  /// conductance), else the shared grid temperature.
  const std::vector<Real>& grid_temperature(int b) const {
    return own_.empty() ? shared_.temperature : own_[static_cast<std::size_t>(b)].temperature;
  }
  /// Whether the bodies have their own nodal temperatures (some pair has a finite contact conductance).
  bool separate_fields() const { return !own_.empty(); }

  void after_p2g(StepContext<Dim>& ctx) override {
    auto& grid = ctx.grid;
    const auto& g = grid.geometry;
    const Real t1 = ctx.time + ctx.dt;
    if (!interfaces_resolved_) resolve_interfaces(ctx);
    if (!own_.empty()) {
      separate_step(ctx);
      return;
    }
    if (!flux_ready_) {  // the first step: q_p from the initial temperature field
      hold_particles(ctx.bodies, ctx.time);
      map_temperature(ctx, false);
      flux_from_grid(ctx);
      flux_ready_ = true;
    }
    hold_particles(ctx.bodies, ctx.time);
    map_temperature(ctx, true);  // C_I, T_I^t and Q_I
    for (int f = 0; f < 2 * Dim; ++f)
      if (face_flux_[f]) {
        const Real q = (*face_flux_[f])(0, 0, 0, ctx.time);
        for (std::size_t k = 0; k < faces_[f].node.size(); ++k)
          shared_.heat_flow[faces_[f].node[k]] -= q * faces_[f].area[k];
      }
    // T~_I = T_I + dt Q_I / C_I; Dirichlet nodes: T_I = T~_I = T*
    predict(shared_, ctx.dt);
    hold_nodes(shared_.temperature, ctx.time);
    hold_nodes(shared_.updated, t1);
    relaxation_target(ctx);
    // T_p += sum phi (T~_I - T_I) (and the relaxation), then the second mapping gives T_I^{t+dt}
    for (std::size_t b = 0; b < ctx.bodies.size(); ++b) update_particles(ctx.bodies[b], b, shared_, g, t1, ctx.dt);
    map_temperature(ctx, false);
    flux_from_grid(ctx);
    grid.node_fields["temperature"] = shared_.temperature;
  }

  /// Thermal expansion (eq. 5.26): L -= (alpha dT / dt) I before the stress update of linear_elastic bodies.
  void after_g2p(StepContext<Dim>& ctx) override {
    step_expansion_work_ = ExactSum{};
    book_expansion_work(ctx);  // the half of the trapezoid at the stress of the start of the step
    for (std::size_t b = 0; b < ctx.bodies.size(); ++b) {
      const Real alpha = setup_.bodies[b].expansion;
      if (alpha == 0) continue;
      auto& L = ctx.bodies[b].velocity_gradient;
      const auto& dT = increment(ctx.bodies[b].particles);
      for (std::size_t i = 0; i < L.size(); ++i)
        for (int d = 0; d < Dim; ++d) L[i](d, d) -= alpha * dT[i] / ctx.dt;
      if constexpr (Coords::axisymmetric) {  // the hoop strain expands freely too
        const axisym::HoopFields hoop = axisym::hoop_fields(ctx.bodies[b].particles);
        for (std::size_t i = 0; i < L.size(); ++i) hoop.rate[i] -= alpha * dT[i] / ctx.dt;
      }
    }
  }
  /// The thermal strain the in-plane velocity gradient cannot carry: with eps^T = alpha dT I in 3D, the
  /// linear law gives lambda tr(eps^T) over all three axes and 2 mu eps^T on the out-of-plane ones.
  void after_stress(StepContext<Dim>& ctx) override {
    if constexpr (Dim < 3 && !Coords::axisymmetric) {  // axisymmetric: L_tt carried the hoop part
      for (std::size_t b = 0; b < ctx.bodies.size(); ++b) {
        const auto& tb = setup_.bodies[b];
        if (tb.expansion == 0) continue;
        auto& p = ctx.bodies[b].particles;
        const auto& dT = increment(p);
        for (Index i = 0; i < p.size(); ++i) {
          const Real e = tb.expansion * dT[i];
          for (int k = 0; k < Dim; ++k) p.stress[i].c[k] -= (3 - Dim) * tb.lambda * e;
          for (int k = Dim; k < 3; ++k) p.stress[i].c[k] -= ((3 - Dim) * tb.lambda + 2 * tb.mu) * e;
        }
      }
    }
    book_expansion_work(ctx);  // the half at the updated stress
    if (ctx.comm) ctx.comm->sum(std::span<ExactSum>(&step_expansion_work_, 1));
    expansion_work_ += step_expansion_work_.value();
  }

  /// J: the work the thermal strain did on the mechanics since t = 0 (eq. 5.26), W_T = -sum over steps and particles
  /// of V tr(sigma) alpha dT (trapezoidal in sigma over the step; the 3D trace: the out-of-plane thermal strain works
  /// too). Heat that becomes strain energy (a constrained body heated) enters the mechanical books through it, so
  /// the energy sentinel and the run's energy change count it as supplied: a negative removed energy (eq. 8.4).
  /// linear_elastic only (ThermalExpansion::by_heat_conduction); the plasticity models' expansion in their update
  /// is not booked.
  Real removed_energy() const override { return -expansion_work_; }
  /// energy.csv's `thermal_expansion_work` (J, W_T) when a body expands: total_energy - thermal_expansion_work is
  /// E(0) + W.
  std::string_view energy_column() const override { return expands_ ? "thermal_expansion_work" : ""; }
  Real energy_column_value() const override { return expansion_work_; }
  Real expansion_work() const { return expansion_work_; }

 private:
  /// step_expansion_work_ += -1/2 sum_p V_p tr(sigma_p) alpha dT_p over the expanding bodies (this rank's particles).
  void book_expansion_work(const StepContext<Dim>& ctx) {
    for (std::size_t b = 0; b < ctx.bodies.size(); ++b) {
      const Real alpha = setup_.bodies[b].expansion;
      if (alpha == 0) continue;
      const auto& p = ctx.bodies[b].particles;
      const auto& dT = p.field(keys::temperature_increment);
      const Real* hoop = Coords::axisymmetric ? axisym::hoop_stretch_of(p) : nullptr;
      for (Index i = 0; i < p.size(); ++i) {
        const Real V = p.volume0[i] * axisym::volume_ratio(p, i, hoop);
        const Real trace = p.stress[i].c[0] + p.stress[i].c[1] + p.stress[i].c[2];
        step_expansion_work_ += -0.5 * V * trace * alpha * dT[i];
      }
    }
  }

  /// Per node: C_I (J/K), sum phi m c T (J), Q_I (W), T_I (K; T_I^{t+dt} after the step), T~_I (K) and, for the
  /// contact conductance, a_I = sum V_p grad phi_I (m^2 per unit thickness in 2D; the body's boundary share).
  struct NodalHeat {
    std::vector<Real> capacity, heat_content, heat_flow, temperature, updated;
    std::vector<Real> target;      ///< the particles' relaxation target (eq. TP.2), K; only with a relaxation
    std::vector<Real> round_trip;  ///< scratch of the target's iterations: sum phi m c (sum phi P)_p, J/K
    std::vector<VecU<Dim>> area;
    void assign(Index n, bool with_area) {
      for (auto* v : {&capacity, &heat_content, &heat_flow, &temperature, &updated}) v->assign(n, 0);
      if (with_area) area.assign(n, VecU<Dim>::Zero());
    }
  };

  /// Asks the run's modules for the pairs' contact conductances (interface_conductance.hpp); with a finite one,
  /// every body gets its own nodal fields.
  void resolve_interfaces(StepContext<Dim>& ctx) {
    interfaces_resolved_ = true;
    const int n = static_cast<int>(ctx.bodies.size());
    for (const auto& m : ctx.hooks.all())
      if (const auto* provider = dynamic_cast<const InterfaceConductance*>(m.get())) {
        conductance_.assign(n * n, std::numeric_limits<Real>::infinity());
        bool finite = false;
        for (int a = 0; a < n; ++a)
          for (int b = 0; b < n; ++b)
            if (a != b) {
              conductance_[a * n + b] = provider->interface_conductance(a, b);
              finite = finite || std::isfinite(conductance_[a * n + b]);
            }
        if (!finite) return;
        own_.resize(ctx.bodies.size());
        for (auto& f : own_) f.assign(ctx.grid.geometry.node_count(), true);
        return;
      }
  }

  /// T~_I = T_I + dt Q_I / C_I.
  static void predict(NodalHeat& f, Real dt) {
    parallel_chunks(Index{0}, static_cast<Index>(f.capacity.size()), 1 << 12, [&](Index chunk_begin, Index chunk_end) {
      for (Index n = chunk_begin; n != chunk_end; ++n)
        f.updated[n] = f.capacity[n] > 0 ? f.temperature[n] + dt * f.heat_flow[n] / f.capacity[n] : f.temperature[n];
    });
  }

  /// The step with the bodies' own nodal fields (a finite contact conductance): Alg. 8 per body, with the heat
  /// exchanged at the nodes two bodies share (eqs TC.1-TC.2) and perfect pairs merged there.
  void separate_step(StepContext<Dim>& ctx) {
    const auto& g = ctx.grid.geometry;
    const Real t1 = ctx.time + ctx.dt;
    if (!flux_ready_) {
      hold_particles(ctx.bodies, ctx.time);
      map_temperature(ctx, false);
      flux_from_grid(ctx);
      flux_ready_ = true;
    }
    hold_particles(ctx.bodies, ctx.time);
    map_temperature(ctx, true);  // per body: C_I, T_I^t (perfect pairs merged), Q_I and a_I
    for (int f = 0; f < 2 * Dim; ++f)
      if (face_flux_[f]) {  // shared by the bodies at the node in proportion to their capacities
        const Real q = (*face_flux_[f])(0, 0, 0, ctx.time);
        for (std::size_t k = 0; k < faces_[f].node.size(); ++k) {
          const Index I = faces_[f].node[k];
          if (!(shared_.capacity[I] > 0)) continue;
          for (auto& own : own_) own.heat_flow[I] -= q * faces_[f].area[k] * own.capacity[I] / shared_.capacity[I];
        }
      }
    for (auto& own : own_) predict(own, ctx.dt);
    exchange(ctx.bodies.size(), ctx.dt);
    for (auto& own : own_) {
      hold_nodes(own.temperature, ctx.time);
      hold_nodes(own.updated, t1);
    }
    relaxation_target(ctx);
    for (std::size_t b = 0; b < ctx.bodies.size(); ++b) update_particles(ctx.bodies[b], b, own_[b], g, t1, ctx.dt);
    map_temperature(ctx, false);
    flux_from_grid(ctx);
    ctx.grid.node_fields["temperature"] = shared_.temperature;
  }

  /// The bodies with heat capacity at node I, and for each the first body of its perfect-contact group (bodies
  /// joined by pairs of infinite conductance share one temperature there). Returns the number of bodies.
  int groups_at(Index I, std::size_t bodies, int* present, int* root) const {
    int count = 0;
    for (std::size_t k = 0; k < bodies; ++k)
      if (own_[k].capacity[I] > 0) present[count++] = static_cast<int>(k);
    const int n = static_cast<int>(bodies);
    for (int i = 0; i < count; ++i) {
      root[i] = i;
      for (int j = 0; j < i; ++j)
        if (!std::isfinite(conductance_[present[i] * n + present[j]]) && root[i] != root[j]) {
          // relabel i's group with j's label; a label stays the index of one of its members
          const int old = root[i], joined = root[j];
          for (int k = 0; k <= i; ++k)
            if (root[k] == old) root[k] = joined;
        }
    }
    return count;
  }

  /// At every node two bodies share: perfect groups take one temperature sum C T / sum C; pairs of groups with
  /// a finite h exchange heat (eq. TC.2); a group's predicted temperature is then T + dt sum Q / sum C.
  void exchange(std::size_t bodies, Real dt) {
    const int n = static_cast<int>(bodies);
    const Index nodes = static_cast<Index>(shared_.capacity.size());
    parallel_chunks(Index{0}, nodes, 1 << 12, [&](Index chunk_begin, Index chunk_end) {
      std::vector<int> present(bodies), root(bodies);
      std::vector<Real> C(bodies), T(bodies), Q(bodies);
      for (Index I = chunk_begin; I != chunk_end; ++I) {
        const int count = groups_at(I, bodies, present.data(), root.data());
        if (count < 2) continue;
        // group sums, held at the group's first member
        for (int i = 0; i < count; ++i) C[i] = T[i] = Q[i] = 0;
        for (int i = 0; i < count; ++i) {
          const auto& own = own_[present[i]];
          C[root[i]] += own.capacity[I];
          T[root[i]] += own.capacity[I] * own.temperature[I];
          Q[root[i]] += own.heat_flow[I];
        }
        for (int i = 0; i < count; ++i)
          if (root[i] == i) T[i] /= C[i];
        // eq. TC.2 between the members of different groups with a finite conductance
        for (int i = 0; i < count; ++i)
          for (int j = i + 1; j < count; ++j) {
            const int a = present[i], b = present[j], ga = root[i], gb = root[j];
            const Real h = conductance_[a * n + b];
            if (ga == gb || !std::isfinite(h) || !(h > 0)) continue;
            const Real A = 0.5 * (Vec<Dim>(own_[a].area[I]) - Vec<Dim>(own_[b].area[I])).norm();
            const Real inv = 1 / C[ga] + 1 / C[gb];
            const Real decay = -std::expm1(-h * A * inv * dt);  // 1 - exp(-lambda dt)
            const Real flow = (T[gb] - T[ga]) * decay / (inv * dt);
            Q[ga] += flow;
            Q[gb] -= flow;
          }
        for (int i = 0; i < count; ++i) {
          auto& own = own_[present[i]];
          own.temperature[I] = T[root[i]];
          own.updated[I] = T[root[i]] + dt * Q[root[i]] / C[root[i]];
        }
      }
    });
  }

  /// After a mapping with own fields: perfect groups take one temperature at their common nodes, and the shared
  /// field holds the capacity-weighted mean (for the grid output).
  void merge_groups(std::size_t bodies) {
    const Index nodes = static_cast<Index>(shared_.capacity.size());
    parallel_chunks(Index{0}, nodes, 1 << 12, [&](Index chunk_begin, Index chunk_end) {
      std::vector<int> present(bodies), root(bodies);
      std::vector<Real> C(bodies), H(bodies);
      for (Index I = chunk_begin; I != chunk_end; ++I) {
        Real c = 0, hc = 0;
        for (const auto& own : own_) c += own.capacity[I], hc += own.heat_content[I];
        shared_.capacity[I] = c;
        shared_.temperature[I] = c > 0 ? hc / c : 0;
        const int count = groups_at(I, bodies, present.data(), root.data());
        if (count < 2) continue;
        for (int i = 0; i < count; ++i) C[i] = H[i] = 0;
        for (int i = 0; i < count; ++i) {
          C[root[i]] += own_[present[i]].capacity[I];
          H[root[i]] += own_[present[i]].heat_content[I];
        }
        for (int i = 0; i < count; ++i) own_[present[i]].temperature[I] = H[root[i]] / C[root[i]];
      }
    });
  }

  /// The face's share of every node on it, A_I = integral of phi_I over the face (the consistent load of a
  /// uniform flux). The hat functions' tributary areas (axisym::face_node_area) for every function whose trace on a
  /// grid face is the hat's (linear, GIMP, CPDI) or close to it (B-splines: interior nodes alike); the two-cell
  /// elements of Bernstein and Lagrange integrate to other shares (per element of size E = 2h: E/3 at each of
  /// Bernstein's three nodes; E/6, 2E/3, E/6 for Lagrange), and the hat's would heat their vertex and mid nodes
  /// unevenly under a uniform flux (their lumped capacities have the same shares): those integrate the function.
  static FaceNodes face_nodes(const GridGeometry<Dim>& g, int face) {
    const int axis = face / 2;
    const int layer = face % 2 == 0 ? 0 : g.nodes[axis] - 1;
    std::array<std::vector<Real>, Dim> share;
    if constexpr (shape_cell_multiple<Shape> == 2)
      for (int d = 0; d < Dim; ++d)
        if (d != axis) share[d] = axis_integrals(g, d);
    FaceNodes f;
    for (Index n = 0; n < g.node_count(); ++n) {
      const auto ijk = g.node_indices(n);
      if (ijk[axis] != layer) continue;
      f.node.push_back(n);
      if constexpr (shape_cell_multiple<Shape> == 2) {
        Real area = 1;
        for (int d = 0; d < Dim; ++d)
          if (d != axis) area *= share[d][static_cast<std::size_t>(ijk[d])];
        f.area.push_back(area);
      } else {
        f.area.push_back(axisym::face_node_area(g, n, axis));  // revolved face when axisymmetric
      }
    }
    return f;
  }

  /// The integral of every node's 1D function along axis d (m): 3-point Gauss per cell, exact for the quadratics.
  static std::vector<Real> axis_integrals(const GridGeometry<Dim>& g, int d) {
    std::vector<Real> integral(static_cast<std::size_t>(g.nodes[d]), 0);
    const Real r = std::sqrt(Real(0.6)) / 2;
    const Real point[3] = {Real(0.5) - r, Real(0.5), Real(0.5) + r},
               weight[3] = {5 / Real(18), 8 / Real(18), 5 / Real(18)};
    for (int cell = 0; cell + 1 < g.nodes[d]; ++cell)
      for (int q = 0; q < 3; ++q) {
        int base = 0;
        Real w[Shape::support], dw[Shape::support];
        evaluate_axis<Shape>(cell + point[q], g.nodes[d], 0, base, w, dw);
        for (int k = 0; k < Shape::support; ++k)
          integral[static_cast<std::size_t>(base + k)] += weight[q] * g.h[d] * w[k];
      }
    return integral;
  }

  /// The temperature change of the last thermal step per particle (K), for the expansion: a particle field,
  /// so that it follows reordering and snapshots (USF runs the stress update before the thermal step: it
  /// then sees the previous step's change, zero at the first step).
  static std::vector<Real>& increment(ParticleSet<Dim>& p) { return p.add_field(keys::temperature_increment, 0); }

  const VecU<Dim>* positions(const ParticleSet<Dim>& p) const {
    return setup_.total_lagrangian ? p.field(mpm::keys::reference_position<Dim>).data() : p.x.data();
  }

  void hold_nodes(std::vector<Real>& T, Real t) const {
    for (int f = 0; f < 2 * Dim; ++f)
      if (face_temperature_[f]) {
        const Real value = (*face_temperature_[f])(0, 0, 0, t);
        for (Index n : faces_[f].node) T[n] = value;
      }
  }

  /// Particles in a fixed-temperature region take its temperature at time t.
  void hold_particles(std::vector<Body<Dim>>& bodies, Real t) const {
    if (region_.empty()) return;
    std::vector<Real> value;
    for (const auto& r : region_) value.push_back(r(0, 0, 0, t));
    for (auto& body : bodies) {
      auto& p = body.particles;
      const auto& region = p.field(keys::thermal_region);
      auto& T = p.field(mpm::keys::temperature);
      for (Index i = 0; i < p.size(); ++i)
        if (region[i] >= 0) T[i] = value[static_cast<std::size_t>(region[i])];
    }
  }

  /// C_I and T_I = sum phi (m c T) / C_I; with `heat_flow`, also Q_I = sum V (gamma* phi + q . grad phi).
  void map_temperature(StepContext<Dim>& ctx, bool heat_flow) {
    auto& grid = ctx.grid;
    const auto& g = grid.geometry;
    const bool separate = !own_.empty();
    if (!separate) clear(shared_, heat_flow);
    for (auto& f : own_) clear(f, heat_flow);
    const bool constant_source = source_.is_constant();
    const Real source_value = source_.constant_value();
    for (std::size_t b = 0; b < ctx.bodies.size(); ++b) {
      auto& body = ctx.bodies[b];
      const auto& p = body.particles;
      const Real c = setup_.bodies[b].specific_heat;
      NodalHeat& f = separate ? own_[b] : shared_;
      Real* capacity = f.capacity.data();
      Real* heat_content = f.heat_content.data();
      Real* heat_flow_out = f.heat_flow.data();
      VecU<Dim>* area = separate ? f.area.data() : nullptr;
      const VecU<Dim>* x = positions(p);
      const auto& T = p.field(mpm::keys::temperature);
      const auto& q = p.field(keys::heat_flux<Dim>);
      [[maybe_unused]] const Real* hoop = Coords::axisymmetric ? axisym::hoop_stretch_of(p) : nullptr;
      // gamma* per particle, evaluated serially (an Expression is not thread-safe), only when it varies
      if (heat_flow && !constant_source) {
        gamma_.resize(p.size());
        for (Index i = 0; i < p.size(); ++i) {
          double xyz[3] = {0, 0, 0};
          for (int d = 0; d < Dim; ++d) xyz[d] = p.x[i][d];
          gamma_[i] = source_.evaluate(xyz, ctx.time);
        }
      }
      // the arrays this scatter adds to: their ghost nodes are exchanged in a distributed run (tile_halo.hpp)
      std::vector<HaloArray> written{HaloArray::of(f.capacity), HaloArray::of(f.heat_content)};
      if (heat_flow) written.push_back(HaloArray::of(f.heat_flow));
      if (heat_flow && area) written.push_back(HaloArray::of(f.area));
      for_each_tile_coloured(body.bins, std::span<const HaloArray>(written), [&](const Index* index, Index count) {
        axisym::StencilFor<Dim, Shape, Coords> st;
        const ThermalDomain<Dim, Shape> domain(p, setup_.total_lagrangian);
        for (Index k = 0; k < count; ++k) {
          const Index i = index[k];
          st.compute(x[i], g, domain(i));
          const Real mc = p.mass[i] * c, mcT = mc * T[i];
          for (int a = 0; a < st.count; ++a) {
            capacity[st.node[a]] += st.w[a] * mc;
            heat_content[st.node[a]] += st.w[a] * mcT;
          }
          if (!heat_flow) continue;
          const Mat<Dim> F = p.F[i];
          Real J = F.determinant();
          if constexpr (Coords::axisymmetric) J *= hoop[i];
          // current volume and flux; TLMPM: reference volume and nominal flux J F^-1 q
          Real V = p.volume0[i] * J;
          Vec<Dim> qv = q[i];
          if (setup_.total_lagrangian) {
            V = p.volume0[i];
            qv = J * (F.inverse() * qv);
          }
          const Real src = V * (constant_source ? source_value : gamma_[i]);
          for (int a = 0; a < st.count; ++a) {
            Real flow = src * st.w[a];
            for (int d = 0; d < Dim; ++d) flow += V * qv[d] * st.grad[a][d];
            heat_flow_out[st.node[a]] += flow;
          }
          if (area)  // a_I = sum V_p grad phi_I (eq. TC.1)
            for (int a = 0; a < st.count; ++a)
              for (int d = 0; d < Dim; ++d) area[st.node[a]][d] += V * st.grad[a][d];
        }
      });
    }
    if (!separate) nodal_values(shared_);
    for (auto& f : own_) nodal_values(f);
    if (separate) merge_groups(ctx.bodies.size());
    if (heat_flow) return;
    hold_nodes(shared_.temperature, ctx.time + ctx.dt);
    for (auto& f : own_) hold_nodes(f.temperature, ctx.time + ctx.dt);
  }

  static void clear(NodalHeat& f, bool heat_flow) {
    std::fill(f.capacity.begin(), f.capacity.end(), 0);
    std::fill(f.heat_content.begin(), f.heat_content.end(), 0);
    if (!heat_flow) return;
    std::fill(f.heat_flow.begin(), f.heat_flow.end(), 0);
    std::memset(static_cast<void*>(f.area.data()), 0, f.area.size() * sizeof(VecU<Dim>));
  }

  /// T_I = sum phi (m c T) / C_I (eq. 5.25).
  static void nodal_values(NodalHeat& f) {
    parallel_chunks(Index{0}, static_cast<Index>(f.capacity.size()), 1 << 12, [&](Index chunk_begin, Index chunk_end) {
      for (Index n = chunk_begin; n != chunk_end; ++n)
        f.temperature[n] = f.capacity[n] > 0 ? f.heat_content[n] / f.capacity[n] : 0;
    });
  }

  /// The relaxation target P_I of eq. TP.2 in every nodal field (none without a relaxation): the nodal values whose
  /// particle round trip S P = sum phi (m c sum_J phi_J P_J)_p / C_I is T~ (the consistent-mass projection), by
  /// `projection_iterations` Richardson steps P <- P + T~ - S P from P = T~ (each one more gather and scatter, of
  /// the arrays it names). Held nodes: T*.
  void relaxation_target(StepContext<Dim>& ctx) {
    if (!(setup_.particle_relaxation > 0)) return;
    const auto& g = ctx.grid.geometry;
    const bool separate = !own_.empty();
    std::vector<NodalHeat*> fields;
    if (separate)
      for (auto& f : own_) fields.push_back(&f);
    else
      fields.push_back(&shared_);
    for (NodalHeat* f : fields) {
      f->target = f->updated;
      hold_nodes(f->target, ctx.time + ctx.dt);
    }
    for (int iteration = 0; iteration < setup_.projection_iterations; ++iteration) {
      for (NodalHeat* f : fields) f->round_trip.assign(f->updated.size(), 0);
      for (std::size_t b = 0; b < ctx.bodies.size(); ++b) {
        auto& body = ctx.bodies[b];
        const auto& p = body.particles;
        const Real c = setup_.bodies[b].specific_heat;
        NodalHeat& f = separate ? own_[b] : shared_;
        const Real* target = f.target.data();
        Real* round_trip = f.round_trip.data();
        const VecU<Dim>* x = positions(p);
        const std::vector<HaloArray> written{HaloArray::of(f.round_trip)};
        for_each_tile_coloured(body.bins, std::span<const HaloArray>(written), [&](const Index* index, Index count) {
          axisym::StencilFor<Dim, Shape, Coords> st;
          const ThermalDomain<Dim, Shape> domain(p, setup_.total_lagrangian);
          for (Index k = 0; k < count; ++k) {
            const Index i = index[k];
            st.compute(x[i], g, domain(i));
            Real value = 0;
            for (int a = 0; a < st.count; ++a) value += st.w[a] * target[st.node[a]];
            const Real mcT = p.mass[i] * c * value;
            for (int a = 0; a < st.count; ++a) round_trip[st.node[a]] += st.w[a] * mcT;
          }
        });
      }
      for (NodalHeat* f : fields) {
        parallel_chunks(Index{0}, static_cast<Index>(f->target.size()), 1 << 12,
                        [&](Index chunk_begin, Index chunk_end) {
                          for (Index n = chunk_begin; n != chunk_end; ++n)
                            if (f->capacity[n] > 0) f->target[n] += f->updated[n] - f->round_trip[n] / f->capacity[n];
                        });
        hold_nodes(f->target, ctx.time + ctx.dt);
      }
    }
  }

  /// The fraction of eq. TP.1 for body b: dt / tau, tau = particle_relaxation h^2 rho c / k_max (at most 1; 0 without
  /// a relaxation or conduction).
  Real relaxation_fraction(std::size_t b, Real dt) const {
    const auto& tb = setup_.bodies[b];
    if (!(setup_.particle_relaxation > 0) || !(tb.max_conductivity > 0)) return 0;
    const Real tau = setup_.particle_relaxation * h_min_ * h_min_ * tb.density * tb.specific_heat / tb.max_conductivity;
    return std::min<Real>(1, dt / tau);
  }

  /// T_p += sum phi (T~_I - T_I), relaxed towards the target (eq. TP.1): T_p = (1 - a) (T_p + sum phi (T~_I - T_I))
  /// + a sum phi P_I; keeps the increment for the thermal expansion (field keys::temperature_increment, only when a
  /// body expands).
  void update_particles(Body<Dim>& body, std::size_t b, const NodalHeat& f, const GridGeometry<Dim>& g, Real t1,
                        Real dt) {
    auto& p = body.particles;
    auto& T = p.field(mpm::keys::temperature);
    const VecU<Dim>* x = positions(p);
    Real* dT = expands_ ? increment(p).data() : nullptr;
    const int* region = region_.empty() ? nullptr : p.field(keys::thermal_region).data();
    std::vector<Real> held;
    for (const auto& r : region_) held.push_back(r(0, 0, 0, t1));
    const Real alpha = relaxation_fraction(b, dt);
    const Real* target = alpha > 0 ? f.target.data() : nullptr;
    parallel_chunks(Index{0}, p.size(), 1024, [&](Index chunk_begin, Index chunk_end) {
      axisym::StencilFor<Dim, Shape, Coords> st;
      const ThermalDomain<Dim, Shape> domain(p, setup_.total_lagrangian);
      for (Index i = chunk_begin; i != chunk_end; ++i) {
        st.compute(x[i], g, domain(i));
        Real d = 0;
        for (int a = 0; a < st.count; ++a) d += st.w[a] * (f.updated[st.node[a]] - f.temperature[st.node[a]]);
        if (target) {
          Real relaxed = 0;
          for (int a = 0; a < st.count; ++a) relaxed += st.w[a] * target[st.node[a]];
          d = (1 - alpha) * d + alpha * (relaxed - T[i]);
        }
        if (region && region[i] >= 0) d = held[static_cast<std::size_t>(region[i])] - T[i];
        T[i] += d;
        if (dT) dT[i] = d;
      }
    });
  }

  /// q_p = -k grad T, grad T = sum grad phi_I T_I^{t+dt} (TLMPM: F^-T grad_0 T).
  void flux_from_grid(StepContext<Dim>& ctx) {
    const auto& g = ctx.grid.geometry;
    for (std::size_t b = 0; b < ctx.bodies.size(); ++b) {
      auto& p = ctx.bodies[b].particles;
      auto& q = p.field(keys::heat_flux<Dim>);
      const VecU<Dim>* x = positions(p);
      const Mat<Dim> k = setup_.bodies[b].conductivity;
      const std::vector<Real>& nodal_temperature = own_.empty() ? shared_.temperature : own_[b].temperature;
      parallel_chunks(Index{0}, p.size(), 1024, [&](Index chunk_begin, Index chunk_end) {
        axisym::StencilFor<Dim, Shape, Coords> st;
        const ThermalDomain<Dim, Shape> domain(p, setup_.total_lagrangian);
        for (Index i = chunk_begin; i != chunk_end; ++i) {
          st.compute(x[i], g, domain(i));
          Vec<Dim> grad = Vec<Dim>::Zero();
          for (int a = 0; a < st.count; ++a)
            for (int d = 0; d < Dim; ++d) grad[d] += st.grad[a][d] * nodal_temperature[st.node[a]];
          if (setup_.total_lagrangian) grad = Mat<Dim>(p.F[i]).inverse().transpose() * grad;
          q[i] = -(k * grad);
        }
      });
    }
  }

  ConductionSetup<Dim> setup_;
  Expression source_;
  std::array<std::unique_ptr<Expression>, 2 * Dim> face_temperature_, face_flux_;
  std::array<FaceNodes, 2 * Dim> faces_;
  std::vector<Expression> region_;
  bool expands_ = false;
  bool flux_ready_ = false;
  bool interfaces_resolved_ = false;
  Real h_min_ = 1;
  NodalHeat shared_;                ///< all bodies on one field (perfect contact); with own fields, their sum
  Real expansion_work_ = 0;         ///< J, W_T since t = 0 (expansion_work())
  ExactSum step_expansion_work_{};  ///< J, this step's, summed between after_g2p and after_stress
  std::vector<NodalHeat> own_;      ///< per body, only when some pair has a finite contact conductance
  std::vector<Real> conductance_;   ///< n x n, W/(m^2 K) (+infinity: perfect), from an InterfaceConductance
  std::vector<Real> gamma_;         ///< scratch: W/m^3 per particle
};

}  // namespace mpm::thermal
