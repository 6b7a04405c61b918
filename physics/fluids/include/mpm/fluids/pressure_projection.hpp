#pragma once
/// \file pressure_projection.hpp
/// The pressure projection of the incompressible fluids (`model: incompressible_fluid`; docs/theory.md §21,
/// Chorin's projection on the MPM grid). After the momentum update of every explicit step the trial nodal velocity
/// v* (gravity, viscous and face forces, no pressure) is made divergence-free cell by cell:
///   G_{c,(I,d)} = int_c dphi_I/dx_d dV                  (hats, eq. 21.1a; one row per fluid cell c)
///   G_{c,(I,d)} = sum_{p in c} V_p dphi_I/dx_d (x_p)    (B-splines, eq. 21.1b)
///   G W G^T p = -G v* / dt,   W = diag(1 / m_I) on the free components        (eq. 21.2)
///   v = v* + dt W G^T p                                                        (eq. 21.3)
/// G v is the integral of div v over each fluid cell (the shape function of the scheme) and G^T p the nodal force of
/// the stress -p I with p constant in each cell (the internal force of eq. 2.63): the pressure is the multiplier of
/// the constraint G v = 0. The fluid cells are those that hold a fluid particle at x^t; a cell without one is outside
/// the fluid, at p = 0 (the free surface). Two quadratures, each the one that keeps a column of water at rest
/// (docs/theory.md §21): with hats the exact integral over the whole cell (the net flux out of it; a surface cell is
/// constrained whole, as in the marker-and-cell method) — G by the particles' gradients let the column's grid-scale
/// perturbations grow 8x per step; with B-splines the particles, the quadrature of the nodal masses and so of gravity
/// — the cell integral reaches the nodes above the surface that only the particles' mass holds, and the column
/// started to move at 0.06 m/s. A component held by a face
/// condition (fixed, slip, a prescribed velocity) keeps its value: W is 0 there, and the held velocity enters the
/// right-hand side; a node lighter than the mass cut-off has no velocity (eq. 2.63) and no entry. Solved by conjugate
/// gradients with a diagonal (Jacobi) preconditioner, from the particles' pressures of the last step; a solve that does
/// not reach the tolerance within its iterations stops the run with a message (both are the material's keys). The
/// pressure of a particle is that of its cell (eq. 21.4): added to its stress as -p I at the end of the step (the
/// output, the histories and the checkpoint see it), and taken off again before the next transfer, since the
/// projection, not the stress divergence, applies it. Every fluid particle keeps its volume (F = I: the schemes leave
/// it, Material::tracks_deformation): the constraint is one per cell, and a particle's own div v only carries that
/// constraint's error (a splash's gradient over one step can exceed 1/dt).
/// v is the M-orthogonal projection of v* (W M = I on the free components and G v = 0): the projection never adds
/// kinetic energy to the grid (eq. 21.5).

#include <fmt/format.h>
#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCore>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "mpm/boundary/grid_boundary.hpp"
#include "mpm/fluids/field_keys.hpp"
#include "mpm/shape/stencil.hpp"
#include "mpm/simulation/module.hpp"

namespace mpm::fluids {

/// What the solves of a run took: for the log, the tests and the performance report.
struct ProjectionStatistics {
  Index solves = 0;
  Index iterations = 0;          ///< conjugate-gradient iterations, summed over the solves
  Index largest_iterations = 0;  ///< of one solve
  Index largest_cells = 0;       ///< unknowns of one solve
  Real largest_residual = 0;     ///< |A p - b| / |b| of any solve
};

template <int Dim, class Shape>
class PressureProjection final : public Module<Dim> {
 public:
  /// `bodies`: the indices (Body::index) of the incompressible bodies, each with the field projected_pressure.
  /// `tolerance`: the relative residual of the solves; `max_iterations`: per solve; `material`: the key of the
  /// material that set them ("materials.water"), for the message of a solve that stops short.
  PressureProjection(std::vector<int> bodies, const Vec<Dim>& gravity, Real h_min, Real tolerance, int max_iterations,
                     std::string material)
      : bodies_(std::move(bodies)),
        gravity_(gravity.norm()),
        h_min_(h_min),
        tolerance_(tolerance),
        max_iterations_(max_iterations),
        material_(std::move(material)) {}

