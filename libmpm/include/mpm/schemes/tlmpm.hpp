#pragma once
/// \file tlmpm.hpp
/// Total-Lagrangian MPM (review §2.6, Algorithm 3, with the MUSL double mapping). Weights and gradients
/// are taken at the reference positions X_p, computed once and cached, with the nodal mass
/// m_I = sum phi_I(X_p) m_p (constant: docs/errata.md #35). Each step:
///   (mv)_I = sum phi_I(X_p) m_p v_p;  f_I = -sum V_p^0 P_p grad_0 phi_I(X_p) + m_I g, P = J sigma F^-T;
///   v~_I = (mv + dt f)/m;  v_p = alpha (v_p + sum phi (v~ - v)) + (1 - alpha) sum phi v~;
///   (mv)_I^{t+dt} = sum phi m_p v_p -> v_I^{t+dt};  dF/dt = sum v_I^{t+dt} (x) grad_0 phi (eq. 2.67);
///   F += dt dF/dt;  L = dF/dt F^-1 (eq. 2.69);  stress update;  x_p += dt sum phi v_I^{t+dt} (for output
///   only; with the same velocity as F, so that x_p - X_p stays the displacement whose gradient is F - I).
/// The grid only needs to cover the reference shape: current positions may leave it. Particles are
/// never reordered (the cache is in particle order). There is no automatic contact between bodies.
/// The cache holds tensor-product stencils in factored form (factored_stencil.hpp): the three particle
/// passes per step read it, and at 104 B per particle (hats, 3D) instead of 368 B it stays in cache.
/// Axisymmetric (Coords), the reference-radius form: dF_tt/dt = sum phi_I(X_p) v_rI / R_p, F_tt += dt dF_tt/dt
/// (so F_tt = r/R with x_p moved by the same velocity), L_tt = dF_tt/dt / F_tt; the nominal stress is
/// F_tt sigma cof(F) in plane and P_tt = det(F) sigma_tt, whose force is -V_0 P_tt phi_I(X_p) / R_p
/// (axisymmetric.hpp). The cache is then the full stencil with its hoop weights.

#include <tbb/enumerable_thread_specific.h>

#include <array>

#include "mpm/core/parallel_chunks.hpp"
#include "mpm/particles/field_keys.hpp"
#include "mpm/schemes/explicit_step.hpp"
#include "mpm/schemes/scheme.hpp"
#include "mpm/shape/factored_stencil.hpp"

namespace mpm {

template <int Dim, class Shape, class Coords = CartesianCoordinates>
class Tlmpm final : public ShapedScheme<Dim, Shape> {
 public:
  std::string_view name() const override { return "tlmpm"; }
  bool reorders_particles() const override { return false; }
  bool positions_must_stay_in_grid() const override { return false; }

  /// Sorts each body by reference cell once, bins it by slab, caches phi_I(X_p) and grad_0 phi_I(X_p),
  /// and computes the constant nodal mass.
  void initialize(std::vector<Body<Dim>>& bodies, Grid<Dim>& grid) override {
    nodal_mass_.assign(grid.size(), 0);
    for (std::size_t b = 0; b < bodies.size(); ++b) {
      auto& p = bodies[b].particles;
      p.gather(order_by_cell(p, grid.geometry, Shape::slab_cells));
      auto& X = p.add_field(keys::reference_position<Dim>, VecU<Dim>::Zero());
      for (Index i = 0; i < p.size(); ++i) X[i] = p.x[i];
    }
    particles_redistributed(bodies, grid);
    // The constant nodal mass, summed in storage order over every particle: a distributed run computes it before
    // its ranks keep their own particles, so every rank holds the one-process sums.
    for (std::size_t b = 0; b < bodies.size(); ++b) {
      const auto& p = bodies[b].particles;
      for (Index i = 0; i < p.size(); ++i)
        for_each_node(stencils_[b][i], grid.geometry,
                      [&](Index n, Real w, const Vec<Dim>&) { nodal_mass_[n] += w * p.mass[i]; });
    }
  }

