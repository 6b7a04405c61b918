#pragma once
/// \file implicit_scheme.hpp
/// The energy-consistent implicit scheme of Love & Sulsky (ref. 003, Algorithm MPM; docs/theory.md §15): per step
///   1. projection: consistent mass M_n (86), grid velocity v_n from M v = sum N pi (87) by conjugate gradients,
///      on the free components only (walls removed from the system);
///   2. mesh dynamics: Newton-Krylov on the residual (88a)-(91) in Delta phi (mixed_residual.hpp), predictor
///      dt v_n;
///   3. material-point update (92): x += Delta phi(x_n), v += Delta v(x_n) (FLIP), F = f F_n, the material's
///      state committed, Theta_{n+1} (88e);
///   4. regrid: the mesh returns to where it was (nothing to do: the grid is fixed).
/// Energy, linear and angular momentum: H_{n+1} = H_n - sum Delta D Omega_0 (Prop. 3.1, Cor. 3.2) to the
/// solver's tolerance, for any dt. Linear hats, plane strain / 1D / 3D, hencky_j2 only (the scene loader refuses
/// the rest, implicit_section.cpp).

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <vector>

#include "mpm/boundary/grid_boundary.hpp"
#include "mpm/core/stability_error.hpp"
#include "mpm/implicit/consistent_mass.hpp"
#include "mpm/implicit/implicit_options.hpp"
#include "mpm/implicit/mixed_residual.hpp"
#include "mpm/implicit/newton_krylov.hpp"
#include "mpm/implicit/solver_log.hpp"
#include "mpm/implicit/step_points.hpp"
#include "mpm/schemes/scheme.hpp"

namespace mpm::implicit {

template <int Dim>
class ImplicitScheme final : public Scheme<Dim> {
 public:
  explicit ImplicitScheme(const ImplicitOptions& options) : options_(options) {}

  std::string_view name() const override { return "implicit"; }
  std::string_view shape_function() const override { return LinearHat::name; }
  int slab_cells() const override { return LinearHat::slab_cells; }
  int min_cells() const override { return LinearHat::min_cells; }
  const ImplicitOptions& options() const { return options_; }
  /// What the last step's solves took (solver.csv).
  const StepRecord& last_step() const { return record_; }

  std::string_view step_log_file() const override { return "solver.csv"; }
  std::vector<std::string> step_log_columns() const override {
    return {"step",
            "time",
            "newton_iterations",
            "gmres_iterations",
            "residual_evaluations",
            "first_residual",
            "last_residual",
            "wall_seconds",
            "projection_seconds",
            "residual_seconds",
            "factorization_seconds"};
  }
  std::vector<double> step_log_row() const override {
    const StepRecord& r = record_;
    return {static_cast<double>(r.step),
            r.time,
            double(r.newton_iterations),
            double(r.gmres_iterations),
            double(r.residual_evaluations),
            r.first_residual,
            r.last_residual,
            r.wall_seconds,
            r.projection_seconds,
            r.residual_seconds,
            r.factorization_seconds};
  }

  /// Adds the mixed volume Theta (= 1, or J of a body read from a file) to every body (before the first snapshot).
  void initialize(std::vector<Body<Dim>>& bodies, Grid<Dim>&) override {
    for (auto& body : bodies) {
      auto& p = body.particles;
      if (p.has_field(plasticity::keys::mixed_volume)) continue;
      auto& theta = p.add_field(plasticity::keys::mixed_volume, Real(1));
      const Real* hoop = axisym::hoop_stretch_of(p);
      for (Index i = 0; i < p.size(); ++i) theta[i] = axisym::volume_ratio(p, i, hoop);  // J (with F_tt)
    }
  }

  void advance(StepContext<Dim>& ctx) override {
    const auto start = std::chrono::steady_clock::now();
    const GridGeometry<Dim>& g = ctx.grid.geometry;
    points_.gather(ctx.bodies, g);
    project(ctx);
    const double projection_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    MixedResidual<Dim> problem(points_, *mass_, dofs_, g, v_n_, f_ext_, ctx.dt, options_.volumetric);
    Vector x(problem.size()), r(problem.size());
    for (Index k = 0; k < problem.size(); ++k) x[k] = ctx.dt * v_n_[dofs_.dofs[k].first][dofs_.dofs[k].second];
    const Real reference = residual_reference(problem, x, ctx.dt);
    NewtonSettings settings{options_.newton_rtol, options_.newton_atol,           options_.max_newton_iterations,
                            options_.linear_rtol, options_.max_linear_iterations, options_.gmres_restart};
    settings.trace = options_.newton_trace;
    const NewtonStats stats = solve_newton_krylov(problem, x, reference, settings);
    record_ = {ctx.step,
               ctx.time + ctx.dt,
               stats.iterations,
               stats.linear_iterations,
               stats.residual_evaluations + 1,
               stats.first_residual,
               stats.last_residual,
               0,
               projection_seconds,
               stats.residual_seconds,
               stats.factor_seconds};
    if (!stats.converged) {
      if (options_.newton_trace && problem.residual(x, r)) {  // where the residual stays
        std::vector<Index> order(static_cast<std::size_t>(r.size()));
        for (Index k = 0; k < r.size(); ++k) order[k] = k;
        std::partial_sort(order.begin(), order.begin() + std::min<Index>(6, r.size()), order.end(),
                          [&](Index a, Index b) { return std::abs(r[a]) > std::abs(r[b]); });
        for (Index j = 0; j < std::min<Index>(6, r.size()); ++j) {
          const auto [node, d] = dofs_.dofs[order[j]];
          const Vec<Dim> at = g.node_position(g.node_indices(node));
          std::fprintf(stderr, "  dof %ld (node %ld at %s, component %d): R = %.4e, lumped mass %.3e\n",
                       static_cast<long>(order[j]), static_cast<long>(node),
                       fmt::format("{}", fmt::join(at, ", ")).c_str(), d, r[order[j]], mass_->lumped(node));
        }
      }
      fail(ctx, stats);
    }
    if (!problem.residual(x, r)) fail(ctx, stats);  // the accepted iterate, evaluated once more for the commit
    update_particles(ctx, problem);
    record_.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }

