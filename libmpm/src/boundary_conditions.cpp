#include "mpm/boundary_conditions.hpp"

#include <algorithm>

#include "mpm/axisymmetric.hpp"
#include "mpm/exact_sum.hpp"
#include "mpm/expression.hpp"

namespace mpm {

template <int Dim>
GridBoundary<Dim>::GridBoundary(const GridGeometry<Dim>& g, const std::array<FaceBoundary, 6>& faces) {
  for (int face = 0; face < 2 * Dim; ++face) {
    const int axis = face / 2;
    const int layer = face % 2 == 0 ? 0 : g.nodes[axis] - 1;
    if (faces[face].component[axis] && *faces[face].component[axis] == "0") {  // a wall
      if (face % 2 == 0)
        wall_lower_[axis] = g.origin[axis];
      else
        wall_upper_[axis] = g.upper()[axis];
    }
    std::vector<Index> nodes;
    for (Index n = 0; n < g.node_count(); ++n)
      if (g.node_indices(n)[axis] == layer) nodes.push_back(n);
    for (int c = 0; c < Dim; ++c) {
      if (!faces[face].traction[c]) continue;
      Traction k;
      k.component = c;
      k.value = std::make_shared<Expression>(*faces[face].traction[c], std::vector<std::string>{"t"});
      k.nodes = nodes;
      for (Index n : nodes) k.area.push_back(axisym::face_node_area(g, n, axis));
      tractions_.push_back(std::move(k));
    }
    for (int c = 0; c < Dim; ++c) {
      const auto& constraint = faces[face].component[c];
      if (!constraint) continue;
      Constraint k;
      k.face = face;
      k.component = c;
      auto e = std::make_shared<Expression>(*constraint, std::vector<std::string>{"t"});
      if (!(e->is_constant() && e->constant_value() == 0)) k.value = std::move(e);
      k.nodes = nodes;
      constraints_.push_back(std::move(k));
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
void GridBoundary<Dim>::apply(NodeArray<NodeVelocity<Dim>>& velocity, VecU<Dim> NodeVelocity<Dim>::*member, Real t,
                              NodeRuns nodes) const {
  for (const auto& k : constraints_) {
    const Real value = k.value ? (*k.value)(0, 0, 0, t) : 0;  // evaluated once per face, not per node
    for_each_listed_node(k.nodes, nodes, [&](std::size_t j) { (velocity[k.nodes[j]].*member)[k.component] = value; });
  }
}

template <int Dim>
bool GridBoundary<Dim>::constrains_face(int face) const {
  for (const auto& k : constraints_)
    if (k.face == face) return true;
  return false;
}

template <int Dim>
void GridBoundary<Dim>::reactions(int face, const NodeArray<NodeRecord<Dim>>& node, const Vec<Dim>& gravity,
                                  Real mass_cutoff, Real t, Real dt, const std::function<void(Index, int, Real)>& f,
                                  NodeRuns nodes) const {
  for (const auto& k : constraints_) {
    if (k.face != face) continue;
    // The prescribed acceleration over the step (zero for a constant velocity).
    const Real a = k.value ? ((*k.value)(0, 0, 0, t + dt) - (*k.value)(0, 0, 0, t)) / dt : 0;
    const int c = k.component;
    for_each_listed_node(k.nodes, nodes, [&](std::size_t j) {
      const Index n = k.nodes[j];
      const NodeRecord<Dim>& r = node[n];
      if (r.mass > mass_cutoff) f(n, c, r.mass * a - (r.force[c] + r.mass * gravity[c]));
    });
  }
}

template <int Dim>
void GridBoundary<Dim>::apply_traction(NodeArray<NodeRecord<Dim>>& node, Real t, NodeRuns nodes) const {
  for (const auto& k : tractions_) {
    const Real value = (*k.value)(0, 0, 0, t);
    for_each_listed_node(k.nodes, nodes, [&](std::size_t j) {
      NodeRecord<Dim>& n = node[k.nodes[j]];
      if (n.mass > 0) n.force[k.component] += value * k.area[j];
    });
  }
}

template <int Dim>
bool GridBoundary<Dim>::does_work() const {
  return !tractions_.empty() ||
         std::any_of(constraints_.begin(), constraints_.end(), [](const Constraint& k) { return k.value != nullptr; });
}

template <int Dim>
ExactSum GridBoundary<Dim>::work(const NodeArray<NodeRecord<Dim>>& node, const NodeArray<NodeVelocity<Dim>>& velocity,
                                 const Vec<Dim>& gravity, Real mass_cutoff, Real t, Real dt, NodeMask owned,
                                 NodeRuns nodes) const {
  auto mine = [&](Index n) { return owned.contains(n); };
  ExactSum w;
  for (const auto& k : constraints_) {
    if (!k.value) continue;  // v = 0: no work
    const Real v = (*k.value)(0, 0, 0, t + 0.5 * dt);
    if (v == 0) continue;
    const Real a = ((*k.value)(0, 0, 0, t + dt) - (*k.value)(0, 0, 0, t)) / dt;
    const int c = k.component;
    for_each_listed_node(k.nodes, nodes, [&](std::size_t j) {
      if (const NodeRecord<Dim>& r = node[k.nodes[j]]; r.mass > mass_cutoff && mine(k.nodes[j]))
        w += (r.mass * a - (r.force[c] + r.mass * gravity[c])) * v * dt;
    });
  }
  for (const auto& k : tractions_) {
    const Real value = (*k.value)(0, 0, 0, t);
    for_each_listed_node(k.nodes, nodes, [&](std::size_t j) {
      if (const Index n = k.nodes[j]; node[n].mass > 0 && mine(n))
        w += value * k.area[j] * 0.5 * (velocity[n].mapped[k.component] + velocity[n].updated[k.component]) * dt;
    });
  }
  return w;
}

template class GridBoundary<1>;
template class GridBoundary<2>;
template class GridBoundary<3>;

}  // namespace mpm
