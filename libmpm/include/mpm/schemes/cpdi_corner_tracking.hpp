#pragma once
/// \file cpdi_corner_tracking.hpp
/// CPDI2 domain update (review eq. 3.38): every corner of every particle domain moves with the grid
/// velocity interpolated by hat functions at the corner, x_c^{t+dt} = x_c^t + dt sum_I N_I(x_c) v_I^{t+dt}, with
/// the body's own nodal velocities when contact gives it a field of its own (Body::separate_grid).
/// Neighbouring particles share corner positions, so they move together and leave no gaps. The module
/// is constructed only for scenes whose CPDI domains follow their corners (field "cpdi_corners").

#include <algorithm>
#include <cmath>

#include "mpm/core/parallel_chunks.hpp"
#include "mpm/particles/field_keys.hpp"
#include "mpm/shape/cpdi_elements.hpp"
#include "mpm/simulation/module.hpp"

namespace mpm {

/// Hat-function interpolation of the updated grid velocity at a point (clamped into the grid box).
template <int Dim>
Vec<Dim> grid_velocity_at(const Grid<Dim>& grid, const Vec<Dim>& x) {
  const auto& g = grid.geometry;
  int lo[Dim];
  Real f[Dim];
  for (int d = 0; d < Dim; ++d) {
    const Real xi = std::clamp<Real>((x[d] - g.origin[d]) * g.inv_h[d], 0, g.nodes[d] - 1);
    lo[d] = std::min(static_cast<int>(std::floor(xi)), g.nodes[d] - 2);
    f[d] = xi - lo[d];
  }
  Vec<Dim> v = Vec<Dim>::Zero();
  for (int corner = 0; corner < (1 << Dim); ++corner) {
    Index n = 0;
    Real N = 1;
    for (int d = 0; d < Dim; ++d) {
      const int bit = (corner >> d) & 1;
      n += (lo[d] + bit) * (d == 0 ? 1 : g.stride[d]);
      N *= bit ? f[d] : 1 - f[d];
    }
    v += N * grid.velocity[n].updated;
  }
  return v;
}

template <int Dim>
class CpdiCornerTracking final : public Module<Dim> {
 public:
  explicit CpdiCornerTracking(int corners) : corners_(corners) {}
  std::string_view name() const override { return "cpdi_corner_tracking"; }
  unsigned phases() const override { return phase_end_of_step; }
  /// Each corner reads the nodes of its particle's stencil (within the rank's reach, complete after the halo).
  std::string why_not_distributed() const override { return {}; }

  void end_of_step(StepContext<Dim>& ctx) override {
    for (auto& body : ctx.bodies) {
      if (!body.particles.has_field(keys::cpdi_corners<Dim>)) continue;
      auto& corners = body.particles.field(keys::cpdi_corners<Dim>);
      // the body's own field with contact (its velocity after the contact correction), else the shared one
      const Grid<Dim>& grid = body.separate_grid ? *body.separate_grid : ctx.grid;
      parallel_chunks(std::size_t{0}, corners.size(), 1024, [&](std::size_t chunk_begin, std::size_t chunk_end) {
        for (std::size_t i = chunk_begin; i != chunk_end; ++i)
          for (int c = 0; c < corners_; ++c) corners[i][c] += ctx.dt * grid_velocity_at(grid, Vec<Dim>(corners[i][c]));
      });
    }
  }

 private:
  int corners_;
};

}  // namespace mpm
