// The projection of the implicit scheme (ref. 003 eqs. 86-87, physics/implicit/consistent_mass.hpp): the
// consistent mass matrix of linear hats and the grid velocity from M v = sum N pi by conjugate gradients.
// References: hats reproduce linear fields, so v_A = a + B x_A solves (87) exactly for particle velocities
// a + B x_p (sum_B M^AB v_B = sum_p m N^A v(x_p)); the rows of M sum to the lumped mass, so
// sum_A (M v)_A = sum_p pi_p (momentum, eq. 93 = 94).
#include <gtest/gtest.h>

#include <random>

#include "mpm/implicit/consistent_mass.hpp"
#include "mpm/implicit/step_points.hpp"
#include "mpm/shape/linear_hat.hpp"

namespace mpm::implicit {
namespace {

/// Particles jittered about a 2x2 lattice per cell in [0.2, 0.8]^2 on a 10 x 10 grid of [0, 1]^2.
struct Cloud {
  std::vector<Vec<2>> x;
  std::vector<Real> m;
};

Cloud cloud(unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<Real> jitter(-0.02, 0.02), mass(0.5, 2);
  Cloud c;
  for (int i = 0; i < 12; ++i)
    for (int j = 0; j < 12; ++j) {
      c.x.emplace_back(0.2 + 0.05 * (i + 0.5) + jitter(rng), 0.2 + 0.05 * (j + 0.5) + jitter(rng));
      c.m.push_back(mass(rng));
    }
  return c;
}

struct Stencil {
  std::array<Index, 4> node{};
  std::array<Real, 4> w{};
};

Stencil stencil(const Vec<2>& x, const GridGeometry<2>& g) {
  int base[2];
  Real wa[2][2], dwa[2][2];
  for (int d = 0; d < 2; ++d)
    LinearHat::evaluate((x[d] - g.origin[d]) * g.inv_h[d], g.nodes[d], base[d], wa[d], dwa[d]);
  Stencil s;
  for (int a = 0; a < 4; ++a) {
    const int i = a & 1, j = a >> 1;
    s.node[a] = (base[0] + i) * g.stride[0] + (base[1] + j) * g.stride[1];
    s.w[a] = wa[0][i] * wa[1][j];
  }
  return s;
}

// With weak_fraction > 0 the edge nodes of the cloud become slaves (free_dofs.hpp): P reproduces linear fields,
// so the Galerkin form P^T M P v = P^T b has the same exact solution, at masters and slaves.
class ImplicitProjection : public ::testing::TestWithParam<Real> {};

TEST_P(ImplicitProjection, ReproducesALinearVelocityFieldAndConservesMomentum) {
  const Real weak_fraction = GetParam();
  const GridGeometry<2> g(Vec<2>::Zero(), Vec<2>::Constant(0.1), {10, 10});
  Mat<2> B;
  B << 0.3, -1.2, 0.7, 0.4;
  const Vec<2> a0(1.5, -0.25);
  for (unsigned seed : {1u, 2u, 3u}) {
    const Cloud c = cloud(seed);
    ConsistentMass<2> M(g);
    M.clear();
    std::vector<Real> b[2] = {std::vector<Real>(g.node_count(), 0), std::vector<Real>(g.node_count(), 0)};
    std::vector<char> touched(g.node_count(), 0);
    std::vector<Real> fraction(g.node_count(), 0);  // the particles' volume (0.05^2 each) weighted by N^A over h^2
    Vec<2> momentum = Vec<2>::Zero();
    for (std::size_t p = 0; p < c.x.size(); ++p) {
      const Stencil s = stencil(c.x[p], g);
      M.add_particle(c.m[p], s.node, s.w);
      const Vec<2> v = a0 + B * c.x[p];
      momentum += c.m[p] * v;
      for (int k = 0; k < 4; ++k) {
        touched[s.node[k]] |= s.w[k] > 0 ? 1 : 0;
        fraction[s.node[k]] += s.w[k] * 0.25;
        for (int d = 0; d < 2; ++d) b[d][s.node[k]] += s.w[k] * c.m[p] * v[d];
      }
    }
    FreeDofs<2> dofs;
    dofs.build(g, touched, fraction, weak_fraction, [](Index, int) { return false; });
    if (weak_fraction > 0) {
      EXPECT_GT(dofs.slave_count(), 0);
    }
    Real max_error = 0, scale = 0;
    Vec<2> grid_momentum = Vec<2>::Zero();
    for (int d = 0; d < 2; ++d) {
      std::vector<Real> v(g.node_count(), 0);
      ASSERT_GE(project_component(M, dofs, d, b[d], v, 1e-14, 1000), 0);
      for (Index n : dofs.active) {
        const auto ij = g.node_indices(n);
        const Vec<2> exact = a0 + B * g.node_position(ij);
        max_error = std::max(max_error, std::abs(v[n] - exact[d]));
        scale = std::max(scale, std::abs(exact[d]));
        grid_momentum[d] += M.lumped(n) * v[n];  // sum_A sum_B M^AB v_B (eq. 93)
      }
    }
    std::printf(
        "[ measured ] weak fraction %.2f (%ld slaves): seed %u: linear field max error %.2e of %.2f; momentum %.2e of "
        "%.2f\n",
        weak_fraction, static_cast<long>(dofs.slave_count()), seed, max_error, scale, (grid_momentum - momentum).norm(),
        momentum.norm());
    EXPECT_LT(max_error, 1e-12 * scale);
    EXPECT_LT((grid_momentum - momentum).norm(), 1e-13 * momentum.norm());
  }
}

INSTANTIATE_TEST_SUITE_P(WeakFractions, ImplicitProjection, ::testing::Values(Real(0), Real(0.3)));

}  // namespace
}  // namespace mpm::implicit
