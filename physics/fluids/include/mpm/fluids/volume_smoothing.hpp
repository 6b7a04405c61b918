#pragma once
/// \file volume_smoothing.hpp
/// Node-averaged volume ratio of a weakly compressible fluid (docs/theory.md eqs PS.1-PS.3): between the
/// grid-to-particle transfer and the stress update of every explicit step, each smoothed body's particle volume
/// ratios are mapped to the nodes by mass and interpolated back,
///   J_I = sum_p phi_I(x_p) m_p J_p / sum_p phi_I(x_p) m_p,   Jbar_p = sum_I phi_I(x_p) J_I       (eq. PS.1)
/// and F_p <- (Jbar_p / J_p)^(1/Dim) F_p (the in-plane F; the hoop stretch of an axisymmetric body is kept), so the
/// pressure, the stored energy and the density of the particle all read Jbar_p. The cell-crossing noise of J_p,
/// a mode below the grid's resolution, no longer reaches the pressure.
/// The weights are linear hats at the particle positions of the start of the step (x^t, copied in before_step):
/// the positions the step's tile bins were made from, so the scatter is race-free and, in a distributed run, its
/// ghost nodes are exchanged like P2G's (every holder ends with the serial sum, bit for bit). A hat reaches no node
/// that the scheme's shape function does not (its cell's corners), so the bins and halo of any function serve.
/// Books: sum_p m_p Jbar_p = sum_p m_p J_p (the body's volume is kept; eq. PS.2), and since W(J) is convex and
/// Jbar_p a convex combination of the J_q, sum_p V0_p W(Jbar_p) <= sum_p V0_p W(J_p): the averaging only removes
/// stored energy. What it removes is summed (energy.csv column `smoothed_energy`, eq. PS.3) but not booked as removed
/// in the sentinel's balance (smoothed_energy() says why). The only state is that sum (checkpointed).

#include <algorithm>
#include <cmath>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "mpm/core/parallel_chunks.hpp"
#include "mpm/core/state_archive.hpp"
#include "mpm/grid/node_runs.hpp"
#include "mpm/grid/tile_binning.hpp"
#include "mpm/parallel/communicator.hpp"
#include "mpm/schemes/axisymmetric.hpp"
#include "mpm/shape/linear_hat.hpp"
#include "mpm/shape/stencil.hpp"
#include "mpm/simulation/module.hpp"

namespace mpm::fluids {

template <int Dim>
class VolumeSmoothing final : public Module<Dim> {
 public:
  /// `bodies`: the indices (Body::index) of the bodies whose J is smoothed, each on its own nodal field.
  explicit VolumeSmoothing(std::vector<int> bodies) : bodies_(std::move(bodies)) {}

  std::string_view name() const override { return "pressure_smoothing"; }
  unsigned phases() const override { return phase_before_step | phase_after_g2p; }
  /// Its scatter names the arrays it writes; the gather reads only nodes the holders have whole; the booked
  /// energy is reduced through the communicator.
  std::string why_not_distributed() const override { return {}; }

  void before_step(StepContext<Dim>& ctx) override {
    start_.resize(bodies_.size());
    for (std::size_t k = 0; k < bodies_.size(); ++k) {
      const auto& p = body(ctx, k).particles;
      start_[k].assign(p.x.begin(), p.x.end());
    }
  }

  void after_g2p(StepContext<Dim>& ctx) override {
    const Index nodes = ctx.grid.geometry.node_count();
    if (static_cast<Index>(mass_.size()) != nodes) {
      mass_.assign(static_cast<std::size_t>(nodes), 0);
      volume_.assign(static_cast<std::size_t>(nodes), 0);
    }
    // the strain energy of the smoothed bodies before and after, each summed exactly over particles and ranks, so
    // that their difference has the same bits on any rank count
    ExactSum energy[2];
    for (std::size_t k = 0; k < bodies_.size(); ++k) {
      Body<Dim>& b = body(ctx, k);  // a rank without particles of the body joins the scatter's exchange too
      b.material->add_strain_energy(b.particles, energy[0]);
      smooth(ctx, b, start_[k]);
      b.material->add_strain_energy(b.particles, energy[1]);
    }
    if (ctx.comm) ctx.comm->sum(std::span<ExactSum>(energy, 2));
    removed_ += energy[0].value() - energy[1].value();
  }

