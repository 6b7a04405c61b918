// The books of the local damping (simulation/local_damping_book.hpp; docs/theory.md eq. 2.75).
#include "mpm/simulation/local_damping_book.hpp"

#include <algorithm>
#include <span>
#include <vector>

#include "mpm/core/exact_sum.hpp"
#include "mpm/core/state_archive.hpp"
#include "mpm/parallel/communicator.hpp"
#include "mpm/schemes/local_damping.hpp"

namespace mpm {

template <int Dim>
LocalDampingBook<Dim>::LocalDampingBook(Real alpha, std::vector<int> undamped_bodies)
    : alpha_(alpha), undamped_bodies_(std::move(undamped_bodies)) {}

template <int Dim>
void LocalDampingBook<Dim>::on_grid_velocity(StepContext<Dim>& ctx, GridStage stage) {
  if (stage != GridStage::updated) return;
  // The damped fields: the shared grid of the bodies that map to it, the own fields of the others (contact) but the
  // rigid bodies'. At a node of several fields each got m_k a_d, a_d of the fields' sum (shared_damping_acceleration),
  // as the contact module applied it; with one field that is eq. 2.74 itself.
  std::vector<const Grid<Dim>*> fields;
  for (const auto& body : ctx.bodies) {
    const Grid<Dim>* grid = body.separate_grid ? body.separate_grid : &ctx.grid;
    const bool undamped =
        std::find(undamped_bodies_.begin(), undamped_bodies_.end(), body.index) != undamped_bodies_.end();
    if (!undamped && std::find(fields.begin(), fields.end(), grid) == fields.end()) fields.push_back(grid);
  }
  const auto for_each_field = [&](auto&& visit) {
    for (const Grid<Dim>* grid : fields) visit(*grid);
  };
  const Real cutoff = ctx.settings.mass_cutoff, dt = ctx.dt;
  const Vec<Dim> gravity = ctx.settings.gravity;
  ExactSum work;  // eq. 2.75: -dt sum_k m_k a_d . (v_k^t + v_k^{t+dt}) / 2 over the nodes this rank owns
  for_each_node_in_order(ctx.grid.size(), ctx.active_nodes, [&](Index I) {
    if (!ctx.owned_nodes.contains(I)) return;
    const Vec<Dim> a = kernels::shared_damping_acceleration<Dim>(I, gravity, cutoff, alpha_, for_each_field);
    if (a.isZero(0)) return;
    for (const Grid<Dim>* grid : fields) {
      const NodeRecord<Dim>& n = grid->node[I];
      if (!(n.mass > cutoff)) continue;
      const NodeVelocity<Dim>& v = grid->velocity[I];
      work += -0.5 * dt * n.mass * a.dot(Vec<Dim>(v.mapped) + Vec<Dim>(v.updated));
    }
  });
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