  std::string_view name() const override { return "pressure_projection"; }
  unsigned phases() const override { return phase_before_step | phase_grid_velocity | phase_end_of_step; }
  std::string why_not_distributed() const override {
    return "the pressure projection of an incompressible fluid solves one linear system over the whole fluid each "
           "step, and that system is not split over ranks yet (threads still apply)";
  }
  /// The free fall through one cell, dt <= sqrt(h / |g|): a fluid at rest has no speed for the CFL bound, and
  /// without a sound speed nothing else bounds the first steps.
  Real stable_time_step(const std::vector<Body<Dim>>&) const override {
    return gravity_ > 0 ? std::sqrt(h_min_ / gravity_) : std::numeric_limits<Real>::infinity();
  }
  std::string_view time_step_bound() const override { return "free fall through one cell sqrt(h / |g|)"; }

  /// Takes the pressure the last step added (eq. 21.4) off the stress: the projection applies it, not the transfer.
  void before_step(StepContext<Dim>& ctx) override {
    for (const int k : bodies_) {
      auto& p = ctx.bodies[static_cast<std::size_t>(k)].particles;
      const auto& pressure = p.field(keys::projected_pressure);
      for (Index i = 0; i < p.size(); ++i)
        for (int d = 0; d < 3; ++d) p.stress[i].c[d] += pressure[static_cast<std::size_t>(i)];
    }
  }

  void on_grid_velocity(StepContext<Dim>& ctx, GridStage stage) override {
    if (stage == GridStage::updated) project(ctx);
  }

  /// The pressure into the stress (eq. 21.4).
  void end_of_step(StepContext<Dim>& ctx) override {
    for (const int k : bodies_) {
      auto& p = ctx.bodies[static_cast<std::size_t>(k)].particles;
      const auto& pressure = p.field(keys::projected_pressure);
      for (Index i = 0; i < p.size(); ++i)
        for (int d = 0; d < 3; ++d) p.stress[i].c[d] -= pressure[static_cast<std::size_t>(i)];
    }
  }

  const ProjectionStatistics& statistics() const { return statistics_; }

 private:
  using SparseMatrix = Eigen::SparseMatrix<Real>;
  using Vector = Eigen::Matrix<Real, Eigen::Dynamic, 1>;

  /// The components the face conditions hold: a probe of NaN velocities through GridBoundary::apply, once (the
  /// conditions hold the same components at every time; only their values change).
  void find_held(const StepContext<Dim>& ctx) {
    const Index nodes = ctx.grid.geometry.node_count();
    const Real nan = std::numeric_limits<Real>::quiet_NaN();
    NodeArray<NodeVelocity<Dim>> probe(static_cast<std::size_t>(nodes),
                                       NodeVelocity<Dim>{VecU<Dim>::Constant(nan), VecU<Dim>::Constant(nan)});
    ctx.boundary.apply(probe, &NodeVelocity<Dim>::updated, ctx.time + ctx.dt);
    held_.assign(static_cast<std::size_t>(nodes), 0);
    for (Index n = 0; n < nodes; ++n)
      for (int d = 0; d < Dim; ++d)
        if (!std::isnan(probe[static_cast<std::size_t>(n)].updated[d])) held_[static_cast<std::size_t>(n)] |= 1u << d;
  }

  /// The linear index of the cell that holds x (a particle on the grid's upper faces in the last cell).
  Index cell_of(const VecU<Dim>& x, const GridGeometry<Dim>& g) const {
    Index cell = 0, stride = 1;
    for (int d = 0; d < Dim; ++d) {
      const int cells = g.cells(d);
      const int c = std::clamp(static_cast<int>(std::floor((x[d] - g.origin[d]) * g.inv_h[d])), 0, cells - 1);
      cell += stride * c;
      stride *= cells;
    }
    return cell;
  }

  /// The column of component d of node n, numbered in order of first use.
  Index column(Index n, int d) {
    Index& c = column_of_[static_cast<std::size_t>(n * Dim + d)];
    if (c < 0) {
      c = static_cast<Index>(columns_.size());
      columns_.push_back(n * Dim + d);
    }
    return c;
  }

  /// Hats: G integrated over the whole cell (eq. 21.1a); wider functions: by the cell's particles (eq. 21.1b).
  static constexpr bool integrates_cells = Shape::support == 2;