 private:
  /// Step 1: M_n (86), the free dofs and v_n from (87); the external force (89b, gravity).
  void project(StepContext<Dim>& ctx) {
    const GridGeometry<Dim>& g = ctx.grid.geometry;
    const Index nodes = g.node_count();
    if (!mass_) mass_ = std::make_unique<ConsistentMass<Dim>>(ctx.grid.geometry);
    mass_->clear();
    std::vector<char> touched(nodes, 0);
    std::vector<Real> fraction(nodes, 0);  // sum N^A V_p / cell volume (meridian volumes when axisymmetric)
    Real cell_volume = 1;
    for (int d = 0; d < Dim; ++d) cell_volume *= g.h[d];
    momentum_.assign(nodes, VecU<Dim>::Zero());
    f_ext_.assign(nodes, VecU<Dim>::Zero());
    const Vec<Dim> gravity = ctx.settings.gravity;
    for (Index i = 0; i < points_.size(); ++i) {
      mass_->add_particle(points_.mass[i], points_.node[i], points_.w[i]);
      Real volume = points_.volume0[i] * points_.J_n[i] / cell_volume;
      if (points_.axisymmetric)
        volume /= 2 * std::numbers::pi * ctx.bodies[points_.body[i]].particles.x[points_.index[i]][0];
      for (int a = 0; a < StepPoints<Dim>::count; ++a) {
        const Index A = points_.node[i][a];
        const Real w = points_.w[i][a];
        if (w > 0) touched[A] = 1;
        fraction[A] += w * volume;
        momentum_[A] += w * points_.mass[i] * Vec<Dim>(points_.velocity[i]);
        f_ext_[A] += w * points_.mass[i] * gravity;
      }
    }
    // held components: what the wall conditions set to zero (all are at rest: the loader refuses the rest)
    NodeArray<NodeVelocity<Dim>> probe(nodes, NodeVelocity<Dim>{VecU<Dim>::Ones(), VecU<Dim>::Ones()});
    ctx.boundary.apply(probe, &NodeVelocity<Dim>::mapped, ctx.time);
    dofs_.build(g, touched, fraction, options_.weak_node_fraction,
                [&](Index a, int d) { return probe[a].mapped[d] == 0; });
    if (options_.newton_trace) {  // the weak-node split of this step
      Real weakest = 1e300;
      Index at = -1;
      for (const auto& [a, d] : dofs_.dofs)
        if (fraction[a] < weakest) weakest = fraction[a], at = a;
      std::fprintf(stderr, "step %ld: %zu masters, %ld slaves, %ld weak kept; weakest master node %ld fraction %.3e\n",
                   static_cast<long>(ctx.step), dofs_.dofs.size(), static_cast<long>(dofs_.slave_count()),
                   static_cast<long>(dofs_.weak_kept), static_cast<long>(at), weakest);
    }
    v_n_.assign(nodes, VecU<Dim>::Zero());
    for (int d = 0; d < Dim; ++d) {
      std::vector<Real> b(nodes, 0), v(nodes, 0);
      for (Index a : dofs_.active) b[a] = probe[a].mapped[d] != 0 ? momentum_[a][d] : 0;
      for (Index a : dofs_.free_nodes[d]) v[a] = b[a] / mass_->lumped(a);  // the lumped-mass velocity as the start
      const int its = project_component(*mass_, dofs_, d, b, v, options_.mass_rtol,
                                        10 * static_cast<int>(dofs_.free_nodes[d].size()) + 100);
      if (its < 0) {
        StabilityReport report;
        report.step = ctx.step, report.time = ctx.time, report.body = "?", report.field = "grid_velocity";
        report.detail = fmt::format("the projection (87) did not reach mass_rtol = {:g}", options_.mass_rtol);
        throw StabilityError(report);
      }
      for (Index a : dofs_.free_nodes[d]) v_n_[a][d] = v[a];
      for (const auto& slave : dofs_.slaves[d]) v_n_[slave.node][d] = v[slave.node];
    }
  }

