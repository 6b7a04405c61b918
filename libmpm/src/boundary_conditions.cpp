#include "mpm/boundary_conditions.hpp"

#include "mpm/expression.hpp"

namespace mpm {

template <int Dim>
GridBoundary<Dim>::GridBoundary(const GridGeometry<Dim>& g, const std::array<FaceBoundary, 6>& faces) {
  for (int face = 0; face < 2 * Dim; ++face) {
    const int axis = face / 2;
    const int layer = face % 2 == 0 ? 0 : g.nodes[axis] - 1;
    std::vector<Index> nodes;
    for (Index n = 0; n < g.node_count(); ++n)
      if (g.node_indices(n)[axis] == layer) nodes.push_back(n);
    for (int c = 0; c < Dim; ++c) {
      const auto& constraint = faces[face].component[c];
      if (!constraint) continue;
      Constraint k;
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
void GridBoundary<Dim>::apply(std::vector<NodeVelocity<Dim>>& velocity, VecU<Dim> NodeVelocity<Dim>::*member,
                              Real t) const {
  for (const auto& k : constraints_) {
    const Real value = k.value ? (*k.value)(0, 0, 0, t) : 0;  // evaluated once per face, not per node
    for (Index n : k.nodes) (velocity[n].*member)[k.component] = value;
  }
}

template class GridBoundary<1>;
template class GridBoundary<2>;
template class GridBoundary<3>;

}  // namespace mpm