  /// Eqs 21.1-21.3 on the grid's updated velocities, and each fluid particle's pressure (eq. 21.4).
  void project(StepContext<Dim>& ctx) {
    const auto& g = ctx.grid.geometry;
    if (held_.empty()) find_held(ctx);
    Index cell_count = 1;
    for (int d = 0; d < Dim; ++d) cell_count *= g.cells(d);
    if (static_cast<Index>(unknown_of_cell_.size()) != cell_count) unknown_of_cell_.assign(cell_count, -1);
    if (column_of_.size() != static_cast<std::size_t>(g.node_count() * Dim))
      column_of_.assign(static_cast<std::size_t>(g.node_count() * Dim), -1);
    const Real cutoff = ctx.settings.mass_cutoff;
    const auto& node = ctx.grid.node;
    auto& velocity = ctx.grid.velocity;

    // the fluid cells: those that hold a fluid particle (at x^t), numbered in order of first use
    cells_.clear();
    columns_.clear();
    entries_.clear();
    particle_unknown_.resize(bodies_.size());
    for (std::size_t k = 0; k < bodies_.size(); ++k) {
      const auto& p = ctx.bodies[static_cast<std::size_t>(bodies_[k])].particles;
      auto& unknown = particle_unknown_[k];
      unknown.resize(static_cast<std::size_t>(p.size()));
      for (Index i = 0; i < p.size(); ++i) {
        const Index cell = cell_of(p.x[i], g);
        Index& u = unknown_of_cell_[static_cast<std::size_t>(cell)];
        if (u < 0) {
          u = static_cast<Index>(cells_.size());
          cells_.push_back(cell);
        }
        unknown[static_cast<std::size_t>(i)] = u;
      }
    }
    // eq. 21.1: G by its entries
    Stencil<Dim, Shape> st;
    const auto add = [&](Index u, Real weight) {
      for (int a = 0; a < st.count; ++a) {
        if (!(node[static_cast<std::size_t>(st.node[a])].mass > cutoff)) continue;  // no velocity (eq. 2.63)
        for (int d = 0; d < Dim; ++d)
          if (st.grad[a][d] != 0)
            entries_.emplace_back(static_cast<int>(u), static_cast<int>(column(st.node[a], d)), weight * st.grad[a][d]);
      }
    };
    if constexpr (integrates_cells) {  // over the whole cell: the midpoint rule is exact (hats' gradients are linear)
      for (Index u = 0; u < static_cast<Index>(cells_.size()); ++u) {
        Index rest = cells_[static_cast<std::size_t>(u)];
        VecU<Dim> middle;
        for (int d = 0; d < Dim; ++d) {
          middle[d] = g.origin[d] + g.h[d] * (static_cast<Real>(rest % g.cells(d)) + Real(0.5));
          rest /= g.cells(d);
        }
        st.compute(middle, g);
        add(u, g.cell_volume());
      }
    } else {  // by the cell's particles, the quadrature of their mass
      for (std::size_t k = 0; k < bodies_.size(); ++k) {
        const auto& p = ctx.bodies[static_cast<std::size_t>(bodies_[k])].particles;
        for (Index i = 0; i < p.size(); ++i) {
          st.compute(p.x[i], g);
          add(particle_unknown_[k][static_cast<std::size_t>(i)], p.volume0[i]);  // F = I: V_p = V0_p
        }
      }
    }
    const Index n = static_cast<Index>(cells_.size()), m = static_cast<Index>(columns_.size());
    SparseMatrix G(n, m);
    G.setFromTriplets(entries_.begin(), entries_.end());
    Vector v_star(m), w(m);
    for (Index c = 0; c < m; ++c) {
      const Index nd = columns_[static_cast<std::size_t>(c)], nn = nd / Dim;
      const int d = static_cast<int>(nd % Dim);
      v_star[c] = velocity[static_cast<std::size_t>(nn)].updated[d];
      w[c] = (held_[static_cast<std::size_t>(nn)] >> d & 1u) ? 0 : 1 / node[static_cast<std::size_t>(nn)].mass;
    }
    // eq. 21.2
    const Vector b = -(G * v_star) / ctx.dt;
    // A = G W G^T from the columns of G: a free component couples the cells it touches (2^Dim with hats)
    a_entries_.clear();
    for (Index c = 0; c < m; ++c) {
      if (w[c] == 0) continue;
      for (SparseMatrix::InnerIterator i(G, c); i; ++i)
        for (SparseMatrix::InnerIterator j(G, c); j; ++j)
          a_entries_.emplace_back(static_cast<int>(i.row()), static_cast<int>(j.row()), w[c] * i.value() * j.value());
    }
    SparseMatrix A(n, n);
    A.setFromTriplets(a_entries_.begin(), a_entries_.end());
    Vector pressure = Vector::Zero(n);
    if (b.squaredNorm() > 0) {
      // the first guess: each cell's mean of its particles' pressures of the last step (particle fields, so a restart
      // starts its first solve from the same guess)
      Vector guess = Vector::Zero(n), count = Vector::Zero(n);
      for (std::size_t k = 0; k < bodies_.size(); ++k) {
        const auto& last = ctx.bodies[static_cast<std::size_t>(bodies_[k])].particles.field(keys::projected_pressure);
        for (std::size_t i = 0; i < last.size(); ++i) {
          guess[particle_unknown_[k][i]] += last[i];
          count[particle_unknown_[k][i]] += 1;
        }
      }
      guess = guess.cwiseQuotient(count);
      // Jacobi-preconditioned: on the tank of examples/14 at 40 cells per column width 1.5x faster than with an
      // incomplete Cholesky factor (half the iterations, each dearer and a factorization per step)
      Eigen::ConjugateGradient<SparseMatrix, Eigen::Lower | Eigen::Upper> cg;
      cg.setTolerance(tolerance_);
      cg.setMaxIterations(max_iterations_);
      cg.compute(A);
      pressure = cg.solveWithGuess(b, guess);
      ++statistics_.solves;
      statistics_.iterations += cg.iterations();
      statistics_.largest_iterations = std::max<Index>(statistics_.largest_iterations, cg.iterations());
      statistics_.largest_cells = std::max(statistics_.largest_cells, n);
      statistics_.largest_residual = std::max(statistics_.largest_residual, cg.error());
      if (cg.info() != Eigen::Success)
        throw std::runtime_error(fmt::format(
            "pressure projection: the conjugate gradients stopped after {} iterations at a relative residual of "
            "{:.3g}, "
            "above projection_tolerance = {:.3g} (step {}, t = {:.9g} s, {} fluid cells): raise "
            "{}.projection_iterations "
            "(or {}.projection_tolerance)",
            cg.iterations(), cg.error(), tolerance_, ctx.step, ctx.time, n, material_, material_));
    }
    // eq. 21.3
    const Vector dv = ctx.dt * w.cwiseProduct(G.transpose() * pressure);
    for (Index c = 0; c < m; ++c) {
      const Index nd = columns_[static_cast<std::size_t>(c)], nn = nd / Dim;
      if (w[c] != 0) velocity[static_cast<std::size_t>(nn)].updated[static_cast<int>(nd % Dim)] += dv[c];
    }
    // eq. 21.4
    for (std::size_t k = 0; k < bodies_.size(); ++k) {
      auto& p = ctx.bodies[static_cast<std::size_t>(bodies_[k])].particles;
      auto& field = p.field(keys::projected_pressure);
      for (Index i = 0; i < p.size(); ++i)
        field[static_cast<std::size_t>(i)] = pressure[particle_unknown_[k][static_cast<std::size_t>(i)]];
    }
    for (const Index c : cells_) unknown_of_cell_[static_cast<std::size_t>(c)] = -1;
    for (const Index c : columns_) column_of_[static_cast<std::size_t>(c)] = -1;
  }

  std::vector<int> bodies_;
  Real gravity_;
  Real h_min_;
  Real tolerance_;
  int max_iterations_;
  std::string material_;
  std::vector<unsigned char> held_;                   ///< per node: bit d set when a face holds component d
  std::vector<Index> unknown_of_cell_;                ///< scratch: per grid cell its unknown, or -1
  std::vector<Index> column_of_;                      ///< scratch: per node component its column of G, or -1
  std::vector<Index> cells_;                          ///< scratch: the cell of each unknown
  std::vector<Index> columns_;                        ///< scratch: node * Dim + d of each column
  std::vector<Eigen::Triplet<Real>> entries_;         ///< scratch: the entries of G
  std::vector<Eigen::Triplet<Real>> a_entries_;       ///< scratch: the entries of A = G W G^T
  std::vector<std::vector<Index>> particle_unknown_;  ///< scratch: per body and particle, its cell's unknown
  ProjectionStatistics statistics_;
};

}  // namespace mpm::fluids