  /// The size of the residual's terms at the predictor: ||2 M v_n / dt|| + ||F^int|| + ||F^ext|| (free dofs).
  Real residual_reference(MixedResidual<Dim>& problem, const Vector& x, Real dt) const {
    Vector r;
    Real inertia = 0, external = 0;
    for (const auto& [a, d] : dofs_.dofs) {
      inertia += momentum_[a][d] * momentum_[a][d];  // M v_n = sum N pi on the free dofs (87)
      external += f_ext_[a][d] * f_ext_[a][d];
    }
    Real internal = 0;
    if (problem.residual(x, r))  // inertia is zero at the predictor: R = F^int - F^ext
      for (Index k = 0; k < problem.size(); ++k) {
        const Real f = r[k] + f_ext_[dofs_.dofs[k].first][dofs_.dofs[k].second];
        internal += f * f;
      }
    return 2 / dt * std::sqrt(inertia) + std::sqrt(internal) + std::sqrt(external);
  }

  /// Step 3 (92) with the accepted Delta phi, and the commit of the materials.
  void update_particles(StepContext<Dim>& ctx, const MixedResidual<Dim>& problem) {
    const auto& dphi = problem.increment();
    const Index nodes = ctx.grid.geometry.node_count();
    std::vector<VecU<Dim>> dv(nodes, VecU<Dim>::Zero());
    for (Index a : dofs_.active) dv[a] = 2 * dphi[a] / ctx.dt - 2 * v_n_[a];  // v_{n+1} - v_n (0 where held)
    const auto& F1 = problem.deformation_gradient();
    const auto& update = problem.update();
    const auto& theta = problem.mixed_volume();
    const auto& pressure = problem.pressure();
    std::vector<plasticity::HenckyJ2State<Dim>*> states;  // the fields, looked up once per body
    std::vector<Real*> thetas;
    std::vector<axisym::HoopFields> hoops;  // axisymmetric: F_tt and L_tt, else null
    for (auto& body : ctx.bodies) {
      states.push_back(body.particles.field(plasticity::keys::hencky_j2_state<Dim>).data());
      thetas.push_back(body.particles.field(plasticity::keys::mixed_volume).data());
      hoops.push_back(axisym::hoop_fields(body.particles));
    }
    WaveSpeedBound<Dim> bound;
    for (Index k = 0; k < points_.size(); ++k) {
      auto& body = ctx.bodies[points_.body[k]];
      auto& p = body.particles;
      const Index i = points_.index[k];
      Vec<Dim> dx = Vec<Dim>::Zero(), dvel = Vec<Dim>::Zero();
      for (int a = 0; a < StepPoints<Dim>::count; ++a) {
        dx += points_.w[k][a] * Vec<Dim>(dphi[points_.node[k][a]]);
        dvel += points_.w[k][a] * Vec<Dim>(dv[points_.node[k][a]]);
      }
      p.x[i] = Vec<Dim>(p.x[i]) + dx;
      p.v[i] = Vec<Dim>(p.v[i]) + dvel;
      p.F[i] = F1[k].template topLeftCorner<Dim, Dim>();
      if (const auto& hoop = hoops[points_.body[k]]; hoop.stretch) {
        hoop.stretch[i] = F1[k](2, 2);
        hoop.rate[i] = (F1[k](2, 2) / points_.F_n[k](2, 2) - 1) / ctx.dt;  // the mean L_tt over the step
      }
      plasticity::HenckyJ2::commit(states[points_.body[k]][i], update[k]);
      thetas[points_.body[k]][i] = theta[k];
      const Real J = F1[k].determinant();
      Mat3 sigma = update[k].dev_kirchhoff / J;  // Cauchy stress: dev tau / J + p (the mixed pressure, eq. 90)
      sigma.diagonal().array() += pressure[k];
      p.stress[i] = SymTensor<Dim>::from(sigma);
      if (!p.x[i].allFinite() || !(J > 0)) ctx.guard_tripped.store(true);
    }
    for (auto& body : ctx.bodies) bound.merge(body.material->wave_speed_bound(body.particles));
    ctx.wave_speed = bound;
  }

  [[noreturn]] void fail(const StepContext<Dim>& ctx, const NewtonStats& stats) const {
    StabilityReport report;
    report.step = ctx.step;
    report.time = ctx.time;
    report.body = "all";
    report.field = "newton";
    report.detail = fmt::format(
        "the implicit step did not converge: {}; ||R|| = {:.6g} after {} iterations (first {:.6g}), tolerance "
        "{:.6g} (newton_rtol x reference residual, or newton_atol); dt = {:g} s",
        stats.failure, stats.last_residual, stats.iterations, stats.first_residual, stats.tolerance, ctx.dt);
    throw StabilityError(report);
  }

  ImplicitOptions options_;
  StepPoints<Dim> points_;
  std::unique_ptr<ConsistentMass<Dim>> mass_;
  FreeDofs<Dim> dofs_;
  std::vector<VecU<Dim>> momentum_, f_ext_, v_n_;
  StepRecord record_;
};

}  // namespace mpm::implicit
