// The geostatic initial stress of a set (sets/geostatic_stress.hpp; docs/theory.md eqs 20.1-20.2).
#include "mpm/sets/geostatic_stress.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <tuple>

#include "mpm/materials/material_registry.hpp"
#include "mpm/scene/scene_error.hpp"
#include "mpm/sets/particle_sets.hpp"

namespace mpm {
namespace {

/// One particle of the set in its column.
struct ColumnEntry {
  Real height;  ///< m, along -g
  Real top;     ///< m, the top of the particle
  Real density;
  int body;
  Index particle;
};

/// The axis gravity points along, or -1 when it is zero or oblique.
template <int Dim>
int vertical_axis(const Vec<Dim>& g) {
  int axis = -1;
  for (int d = 0; d < Dim; ++d)
    if (g[d] != 0) {
      if (axis >= 0) return -1;
      axis = d;
    }
  return axis;
}

/// K0 of body `b` under condition `c`: the condition's, or the body's model's.
Real at_rest_coefficient(const SceneDescription& scene, const SetConditionDescription& c, int b) {
  if (c.k0) return *c.k0;
  const MaterialDescription& m = scene.materials.at(scene.bodies[static_cast<std::size_t>(b)].material);
  const MaterialModel* model = find_material_model(m.model);
  if (!model || !model->at_rest_coefficient)
    throw SceneError(c.where, c.path + ".k0",
                     fmt::format("model {} of material '{}' gives no coefficient of earth pressure at rest: give k0",
                                 m.model, m.name));
  return model->at_rest_coefficient(m.parameters);
}

/// The side of the square (cube) of the particle's volume: its extent along the vertical on a lattice.
template <int Dim>
Real particle_side(const ParticleSet<Dim>& p, Index i, bool axisymmetric) {
  const Real volume = axisymmetric ? p.volume0[i] / std::max(Real(p.x[i][0]), Real(1e-300)) : p.volume0[i];
  return std::pow(volume, Real(1) / Dim);
}

template <int Dim>
void apply_condition(const SceneDescription& scene, const SetConditionDescription& c, std::vector<Body<Dim>>& bodies,
                     const GridGeometry<Dim>& geometry) {
  Vec<Dim> g;
  for (int d = 0; d < Dim; ++d) g[d] = scene.solver.gravity[static_cast<std::size_t>(d)];
  const int a = vertical_axis<Dim>(g);
  if (a < 0)
    throw SceneError(c.where, c.path + ".initial_stress",
                     fmt::format("a geostatic stress is the weight of the material above a point, along gravity, "
                                 "which must point along an axis; solver.gravity is [{}]",
                                 fmt::join(std::span(scene.solver.gravity.data(), Dim), ", ")));
  const Real up = g[a] < 0 ? 1 : -1, weight = std::abs(g[a]);
  const bool axisymmetric = geometry.coordinates == Coordinates::axisymmetric;
  // K0 per body of the set (each model takes an initial stress: the loader refused the others), looked up once
  const std::vector<int>& named = scene.sets[static_cast<std::size_t>(c.set)].bodies;
  std::vector<Real> k0(bodies.size(), 0);
  for (const auto& body : bodies)
    if (named.empty() || std::find(named.begin(), named.end(), body.index) != named.end())
      k0[static_cast<std::size_t>(body.index)] = at_rest_coefficient(scene, c, body.index);
  using Key = std::array<long long, 3>;  // the horizontal cell indices of the column
  std::map<Key, std::vector<ColumnEntry>> columns;
  const std::uint32_t mask = set_bit(c.set);
  for (const auto& body : bodies) {
    const auto& p = body.particles;
    for (Index i = 0; i < p.size(); ++i) {
      if (!in_sets(p, i, mask)) continue;
      Key key{};
      for (int d = 0, k = 0; d < Dim; ++d)
        if (d != a)
          key[static_cast<std::size_t>(k++)] =
              static_cast<long long>(std::floor((Real(p.x[i][d]) - geometry.origin[d]) * geometry.inv_h[d]));
      const Real height = up * p.x[i][a];
      columns[key].push_back(
          {height, height + 0.5 * particle_side(p, i, axisymmetric), p.mass[i] / p.volume0[i], body.index, i});
    }
  }
  for (auto& [key, column] : columns) {
    // from the top down; ties in a fixed order, so that the result does not depend on the particles' order
    std::sort(column.begin(), column.end(), [](const ColumnEntry& l, const ColumnEntry& r) {
      return std::tie(r.height, l.body, l.particle) < std::tie(l.height, r.body, r.particle);
    });
    Real surface = column.front().top;
    for (const auto& e : column) surface = std::max(surface, e.top);
    Real sigma = 0;  // eq. 20.1, compression positive
    for (std::size_t k = 0; k < column.size(); ++k) {
      const ColumnEntry& e = column[k];
      sigma += k == 0 ? e.density * (surface - e.height)
                      : 0.5 * (column[k - 1].density + e.density) * (column[k - 1].height - e.height);
      const Real vertical = -weight * sigma;
      SymTensor<Dim>& s = bodies[static_cast<std::size_t>(e.body)].particles.stress[e.particle];
      s = SymTensor<Dim>{};
      for (int n = 0; n < 3; ++n)
        s.c[static_cast<std::size_t>(n)] =
            n == a ? vertical : k0[static_cast<std::size_t>(e.body)] * vertical;  // eq. 20.2
    }
  }
}

}  // namespace

template <int Dim>
void apply_geostatic_stress(const SceneDescription& scene, std::vector<Body<Dim>>& bodies,
                            const GridGeometry<Dim>& geometry) {
  for (const auto& c : scene.conditions)
    if (c.geostatic) apply_condition(scene, c, bodies, geometry);
}

template void apply_geostatic_stress<1>(const SceneDescription&, std::vector<Body<1>>&, const GridGeometry<1>&);
template void apply_geostatic_stress<2>(const SceneDescription&, std::vector<Body<2>>&, const GridGeometry<2>&);
template void apply_geostatic_stress<3>(const SceneDescription&, std::vector<Body<3>>&, const GridGeometry<3>&);

}  // namespace mpm