  /// Bins the particles by the slab of their reference position and caches their stencils (again after a
  /// distributed run moved particles between ranks: they migrate by reference position, never by motion).
  void particles_redistributed(std::vector<Body<Dim>>& bodies, Grid<Dim>& grid) override {
    stencils_.assign(bodies.size(), {});
    for (std::size_t b = 0; b < bodies.size(); ++b) {
      auto& p = bodies[b].particles;
      const auto& X = p.field(keys::reference_position<Dim>);
      ParticleSet<Dim> reference;  // binned by X: bin_by_tile reads positions
      reference.x = X;
      bin_by_tile(reference, grid.geometry, Shape::slab_cells, bodies[b].bins);
      auto& cache = stencils_[b];
      cache.resize(p.size());
      const ParticleDomain<Dim, Shape> domain(p);
      for (Index i = 0; i < p.size(); ++i) cache[i].compute(X[i], grid.geometry, domain(i));
    }
  }
  bool runs_distributed() const override { return true; }
  const VecU<Dim>* ownership_positions(const ParticleSet<Dim>& p) const override {
    return p.field(keys::reference_position<Dim>).data();
  }

  void advance(StepContext<Dim>& ctx) override {
    auto& grid = ctx.grid;
    PhaseTimer p2g(ctx.profile, StepPhase::p2g);
    parallel_chunks(Index{0}, grid.size(), 1 << 12, [&](Index chunk_begin, Index chunk_end) {
      for (Index i = chunk_begin; i != chunk_end; ++i) {
        grid.node[i].mass = nodal_mass_[i];
        grid.node[i].momentum.setZero();
        grid.node[i].force.setZero();
      }
    });
    for (std::size_t b = 0; b < ctx.bodies.size(); ++b) map_momentum_and_force(ctx.bodies[b], stencils_[b], grid);
    p2g.stop();
    PhaseTimer grid_update(ctx.profile, StepPhase::grid_update);
    ctx.hooks.after_p2g(ctx);  // the face tractions first (GridBoundary): nominal tractions here
    kernels::update_grid_velocity(grid, ctx.settings, ctx.dt);
    ctx.hooks.grid_velocity(ctx, GridStage::mapped);
    ctx.hooks.grid_velocity(ctx, GridStage::updated);
    grid_update.stop();

    PhaseTimer remap(ctx.profile, StepPhase::p2g);
    parallel_chunks(Index{0}, grid.size(), 1 << 14, [&](Index chunk_begin, Index chunk_end) {
      for (Index i = chunk_begin; i != chunk_end; ++i) grid.node[i].momentum.setZero();
    });
    for (std::size_t b = 0; b < ctx.bodies.size(); ++b) update_velocity_and_remap(ctx.bodies[b], stencils_[b], ctx);
    remap.stop();
    PhaseTimer remapped_velocity(ctx.profile, StepPhase::grid_update);
    parallel_chunks(Index{0}, grid.size(), 1 << 12, [&](Index chunk_begin, Index chunk_end) {
      for (Index i = chunk_begin; i != chunk_end; ++i) {
        const NodeRecord<Dim>& n = grid.node[i];
        if (n.mass > ctx.settings.mass_cutoff)
          grid.velocity[i].mapped = n.momentum / n.mass;
        else
          grid.velocity[i].mapped.setZero();
      }
    });
    ctx.hooks.grid_velocity(ctx, GridStage::remapped);
    remapped_velocity.stop();

    // The grid is the reference configuration: a wave moving at c in the current configuration moves at
    // most at c |row_a(F^-1)| along reference axis a, so the CFL speeds are scaled by the largest of those
    // row norms (a compressed foot shortens the stable step; found by the Taylor anvil).
    tbb::enumerable_thread_specific<Vec<Dim>> row_norm2(Vec<Dim>::Zero());
    kernels::transfer_and_update_stress(ctx, [&](Body<Dim>& body, Index begin, Index end, MatU<Dim>* L) {
      return deform(body, stencils_[static_cast<std::size_t>(body.index)], ctx, begin, end, L, row_norm2.local());
    });
    Vec<Dim> scale2 = Vec<Dim>::Zero();
    for (const auto& r : row_norm2) scale2 = scale2.cwiseMax(r);
    if (ctx.comm) {  // a distributed run: the scale and the speeds of all ranks, as one process takes them
      std::array<double, std::size_t{2} * Dim> v{};
      for (int d = 0; d < Dim; ++d) {
        v[d] = scale2[d];
        v[Dim + d] = ctx.wave_speed.max_speed[d];
      }
      ctx.comm->max(v);
      for (int d = 0; d < Dim; ++d) {
        scale2[d] = v[d];
        ctx.wave_speed.max_speed[d] = v[Dim + d];
      }
    }
    const Vec<Dim> scale = scale2.cwiseSqrt();
    ctx.wave_speed.max_speed = ctx.wave_speed.max_speed.cwiseProduct(scale);
  }

