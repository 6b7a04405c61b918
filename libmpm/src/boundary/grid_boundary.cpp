// The conditions of the grid box's faces as a module of the step (boundary/grid_boundary.hpp): tractions, velocity
// constraints, and the bounds the position updates and the stability guard use. Outflow: grid_boundary_outflow.cpp.
#include "mpm/boundary/grid_boundary.hpp"

#include <algorithm>

#include "mpm/boundary/face.hpp"

namespace mpm {

template <int Dim>
GridBoundary<Dim>::GridBoundary(const GridGeometry<Dim>& g, std::vector<std::unique_ptr<FaceCondition<Dim>>> conditions)
    : conditions_(std::move(conditions)) {
  std::stable_sort(conditions_.begin(), conditions_.end(),
                   [](const auto& a, const auto& b) { return a->face() < b->face(); });
  for (const auto& c : conditions_) {
    const int face = c->face(), axis = face_axis(face);
    if (c->is_wall()) {
      if (is_upper_face(face))
        wall_upper_[axis] = g.upper()[axis];
      else
        wall_lower_[axis] = g.origin[axis];
    }
    if (const auto plane = c->removal()) {
      removals_.push_back(*plane);
      {
        OutflowBook book;
        book.face = face;
        books_.push_back(book);
      }
    }
  }
}

template <int Dim>
GridBoundary<Dim>::~GridBoundary() = default;
template <int Dim>
GridBoundary<Dim>::GridBoundary(GridBoundary&&) noexcept = default;
template <int Dim>
GridBoundary<Dim>& GridBoundary<Dim>::operator=(GridBoundary&&) noexcept = default;

template <int Dim>
unsigned GridBoundary<Dim>::phases() const {
  unsigned p = 0;
  if (has_traction()) p |= phase_after_p2g;
  for (int face = 0; face < 2 * Dim; ++face)
    if (constrains_face(face)) p |= phase_grid_velocity;
  if (removes_particles()) p |= phase_end_of_step;
  return p;
}

template <int Dim>
void GridBoundary<Dim>::after_p2g(StepContext<Dim>& ctx) {
  apply_traction(ctx.grid.node, ctx.time, ctx.active_nodes);
}

template <int Dim>
void GridBoundary<Dim>::on_grid_velocity(StepContext<Dim>& ctx, GridStage stage) {
  switch (stage) {
    case GridStage::mapped:
      apply(ctx.grid.velocity, &NodeVelocity<Dim>::mapped, ctx.time, ctx.active_nodes);
      break;
    case GridStage::updated:
      apply(ctx.grid.velocity, &NodeVelocity<Dim>::updated, ctx.time + ctx.dt, ctx.active_nodes);
      break;
    case GridStage::remapped:
      apply(ctx.grid.velocity, &NodeVelocity<Dim>::mapped, ctx.time + ctx.dt, ctx.active_nodes);
      break;
  }
}

template <int Dim>
bool GridBoundary<Dim>::has_traction() const {
  return std::any_of(conditions_.begin(), conditions_.end(), [](const auto& c) { return c->has_traction(); });
}

template <int Dim>
void GridBoundary<Dim>::apply_traction(NodeArray<NodeRecord<Dim>>& node, Real t, NodeRuns nodes) const {
  for (const auto& c : conditions_) c->add_traction(node, t, nodes);
}

template <int Dim>
void GridBoundary<Dim>::traction_forces(Real t, NodeRuns nodes, const std::function<void(Index, int, Real)>& f) const {
  for (const auto& c : conditions_) c->traction_forces(t, nodes, f);
}

template <int Dim>
void GridBoundary<Dim>::apply(NodeArray<NodeVelocity<Dim>>& velocity, VecU<Dim> NodeVelocity<Dim>::*member, Real t,
                              NodeRuns nodes) const {
  for (const auto& c : conditions_) c->constrain(velocity, member, t, nodes);
}

template <int Dim>
Vec<Dim> GridBoundary<Dim>::keep_lower(const GridGeometry<Dim>& g) const {
  Vec<Dim> lower = g.origin;
  for (const auto& r : removals_)
    if (!r.upper) lower[r.axis] = -std::numeric_limits<Real>::infinity();
  return lower;
}

template <int Dim>
Vec<Dim> GridBoundary<Dim>::keep_upper(const GridGeometry<Dim>& g) const {
  Vec<Dim> upper = g.upper();
  for (const auto& r : removals_)
    if (r.upper) upper[r.axis] = std::numeric_limits<Real>::infinity();
  return upper;
}

template <int Dim>
bool GridBoundary<Dim>::constrains_face(int face) const {
  for (const auto& c : conditions_)
    if (c->face() == face)
      for (int d = 0; d < Dim; ++d)
        if (c->holds(d)) return true;
  return false;
}

template <int Dim>
void GridBoundary<Dim>::reactions(int face, const NodeArray<NodeRecord<Dim>>& node, const Vec<Dim>& gravity,
                                  Real mass_cutoff, Real t, Real dt, const std::function<void(Index, int, Real)>& f,
                                  NodeRuns nodes) const {
  for (const auto& c : conditions_)
    if (c->face() == face) c->reactions(node, gravity, mass_cutoff, t, dt, f, nodes);
}

template <int Dim>
void GridBoundary<Dim>::mapped_impulses(int face, const NodeArray<NodeRecord<Dim>>& node, Real mass_cutoff, Real t,
                                        const std::function<void(Index, int, Real)>& f, NodeRuns nodes) const {
  for (const auto& c : conditions_)
    if (c->face() == face) c->mapped_impulses(node, mass_cutoff, t, f, nodes);
}

template <int Dim>
bool GridBoundary<Dim>::does_work() const {
  return std::any_of(conditions_.begin(), conditions_.end(), [](const auto& c) { return c->does_work(); });
}

template <int Dim>
ExactSum GridBoundary<Dim>::work(const NodeArray<NodeRecord<Dim>>& node, const NodeArray<NodeVelocity<Dim>>& velocity,
                                 const Vec<Dim>& gravity, Real mass_cutoff, Real t, Real dt, NodeMask owned,
                                 NodeRuns nodes) const {
  ExactSum w;
  for (const auto& c : conditions_) c->add_work(w, node, velocity, gravity, mass_cutoff, t, dt, owned, nodes);
  return w;
}

template class GridBoundary<1>;
template class GridBoundary<2>;
template class GridBoundary<3>;

}  // namespace mpm
