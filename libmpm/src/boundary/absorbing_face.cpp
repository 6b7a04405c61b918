// An absorbing face: Lysmer–Kuhlemeyer dashpots with an optional input motion (boundary/absorbing_face.hpp;
// docs/theory.md §19).
#include "mpm/boundary/absorbing_face.hpp"

#include "mpm/boundary/face.hpp"
#include "mpm/schemes/axisymmetric.hpp"

namespace mpm {

template <int Dim>
AbsorbingFace<Dim>::AbsorbingFace(const GridGeometry<Dim>& g, int face, AbsorbingFaceSpec spec)
    : FaceCondition<Dim>(face), nodes_(face_nodes(g, face)), spec_(std::move(spec)) {
  const int axis = face_axis(face);
  for (Index n : nodes_) area_.push_back(axisym::face_node_area(g, n, axis));
  for (int d = 0; d < Dim; ++d)
    impedance_[d] = spec_.density * (d == axis ? spec_.p_wave_speed : spec_.s_wave_speed);  // eq. 19.1
}

template <int Dim>
std::array<Real, 3> AbsorbingFace<Dim>::input_at(Real t) const {
  return spec_.input ? spec_.input(t) : std::array<Real, 3>{0, 0, 0};  // once per face and call, not per node
}

template <int Dim>
Vec<Dim> AbsorbingFace<Dim>::force(std::size_t j, const NodeRecord<Dim>& n, const std::array<Real, 3>& in) const {
  Vec<Dim> f;
  for (int d = 0; d < Dim; ++d)  // eq. 19.3: A rho c (2 v_in - v), v = p / m the node's velocity at t
    f[d] = area_[j] * impedance_[d] * (2 * in[static_cast<std::size_t>(d)] - n.momentum[d] / n.mass);
  return f;
}

template <int Dim>
void AbsorbingFace<Dim>::add_traction(NodeArray<NodeRecord<Dim>>& node, Real t, NodeRuns nodes) const {
  const auto in = input_at(t);
  for_each_listed_node(nodes_, nodes, [&](std::size_t j) {
    NodeRecord<Dim>& n = node[nodes_[j]];
    if (n.mass > 0) n.force += force(j, n, in);
  });
}

template <int Dim>
void AbsorbingFace<Dim>::traction_forces(Real, NodeRuns, const std::function<void(Index, int, Real)>&) const {}

template <int Dim>
void AbsorbingFace<Dim>::add_work(ExactSum& w, const NodeArray<NodeRecord<Dim>>& node,
                                  const NodeArray<NodeVelocity<Dim>>& velocity, const Vec<Dim>& /*gravity*/,
                                  Real /*mass_cutoff*/, Real t, Real dt, NodeMask owned, NodeRuns nodes) const {
  const auto in = input_at(t);
  for_each_listed_node(nodes_, nodes, [&](std::size_t j) {
    const Index i = nodes_[j];
    const NodeRecord<Dim>& n = node[i];
    if (!(n.mass > 0) || !owned.contains(i)) return;
    const Vec<Dim> f = force(j, n, in);
    for (int d = 0; d < Dim; ++d) w += f[d] * 0.5 * (velocity[i].mapped[d] + velocity[i].updated[d]) * dt;
  });
}

template class AbsorbingFace<1>;
template class AbsorbingFace<2>;
template class AbsorbingFace<3>;

}  // namespace mpm