 private:
  using Cache = std::vector<
      std::conditional_t<Coords::axisymmetric, axisym::StencilFor<Dim, Shape, Coords>, ReferenceStencil<Dim, Shape>>>;

  /// cof(F) = J F^-T, without a division (the nominal stress needs J F^-T, the inverse cof^T / J).
  static Mat<Dim> cofactor(const Mat<Dim>& F) {
    Mat<Dim> c;
    if constexpr (Dim == 1) {
      c(0, 0) = 1;
    } else if constexpr (Dim == 2) {
      c << F(1, 1), -F(1, 0), -F(0, 1), F(0, 0);
    } else {
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
          const int i1 = (i + 1) % 3, i2 = (i + 2) % 3, j1 = (j + 1) % 3, j2 = (j + 2) % 3;
          c(i, j) = F(i1, j1) * F(i2, j2) - F(i1, j2) * F(i2, j1);
        }
    }
    return c;
  }

  /// (mv)_I and f_I = -sum V0 P grad_0 phi, scattered with the slab colouring of the reference positions.
  static void map_momentum_and_force(Body<Dim>& body, const Cache& cache, Grid<Dim>& grid) {
    const auto& p = body.particles;
    const auto& geometry = grid.geometry;
    NodeRecord<Dim>* node = grid.node.data();
    const VecU<Dim>* body_force = kernels::body_force_of(p);
    const Real* hoop_stretch = Coords::axisymmetric ? axisym::hoop_stretch_of(p) : nullptr;
    for_each_tile_coloured(body.bins, {HaloArray::of(grid.node)}, [&](const Index* index, Index count) {
      for (Index k = 0; k < count; ++k) {
        const Index i = index[k];
        // First Piola-Kirchhoff stress P = J sigma F^-T = sigma cof(F) (review Table 4), times V0.
        Real V0 = p.volume0[i];
        [[maybe_unused]] Real v_hoop = 0;  // V0 P_tt
        if constexpr (Coords::axisymmetric) {
          v_hoop = V0 * axisym::nominal_hoop_stress(p.F[i], p.stress[i].c[2]);
          V0 *= hoop_stretch[i];  // J F^-T = F_tt cof(F) in plane
        }
        const Mat<Dim> vP = V0 * (p.stress[i].block() * cofactor(p.F[i]));
        const Vec<Dim> mv = p.mass[i] * p.v[i];
        const Vec<Dim> mb = body_force ? Vec<Dim>(p.mass[i] * body_force[i]) : Vec<Dim>::Zero();
        axisym::for_each_node_with_hoop<Coords>(cache[i], geometry, [&](Index a, Real w, const Vec<Dim>& grad, Real T) {
          NodeRecord<Dim>& n = node[a];
          n.momentum += w * mv;
          n.force += w * mb - vP * grad;
          if constexpr (Coords::axisymmetric) n.force[0] += axisym::hoop_force(v_hoop, T);
        });
      }
    });
  }

