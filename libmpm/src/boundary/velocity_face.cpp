// The velocity and traction conditions of a face (boundary/velocity_face.hpp).
#include "mpm/boundary/velocity_face.hpp"

#include <algorithm>

#include "mpm/boundary/face.hpp"
#include "mpm/core/expression.hpp"
#include "mpm/schemes/axisymmetric.hpp"

namespace mpm {

template <int Dim>
VelocityFace<Dim>::VelocityFace(const GridGeometry<Dim>& g, int face, const VelocityFaceSpec& spec)
    : FaceCondition<Dim>(face), nodes_(face_nodes(g, face)) {
  const int axis = face_axis(face);
  wall_ = spec.velocity[axis] && *spec.velocity[axis] == "0";
  for (int c = 0; c < Dim; ++c) {
    if (!spec.traction[c]) continue;
    traction_.push_back({c, std::make_shared<Expression>(*spec.traction[c], std::vector<std::string>{"t"})});
  }
  if (!traction_.empty())
    for (Index n : nodes_) area_.push_back(axisym::face_node_area(g, n, axis));
  for (int c = 0; c < Dim; ++c) {
    if (!spec.velocity[c]) continue;
    Held k;
    k.component = c;
    auto e = std::make_shared<Expression>(*spec.velocity[c], std::vector<std::string>{"t"});
    if (!(e->is_constant() && e->constant_value() == 0)) k.value = std::move(e);
    held_.push_back(std::move(k));
  }
}

template <int Dim>
VelocityFace<Dim>::~VelocityFace() = default;

template <int Dim>
bool VelocityFace<Dim>::holds(int component) const {
  return std::any_of(held_.begin(), held_.end(), [&](const Held& k) { return k.component == component; });
}

template <int Dim>
void VelocityFace<Dim>::constrain(NodeArray<NodeVelocity<Dim>>& velocity, VecU<Dim> NodeVelocity<Dim>::*member, Real t,
                                  NodeRuns nodes) const {
  for (const auto& k : held_) {
    const Real value = k.value ? (*k.value)(0, 0, 0, t) : 0;  // evaluated once per face, not per node
    for_each_listed_node(nodes_, nodes, [&](std::size_t j) { (velocity[nodes_[j]].*member)[k.component] = value; });
  }
}

template <int Dim>
void VelocityFace<Dim>::add_traction(NodeArray<NodeRecord<Dim>>& node, Real t, NodeRuns nodes) const {
  for (const auto& k : traction_) {
    const Real value = (*k.value)(0, 0, 0, t);
    for_each_listed_node(nodes_, nodes, [&](std::size_t j) {
      NodeRecord<Dim>& n = node[nodes_[j]];
      if (n.mass > 0) n.force[k.component] += value * area_[j];
    });
  }
}

template <int Dim>
void VelocityFace<Dim>::traction_forces(Real t, NodeRuns nodes, const std::function<void(Index, int, Real)>& f) const {
  for (const auto& k : traction_) {
    const Real value = (*k.value)(0, 0, 0, t);
    for_each_listed_node(nodes_, nodes, [&](std::size_t j) { f(nodes_[j], k.component, value * area_[j]); });
  }
}

template <int Dim>
bool VelocityFace<Dim>::does_work() const {
  return !traction_.empty() ||
         std::any_of(held_.begin(), held_.end(), [](const Held& k) { return k.value != nullptr; });
}

template <int Dim>
void VelocityFace<Dim>::reactions(const NodeArray<NodeRecord<Dim>>& node, const Vec<Dim>& gravity, Real mass_cutoff,
                                  Real t, Real dt, const std::function<void(Index, int, Real)>& f,
                                  NodeRuns nodes) const {
  for (const auto& k : held_) {
    // The prescribed acceleration over the step (zero for a constant velocity).
    const Real a = k.value ? ((*k.value)(0, 0, 0, t + dt) - (*k.value)(0, 0, 0, t)) / dt : 0;
    const int c = k.component;
    for_each_listed_node(nodes_, nodes, [&](std::size_t j) {
      const Index n = nodes_[j];
      const NodeRecord<Dim>& r = node[n];
      if (r.mass > mass_cutoff) f(n, c, r.mass * a - (r.force[c] + r.mass * gravity[c]));
    });
  }
}

template <int Dim>
void VelocityFace<Dim>::mapped_impulses(const NodeArray<NodeRecord<Dim>>& node, Real mass_cutoff, Real t,
                                        const std::function<void(Index, int, Real)>& f, NodeRuns nodes) const {
  for (const auto& k : held_) {
    const Real v = k.value ? (*k.value)(0, 0, 0, t) : 0;
    const int c = k.component;
    for_each_listed_node(nodes_, nodes, [&](std::size_t j) {
      const Index n = nodes_[j];
      const NodeRecord<Dim>& r = node[n];
      if (r.mass > mass_cutoff) f(n, c, r.mass * v - r.momentum[c]);
    });
  }
}

template <int Dim>
void VelocityFace<Dim>::add_work(ExactSum& w, const NodeArray<NodeRecord<Dim>>& node,
                                 const NodeArray<NodeVelocity<Dim>>& velocity, const Vec<Dim>& gravity,
                                 Real mass_cutoff, Real t, Real dt, NodeMask owned, NodeRuns nodes) const {
  for (const auto& k : held_) {
    if (!k.value) continue;  // v = 0: no work
    const Real v = (*k.value)(0, 0, 0, t + 0.5 * dt);
    if (v == 0) continue;
    const Real a = ((*k.value)(0, 0, 0, t + dt) - (*k.value)(0, 0, 0, t)) / dt;
    const int c = k.component;
    for_each_listed_node(nodes_, nodes, [&](std::size_t j) {
      if (const NodeRecord<Dim>& r = node[nodes_[j]]; r.mass > mass_cutoff && owned.contains(nodes_[j]))
        w += (r.mass * a - (r.force[c] + r.mass * gravity[c])) * v * dt;
    });
  }
  for (const auto& k : traction_) {
    const Real value = (*k.value)(0, 0, 0, t);
    for_each_listed_node(nodes_, nodes, [&](std::size_t j) {
      if (const Index n = nodes_[j]; node[n].mass > 0 && owned.contains(n))
        w += value * area_[j] * 0.5 * (velocity[n].mapped[k.component] + velocity[n].updated[k.component]) * dt;
    });
  }
}

template class VelocityFace<1>;
template class VelocityFace<2>;
template class VelocityFace<3>;

}  // namespace mpm
