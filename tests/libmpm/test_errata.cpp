// The errata of docs/errata.md that no other test shows: each test runs the corrected equation and checks a
// number that the equation as printed in the review would not give.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "mpm/output/output_writer.hpp"
#include "mpm/shape/gimp.hpp"
#include "scene_fixture.hpp"

namespace mpm {
namespace {

// docs/errata.md #2 (eq. 2.57): L_p = sum_I v_I (x) grad phi_I; the printed row 3, column 2 uses v_xI where
// v_zI belongs. A linear velocity field v = A x with nine different entries is reproduced exactly by hat
// functions at the particles whose nodes are all covered, so L_p = A there (to round-off); the printed
// L_zy would be A_xy = 0.2 instead of A_zy = 0.8.
TEST(Errata, VelocityGradientEq257In3D) {
  const std::string scene =
      "dimension: 3\n"
      "grid: {origin: [0, 0, 0], extent: [1, 1, 1], cell_size: 0.1}\n"
      "materials: {m: {model: linear_elastic, density: 1000, youngs_modulus: 1.0e5, poisson_ratio: 0.3}}\n"
      "bodies: [{material: m, shape: {type: box, min: [0.2, 0.2, 0.2], max: [0.8, 0.8, 0.8]}, velocity: "
      "[\"0.1*x + 0.2*y + 0.3*z\", \"0.4*x + 0.5*y + 0.6*z\", \"0.7*x + 0.8*y + 0.9*z\"]}]\n"
      "solver: {scheme: musl, flip_fraction: 1, dt: 1.0e-7, end_time: 1}\n"
      "output: {fields: [velocity_gradient]}\n";
  auto sim = test::simulation_from_yaml<3>(scene);
  sim->advance(1e-7);
  OutputWriter<3> writer(std::filesystem::temp_directory_path() / "mpm_errata_eq257", "p", {"velocity_gradient"}, false,
                         0);
  const io::PointCloud cloud = writer.particle_cloud(*sim);
  std::filesystem::remove_all(writer.directory());
  const auto& L = cloud.fields.at(0);
  const double A[9] = {0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9};  // row-major, as written
  int interior = 0;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    bool inside = true;  // a cell away from the body's faces: every node of the stencil is fully covered
    for (int d = 0; d < 3; ++d) inside = inside && cloud.points[3 * i + d] > 0.3 && cloud.points[3 * i + d] < 0.7;
    if (!inside) continue;
    ++interior;
    for (int k = 0; k < 9; ++k) ASSERT_NEAR(L.values[9 * i + k], A[k], 1e-9) << "component " << k;
  }
  EXPECT_EQ(interior, 512);  // 4^3 cells x 8 particles
}

// docs/errata.md #5 (§3.3.1): "for a given particle only three non-zero functions" holds for l_p <= h only;
// a domain stretched to 1.8 cells (cpGIMP, eq. 3.14) reaches four nodes per axis. The weights equal the
// hat averaged over the domain, phi_I = (1/l_p) int N_I, here by a midpoint rule of 2e5 points.
TEST(Errata, GimpReachesFourNodesPerAxis) {
  const Real xi = 3.5, a = 0.9;  // particle at the centre of cell 3, half-length 0.9 cells
  int base = 0;
  Real w[4], dw[4];
  gimp_detail::evaluate(xi, 12, a, base, w, dw);
  int nonzero = 0;
  Real sum = 0;
  for (int k = 0; k < 4; ++k) {
    const int n = 200000;
    Real integral = 0;
    for (int q = 0; q < n; ++q) {
      const Real s = xi - a + (q + 0.5) * 2 * a / n;
      integral += gimp_detail::hat(s - (base + k));
    }
    integral /= n;
    EXPECT_NEAR(w[k], integral, 1e-9) << "node " << base + k;
    nonzero += w[k] > 0;
    sum += w[k];
  }
  EXPECT_EQ(nonzero, 4);
  EXPECT_NEAR(sum, 1, 1e-14);
  // the outer node (r = 1.5) overlaps the domain over 1 + a - r = 0.4 cells: w = 0.4^2 / 2 / (l_p / h)
  EXPECT_NEAR(w[0], 0.4 * 0.4 / (2 * 1.8), 1e-14);
}

// docs/errata.md #35 (Alg. 3, line 17): TLMPM divides by a constant nodal mass m_I = sum phi_I(X_p) m_p; the
// printed m_I^t would follow the particles. A bar translating by 0.4 cells keeps the nodal masses of the
// first step bit for bit: at node 0 (x = 0) m_0 = 50 kg/m^2 x (0.75 + 0.25) from the particles' reference
// positions 0.025 and 0.075 m, while the current positions 0.065 and 0.115 m would give 50 x 0.35 = 17.5.
TEST(Errata, TlmpmNodalMassIsConstant) {
  const std::string scene =
      "dimension: 1\n"
      "grid: {origin: [0], extent: [1], cell_size: 0.1}\n"
      "materials: {m: {model: linear_elastic, density: 1000, youngs_modulus: 1.0e5, poisson_ratio: 0.3}}\n"
      "bodies: [{material: m, shape: {type: box, min: [0], max: [0.5]}, particles_per_cell: 2, velocity: [\"1\"]}]\n"
      "solver: {scheme: tlmpm, dt: 1.0e-4, end_time: 1}\n";
  auto sim = test::simulation_from_yaml<1>(scene);
  sim->advance(1e-4);
  std::vector<Real> first;
  for (const auto& n : sim->grid().node) first.push_back(n.mass);
  for (int s = 0; s < 399; ++s) sim->advance(1e-4);
  const auto& p = sim->bodies()[0].particles;
  EXPECT_NEAR(p.x[0][0] - 0.025, 0.04, 1e-9);  // moved by 0.4 h
  for (std::size_t I = 0; I < first.size(); ++I) EXPECT_EQ(sim->grid().node[I].mass, first[I]) << "node " << I;
  Real current = 0;  // m_0 from the current positions
  for (Index i = 0; i < p.size(); ++i) current += gimp_detail::hat(p.x[i][0] / 0.1) * p.mass[i];
  EXPECT_NEAR(first[0], 50.0, 1e-9);
  EXPECT_NEAR(current, 17.5, 1e-9);
}

}  // namespace
}  // namespace mpm