  static void update_velocity_and_remap(Body<Dim>& body, const Cache& cache, StepContext<Dim>& ctx) {
    auto& p = body.particles;
    const auto& geometry = ctx.grid.geometry;
    NodeRecord<Dim>* node = ctx.grid.node.data();
    const NodeVelocity<Dim>* vel = ctx.grid.velocity.data();
    const Real alpha = ctx.settings.flip_fraction;
    for_each_tile_coloured(body.bins, {HaloArray::of(ctx.grid.node)}, [&](const Index* index, Index count) {
      for (Index k = 0; k < count; ++k) {
        const Index i = index[k];
        const auto& st = cache[i];
        Vec<Dim> v_pic = Vec<Dim>::Zero(), dv = Vec<Dim>::Zero();
        for_each_node(st, geometry, [&](Index a, Real w, const Vec<Dim>&) {
          const NodeVelocity<Dim>& nv = vel[a];
          v_pic += w * nv.updated;
          dv += w * (nv.updated - nv.mapped);
        });
        const Vec<Dim> v = alpha * (p.v[i] + dv) + (1 - alpha) * v_pic;
        p.v[i] = v;
        const Vec<Dim> mv = p.mass[i] * v;
        for_each_node(st, geometry, [&](Index a, Real w, const Vec<Dim>&) { node[a].momentum += w * mv; });
      }
    });
  }

  /// dF/dt = sum v_I^{t+dt} (x) grad_0 phi (eq. 2.67), F += dt dF/dt, L = dF/dt F^-1 (eq. 2.69).
  static bool deform(Body<Dim>& body, const Cache& cache, const StepContext<Dim>& ctx, Index begin, Index end,
                     MatU<Dim>* L_out, Vec<Dim>& max_row_norm2) {
    auto& p = body.particles;
    const NodeVelocity<Dim>* vel = ctx.grid.velocity.data();
    [[maybe_unused]] const axisym::HoopFields hoop =
        Coords::axisymmetric ? axisym::hoop_fields(p) : axisym::HoopFields{};
    bool ok = true;
    for (Index i = begin; i != end; ++i) {
      Mat<Dim> Fdot = Mat<Dim>::Zero();
      Vec<Dim> v_move = Vec<Dim>::Zero();
      for_each_node(cache[i], ctx.grid.geometry, [&](Index a, Real w, const Vec<Dim>& grad) {
        const Vec<Dim> v = vel[a].mapped;
        v_move += w * v;  // the re-mapped v^{t+dt}, like F (Alg. 3): positions stay consistent with F
        Fdot.noalias() += v * grad.transpose();
      });
      p.x[i] += ctx.dt * v_move;
      const Mat<Dim> F = Mat<Dim>(p.F[i]) + ctx.dt * Fdot;
      p.F[i] = F;
      const Real J = F.determinant();
      if constexpr (Coords::axisymmetric) {  // dF_tt/dt = sum phi_I(X) v_rI / R (the reference-radius form)
        const Real hoop_dot = axisym::hoop_rate(cache[i], [&](Index n) { return vel[n].mapped; });
        hoop.stretch[i] += ctx.dt * hoop_dot;
        hoop.rate[i] = hoop_dot / hoop.stretch[i];
        ok &= hoop.stretch[i] > 0 && std::isfinite(hoop.rate[i]);
      }
      ok &= J > 0 && std::isfinite(J) && p.x[i].allFinite() && std::isfinite(p.v[i].sum());
      const Mat<Dim> F_inv = cofactor(F).transpose() * (1 / J);
      L_out[i - begin] = Fdot * F_inv;
      max_row_norm2 = max_row_norm2.cwiseMax(F_inv.rowwise().squaredNorm());
    }
    return ok;
  }

  std::vector<Cache> stencils_;
  std::vector<Real> nodal_mass_;
};

}  // namespace mpm