  /// J: the stored energy the averaging has removed since t = 0 (eq. PS.3), the same on every rank: energy.csv's
  /// `smoothed_energy`, for information. Not removed_energy(): the sentinel's balance does not add it (it is 0),
  /// because most of it is stored energy that the cell crossings put into J without work (the gain of FLIP with
  /// hats): booked, E + smoothed_energy rose 24.6% of E0 on the review's dam break at 35 cells, while E itself
  /// never rose above E0 (docs/theory.md §10, physics/fluids/README.md).
  Real smoothed_energy() const { return removed_; }
  std::string_view energy_column() const override { return "smoothed_energy"; }
  Real energy_column_value() const override { return removed_; }

  void save_state(StateArchive& archive, const std::string& prefix) const override {
    archive.put_number(prefix + "smoothed_energy", removed_);
  }
  void restore_state(const StateArchive& archive, const std::string& prefix) override {
    removed_ = archive.number(prefix + "smoothed_energy");
  }

 private:
  Body<Dim>& body(StepContext<Dim>& ctx, std::size_t k) const {
    return ctx.bodies[static_cast<std::size_t>(bodies_[k])];
  }

  /// Eq. PS.1 on one body: scatter m_p and m_p J_p with hats at x^t, then Jbar_p and the scaled F_p.
  void smooth(StepContext<Dim>& ctx, Body<Dim>& b, const std::vector<VecU<Dim>>& x) {
    const auto& g = ctx.grid.geometry;
    auto& p = b.particles;
    const Real* hoop = axisym::hoop_stretch_of(p);
    Real* mass = mass_.data();
    Real* volume = volume_.data();
    for_each_node_block(static_cast<Index>(mass_.size()), ctx.active_nodes, 1 << 14, [&](Index begin, Index end) {
      std::fill(mass + begin, mass + end, Real(0));
      std::fill(volume + begin, volume + end, Real(0));
    });
    const HaloArray written[2] = {HaloArray::of(mass_), HaloArray::of(volume_)};
    for_each_tile_coloured(b.bins, std::span<const HaloArray>(written, 2), [&](const Index* index, Index count) {
      Stencil<Dim, LinearHat> st;
      for (Index k = 0; k < count; ++k) {
        const Index i = index[k];
        st.compute(x[static_cast<std::size_t>(i)], g);
        const Real m = p.mass[i], mJ = m * axisym::volume_ratio(p, i, hoop);
        for (int a = 0; a < st.count; ++a) {
          mass[st.node[a]] += st.w[a] * m;
          volume[st.node[a]] += st.w[a] * mJ;
        }
      }
    });
    parallel_chunks(Index{0}, p.size(), 1024, [&](Index chunk_begin, Index chunk_end) {
      Stencil<Dim, LinearHat> st;
      for (Index i = chunk_begin; i != chunk_end; ++i) {
        const Real J = axisym::volume_ratio(p, i, hoop);
        if (!(J > 0)) continue;  // the stability guard names it
        st.compute(x[static_cast<std::size_t>(i)], g);
        Real smoothed = 0;
        for (int a = 0; a < st.count; ++a)
          if (st.w[a] > 0) smoothed += st.w[a] * volume[st.node[a]] / mass[st.node[a]];
        const Real scale = Dim == 1 ? smoothed / J : std::pow(smoothed / J, Real(1) / Dim);
        p.F[i] = MatU<Dim>(scale * Mat<Dim>(p.F[i]));
      }
    });
  }

  std::vector<int> bodies_;
  std::vector<std::vector<VecU<Dim>>> start_;  ///< scratch: x^t of each smoothed body's particles
  std::vector<Real> mass_, volume_;            ///< scratch: sum phi m and sum phi m J per node
  Real removed_ = 0;                           ///< J, eq. PS.3 summed over the steps
};

}  // namespace mpm::fluids
