#pragma once
/// \file step_points.hpp
/// What one implicit step knows of every material point at t_n, gathered once per step from all bodies (a
/// point is a particle; the order is body by body, particle by particle, fixed for the step): its linear-hat
/// stencil at x_n (weights N^A and spatial gradients grad_n N^A, fixed during the step, eq. 89a), its cell
/// (the Q1/P0 element of eqs. 88c-88e), and the material's state at t_n (F_n, C_n, J_n, Theta_n, the pulled-back
/// deviatoric stress S_n = phi_n^*(dev tau_n) and W~_n of eq. 82).

#include <array>
#include <vector>

#include "mpm/particles/body.hpp"
#include "mpm/plasticity/discrete_gradient.hpp"
#include "mpm/plasticity/field_keys.hpp"
#include "mpm/plasticity/hencky_j2_batch.hpp"
#include "mpm/schemes/axisymmetric.hpp"
#include "mpm/shape/linear_hat.hpp"

namespace mpm::implicit {

template <int Dim>
struct StepPoints {
  static constexpr int count = 1 << Dim;  ///< nodes of a linear-hat stencil
  using State = plasticity::HenckyJ2State<Dim>;

  std::vector<std::array<Index, count>> node;
  std::vector<std::array<Real, count>> w;
  std::vector<std::array<VecU<Dim>, count>> grad;  ///< grad_n N^A, 1/m
  /// Axisymmetric (2D, x = r): the hoop weights T^A = N^A / r_p (1/m), so that grad_n Delta phi has the hoop
  /// component sum T^A Delta phi_r^A (review eq. G.4) and the radial force the term P_tt T^A; empty otherwise.
  std::vector<std::array<Real, count>> hoop;
  bool axisymmetric = false;
  std::vector<Index> cell;
  std::vector<Real> mass, volume0;
  std::vector<VecU<Dim>> velocity;
  std::vector<Mat3> F_n, C_n, S_n;
  std::vector<Real> J_n, W_n, theta_n;
  std::vector<const State*> state_n;
  std::vector<const plasticity::HenckyJ2Params*> params;
  std::vector<int> body;
  std::vector<Index> index;  ///< in the body's particle set

  Index size() const { return static_cast<Index>(mass.size()); }

  /// Gathers every particle of `bodies` (each of material hencky_j2, with the field mixed_volume).
  void gather(const std::vector<Body<Dim>>& bodies, const GridGeometry<Dim>& g) {
    clear();
    axisymmetric = Dim == 2 && g.coordinates == Coordinates::axisymmetric;
    for (int b = 0; b < static_cast<int>(bodies.size()); ++b) {
      const auto& p = bodies[b].particles;
      const auto& material = dynamic_cast<const plasticity::HenckyJ2Batch<Dim>&>(*bodies[b].material);
      const auto& states = p.field(plasticity::keys::hencky_j2_state<Dim>);
      const auto& theta = p.field(plasticity::keys::mixed_volume);
      const Real* hoop_stretch = axisym::hoop_stretch_of(p);  // F_tt, axisymmetric only
      for (Index i = 0; i < p.size(); ++i)
        add_point(p, i, g, material.params(), states[i], theta[i], hoop_stretch ? hoop_stretch[i] : Real(1), b);
    }
  }

 private:
  void clear() {
    node.clear(), w.clear(), grad.clear(), hoop.clear(), cell.clear(), mass.clear(), volume0.clear(), velocity.clear();
    F_n.clear(), C_n.clear(), S_n.clear(), J_n.clear(), W_n.clear(), theta_n.clear(), state_n.clear();
    params.clear(), body.clear(), index.clear();
  }

  void add_point(const ParticleSet<Dim>& p, Index i, const GridGeometry<Dim>& g, const plasticity::HenckyJ2Params& c,
                 const State& state, Real theta, Real hoop_stretch, int b) {
    // linear hats per axis (review eqs. 3.1-3.3), tensor product over the 2^Dim nodes of the cell
    std::array<int, Dim> base{};
    std::array<std::array<Real, 2>, Dim> wa{}, dwa{};
    Index cell_index = 0;
    for (int d = 0; d < Dim; ++d) {
      const Real xi = (p.x[i][d] - g.origin[d]) * g.inv_h[d];
      LinearHat::evaluate(xi, g.nodes[d], base[d], wa[d].data(), dwa[d].data());
      cell_index += base[d] * g.stride[d];  // the cell's lower node, as its index
    }
    std::array<Index, count> n{};
    std::array<Real, count> weight{};
    std::array<VecU<Dim>, count> gradient{};
    for (int a = 0; a < count; ++a) {
      Index linear = 0;
      Real wt = 1;
      VecU<Dim> gr = VecU<Dim>::Ones();
      for (int d = 0; d < Dim; ++d) {
        const int k = (a >> d) & 1;
        linear += (base[d] + k) * g.stride[d];
        wt *= wa[d][k];
        for (int e = 0; e < Dim; ++e) gr[e] *= e == d ? dwa[d][k] * g.inv_h[d] : wa[d][k];
      }
      n[a] = linear, weight[a] = wt, gradient[a] = gr;
    }
    node.push_back(n), w.push_back(weight), grad.push_back(gradient), cell.push_back(cell_index);
    if (axisymmetric) {
      std::array<Real, count> t{};
      for (int a = 0; a < count; ++a) t[a] = weight[a] / p.x[i][0];
      hoop.push_back(t);
    }
    mass.push_back(p.mass[i]), volume0.push_back(p.volume0[i]), velocity.push_back(p.v[i]);
    const Mat3 F = embed<Dim>(Mat<Dim>(p.F[i]), hoop_stretch);
    const auto at_n = plasticity::HenckyJ2::elastic_response<Dim>(c, state, F);
    F_n.push_back(F), C_n.push_back(F.transpose() * F), J_n.push_back(F.determinant());
    S_n.push_back(plasticity::pull_back(F, at_n.dev_kirchhoff)), W_n.push_back(at_n.stored_energy);
    theta_n.push_back(theta), state_n.push_back(&state), params.push_back(&c), body.push_back(b), index.push_back(i);
  }
};

}  // namespace mpm::implicit
