// The books of the local damping (simulation/local_damping_book.hpp; docs/theory.md eq. 2.75).
#include "mpm/simulation/local_damping_book.hpp"

#include <algorithm>
#include <span>

#include "mpm/core/exact_sum.hpp"
#include "mpm/core/state_archive.hpp"
#include "mpm/parallel/communicator.hpp"
#include "mpm/schemes/local_damping.hpp"

namespace mpm {
namespace {

/// Adds -dt f_d . (v^t + v^{t+dt})/2 of every node of `grid` in `nodes` this rank owns to `sum` (eq. 2.75).
template <int Dim>
void add_damping_work(const Grid<Dim>& grid, const StepContext<Dim>& ctx, Real alpha, ExactSum& sum) {
  const Real cutoff = ctx.settings.mass_cutoff, dt = ctx.dt;
  const Vec<Dim> gravity = ctx.settings.gravity;
  for_each_node_in_order(grid.size(), ctx.active_nodes, [&](Index I) {
    const NodeRecord<Dim>& n = grid.node[I];
    if (!(n.mass > cutoff) || !ctx.owned_nodes.contains(I)) return;
    const NodeVelocity<Dim>& v = grid.velocity[I];
    const Vec<Dim> f_d =
        kernels::local_damping_force<Dim>(n.force + n.mass * gravity, Vec<Dim>(v.mapped), alpha);
    sum += -0.5 * dt * f_d.dot(Vec<Dim>(v.mapped) + Vec<Dim>(v.updated));
  });
}

}  // namespace

template <int Dim>
LocalDampingBook<Dim>::LocalDampingBook(Real alpha, std::vector<int> undamped_bodies)
    : alpha_(alpha), undamped_bodies_(std::move(undamped_bodies)) {}

template <int Dim>
void LocalDampingBook<Dim>::on_grid_velocity(StepContext<Dim>& ctx, GridStage stage) {
  if (stage != GridStage::updated) return;
  ExactSum work;
  bool shared = false;
  for (const auto& body : ctx.bodies) {
    if (!body.separate_grid) {
      shared = true;
      continue;
    }
    if (std::find(undamped_bodies_.begin(), undamped_bodies_.end(), body.index) == undamped_bodies_.end())
      add_damping_work(*body.separate_grid, ctx, alpha_, work);
  }
  if (shared) add_damping_work(ctx.grid, ctx, alpha_, work);
  if (ctx.comm) ctx.comm->sum(std::span<ExactSum>(&work, 1));  // each rank summed the nodes it owns
  dissipated_ += work.value();
}

template <int Dim>
void LocalDampingBook<Dim>::save_state(StateArchive& archive, const std::string& prefix) const {
  archive.put_number(prefix + "dissipated", dissipated_);
}

template <int Dim>
void LocalDampingBook<Dim>::restore_state(const StateArchive& archive, const std::string& prefix) {
  dissipated_ = archive.number(prefix + "dissipated");
}

template class LocalDampingBook<1>;
template class LocalDampingBook<2>;
template class LocalDampingBook<3>;

}  // namespace mpm
