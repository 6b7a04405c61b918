// The axisymmetric mode (libmpm/include/mpm/schemes/axisymmetric.hpp, docs/theory.md §14) against exact values: the
// ring volumes and masses of a filled cylinder, the hoop kinematics of every scheme and axisymmetric shape function,
// the r-weighted GIMP weights, the revolved face areas and the cylindrical names of the output.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>

#include "mpm/output/output_writer.hpp"
#include "mpm/schemes/axisymmetric.hpp"
#include "mpm/shape/gimp.hpp"
#include "scene_fixture.hpp"

namespace mpm {
namespace {

constexpr Real pi = std::numbers::pi_v<Real>;

/// A linear elastic cylinder r <= 0.6 m, 0.5 <= z <= 1.5 m (rho = 1000) in an axisymmetric grid of h = 0.1 m.
std::string cylinder_scene(const std::string& scheme, const std::string& shape, int ppc, const std::string& velocity,
                           const std::string& extra_solver = "") {
  return fmt::format(R"(dimension: 2
grid: {{coordinates: axisymmetric, extent: [1.0, 2.0], cell_size: 0.1}}
materials: {{steel: {{model: linear_elastic, density: 1000, youngs_modulus: 1.0e6, poisson_ratio: 0.3}}}}
bodies:
  - {{name: cylinder, material: steel, shape: {{type: box, min: [0, 0.5], max: [0.6, 1.5]}}, particles_per_cell: {},
     velocity: {}}}
solver: {{scheme: {}, shape_function: {}, dt: 1.0e-4, end_time: 1{}}}
output: {{fields: [velocity, stress]}}
)",
                     ppc, velocity, scheme, shape, extra_solver);
}

// a filled box r <= R, 0 <= z - z0 <= L weighs rho pi R^2 L to 1e-12 (V_p = 2 pi r_p A_p with r_p the
// sub-cell centroid: Pappus, exact for each ring).
TEST(Axisymmetric, FilledCylinderHasTheMassOfTheCylinder) {
  const Real R = 0.6, L = 1.0, rho = 1000;
  for (const int ppc : {1, 2, 3})
    for (const char* shape : {"linear", "cpgimp"}) {
      auto sim = test::simulation_from_yaml<2>(cylinder_scene("musl", shape, ppc, "[0, 0]"));
      const auto& p = sim->bodies()[0].particles;
      Real mass = 0, volume = 0;
      for (Index i = 0; i < p.size(); ++i) {
        mass += p.mass[i];
        volume += p.volume0[i];
      }
      EXPECT_NEAR(mass / (rho * pi * R * R * L), 1, 1e-12) << shape << " ppc " << ppc;
      EXPECT_NEAR(volume / (pi * R * R * L), 1, 1e-12) << shape << " ppc " << ppc;
      EXPECT_NEAR(sim->energy().mass / (rho * pi * R * R * L), 1, 1e-12);
    }
}

// a uniform radial velocity v_r = a r gives F_tt = F_rr and sigma_tt = sigma_rr after a step. APIC with
// C_p = diag(a, 0) maps the affine field exactly (every node gets v_I = a r_I), so L_rr = a (linear reproduction
// of the gradients) and L_tt = sum T_I a r_I = a for every scheme and axisymmetric shape function, to round-off.
// Not MUSL with cpGIMP: its second mapping starts from v_p = sum S_I v_I, the r-weighted domain average of a r,
// a (r_p + l^2 / (3 r_p)) (the ring's momentum per mass, not a r_p), so the re-mapped field is no longer a r.
// With quadratic B-splines the cylinder fills the grid's height: with ends inside the grid, a particle in the half cell
// next to the axis at an end has nearly empty nodes beyond the end, and C_p's radial column takes them with the
// particle's own velocity (APIC's light-node rule in a face's hat-like cells, transfer_kernels.hpp): L_tt off by 1e-4.
TEST(Axisymmetric, UniformRadialVelocityStretchesTheHoopLikeTheRadius) {
  const Real a = 0.01, dt = 1e-4;
  for (const std::string scheme : {"usl", "musl", "usf"})
    for (const std::string shape : {"linear", "quadratic_bspline", "cubic_bspline", "cpgimp"}) {
      if (scheme == "musl" && shape == "cpgimp") continue;
      std::string scene = cylinder_scene(scheme, shape, 2, "[\"0.01*x\", 0]", ", velocity_transfer: apic");
      if (shape == "quadratic_bspline")
        scene.replace(scene.find("min: [0, 0.5], max: [0.6, 1.5]"), 30, "min: [0, 0], max: [0.6, 2]");
      auto sim = test::simulation_from_yaml<2>(scene);
      auto& p = sim->bodies()[0].particles;
      Mat<2> C = Mat<2>::Zero();
      C(0, 0) = a;
      for (auto& c : p.field(keys::affine_velocity<2>)) c = C;
      sim->advance(dt);
      const auto& F_tt = p.field(keys::hoop_stretch);
      const auto& L_tt = p.field(keys::hoop_velocity_gradient);
      for (Index i = 0; i < p.size(); ++i) {
        SCOPED_TRACE(fmt::format("{} {} particle {} at r = {}", scheme, shape, i, p.x[i][0]));
        ASSERT_NEAR(F_tt[i], 1 + a * dt, 1e-12);
        ASSERT_NEAR(p.F[i](0, 0), F_tt[i], 1e-12);
        ASSERT_NEAR(p.F[i](1, 1), 1, 1e-12);
        ASSERT_NEAR(p.F[i](0, 1), 0, 1e-12);
        ASSERT_NEAR(p.F[i](1, 0), 0, 1e-12);
        ASSERT_NEAR(L_tt[i], a, 1e-12 * a / dt);
        const SymTensor<2>& s = p.stress[i];  // rr, zz, tt, rz
        ASSERT_GT(s.c[0], 0);
        ASSERT_NEAR(s.c[2], s.c[0], 1e-12 * s.c[0]);
      }
    }
}

// F_tt = r / R (current over reference radius) for any motion when the particles move with the velocity
// of the hoop rate: USL (x += dt sum phi v, L_tt = sum phi v_r / r) and the TLMPM's reference-radius form.
TEST(Axisymmetric, HoopStretchIsTheRatioOfCurrentToReferenceRadius) {
  for (const char* scheme : {"usl", "tlmpm"})
    for (const char* shape : {"linear", "quadratic_bspline", "cubic_bspline"}) {
      auto sim = test::simulation_from_yaml<2>(
          cylinder_scene(scheme, shape, 2, "[\"0.3*sin(3*x)*cos(2*y)\", \"0.2*sin(x+y)\"]"));
      auto& p = sim->bodies()[0].particles;
      std::vector<Real> R(p.size());
      for (Index i = 0; i < p.size(); ++i) R[p.id[i]] = p.x[i][0];
      for (int s = 0; s < 40; ++s) sim->advance(1e-3);
      const auto& F_tt = p.field(keys::hoop_stretch);
      Real largest = 0;
      for (Index i = 0; i < p.size(); ++i) {
        ASSERT_NEAR(F_tt[i] * R[p.id[i]] / p.x[i][0], 1, 1e-12) << scheme << " " << shape << " particle " << i;
        largest = std::max(largest, std::abs(F_tt[i] - 1));
      }
      EXPECT_GT(largest, 1e-3) << "the motion must stretch the hoop measurably";
    }
}

/// int_lo^hi f(s) ds by two-point Gauss-Legendre between the integers (the kinks of the hats): exact for the
/// integrands here, polynomials of degree <= 2 between kinks, and never evaluated on a kink.
template <class F>
Real quadrature(F f, Real lo, Real hi) {
  const Real g = 0.5 / std::sqrt(Real(3));
  Real sum = 0;
  for (Real a = lo; a < hi;) {
    const Real b = std::min(hi, std::floor(a) + 1), m = 0.5 * (a + b), l = b - a;
    sum += 0.5 * l * (f(m - g * l) + f(m + g * l));
    a = b;
  }
  return sum;
}

// Nairn & Guilkey (2015): on the radial axis the GIMP weights are the averages of the hat N_I and its slope over
// the particle's domain weighted by r, and the hoop weight the plain average over r. Checked against quadrature,
// with partition of unity and zero-sum gradients, including domains stretched to two cells (a = 1).
TEST(Axisymmetric, RadialGimpWeightsAreRWeightedDomainAverages) {
  const int nodes = 12;
  for (const Real a : {0.25, 0.5, 0.8, 1.0})
    for (const Real xi : {1.0, 1.3, 2.75, 5.5, 7.9}) {
      if (xi - a < 0) continue;
      int base = 0;
      Real w[4], dw[4], planar[4];
      gimp_detail::evaluate_radial(xi, nodes, a, base, w, dw, planar);
      Real sum_w = 0, sum_dw = 0, sum_planar = 0;
      for (int k = 0; k < 4; ++k) {
        const Real node = base + k;
        auto hat = [&](Real s) { return std::max<Real>(0, 1 - std::abs(s - node)); };
        auto slope = [&](Real s) { return std::abs(s - node) < 1 ? (s < node ? 1.0 : -1.0) : 0.0; };
        const Real weight = quadrature([&](Real s) { return s; }, xi - a, xi + a);
        EXPECT_NEAR(w[k], quadrature([&](Real s) { return hat(s) * s; }, xi - a, xi + a) / weight, 1e-14);
        EXPECT_NEAR(dw[k], quadrature([&](Real s) { return slope(s) * s; }, xi - a, xi + a) / weight, 1e-14);
        EXPECT_NEAR(planar[k], quadrature(hat, xi - a, xi + a) / (2 * a), 1e-14);
        sum_w += w[k];
        sum_dw += dw[k];
        sum_planar += planar[k];
      }
      EXPECT_NEAR(sum_w, 1, 1e-14) << "xi " << xi << " a " << a;
      EXPECT_NEAR(sum_dw, 0, 1e-14);
      EXPECT_NEAR(sum_planar, 1, 1e-14);
    }
}

// The revolved face areas (tractions, heat fluxes): the nodes of a face z = const carry 2 pi int N_I r dr, which
// sums to the disk pi R^2; those of the face r = R carry 2 pi R times their length along z (2 pi R H in all);
// the axis carries nothing.
TEST(Axisymmetric, FaceNodeAreasAddUpToTheRevolvedFaces) {
  const GridGeometry<2> g(Vec<2>(0, 0), Vec<2>(0.1, 0.05), {10, 8}, Coordinates::axisymmetric);
  const Real R = 1.0, H = 0.4;
  Real disk = 0, mantle = 0, axis = 0;
  for (Index n = 0; n < g.node_count(); ++n) {
    const auto ijk = g.node_indices(n);
    if (ijk[1] == 0) disk += axisym::face_node_area(g, n, 1);
    if (ijk[0] == 10) mantle += axisym::face_node_area(g, n, 0);
    if (ijk[0] == 0) axis += axisym::face_node_area(g, n, 0);
  }
  EXPECT_NEAR(disk, pi * R * R, 1e-13);
  EXPECT_NEAR(mantle, 2 * pi * R * H, 1e-13);
  EXPECT_EQ(axis, 0);
}

// Face tractions act per unit area of the revolved face: on a body filling the grid, a radial traction
// t_r on the face r = R and an axial t_z on the face z = H push with 2 pi R H t_r and pi R^2 t_z, so one step from
// rest (zero stress: the internal forces add to nothing) gives the particles exactly that momentum times dt.
TEST(Axisymmetric, TractionsActOnTheRevolvedFaceAreas) {
  const Real R = 0.6, H = 1.0, t_r = 2e3, t_z = -3e3, dt = 1e-4;
  for (const char* shape : {"linear", "cubic_bspline"}) {
    auto sim = test::simulation_from_yaml<2>(fmt::format(R"(dimension: 2
grid: {{coordinates: axisymmetric, extent: [0.6, 1.0], cell_size: 0.1,
       boundary: {{x_max: {{traction: [{}, 0]}}, y_max: {{traction: [0, {}]}}}}}}
materials: {{steel: {{model: linear_elastic, density: 1000, youngs_modulus: 1.0e6, poisson_ratio: 0.3}}}}
bodies: [{{material: steel, shape: {{type: box, min: [0, 0], max: [0.6, 1.0]}}}}]
solver: {{scheme: usl, shape_function: {}, dt: 1.0e-4, end_time: 1}}
)",
                                                         t_r, t_z, shape));
    sim->advance(dt);
    const auto momentum = sim->energy().momentum;
    EXPECT_NEAR(momentum[0], dt * t_r * 2 * pi * R * H, 1e-12 * dt * t_r * 2 * pi * R * H) << shape;
    EXPECT_NEAR(momentum[1], dt * t_z * pi * R * R, 1e-12 * std::abs(dt * t_z * pi * R * R)) << shape;
  }
}

// The .vtu of an axisymmetric run names the components of the stress, vectors and 3x3 tensors in cylindrical axes.
TEST(Axisymmetric, OutputNamesCylindricalComponents) {
  auto sim = test::simulation_from_yaml<2>(cylinder_scene("musl", "linear", 2, "[0, 0]"));
  const auto dir = std::filesystem::path(MPM_BINARY_DIR) / "test_axisymmetric_output";
  std::filesystem::remove_all(dir);
  OutputWriter<2> writer(dir, "particles", {"velocity", "stress", "deformation_gradient"}, false, 0);
  writer.write(*sim);
  std::ifstream in(dir / "particles_000000.vtu", std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  const std::string vtu = text.str();
  for (const char* name : {R"(ComponentName0="rr")", R"(ComponentName2="thetatheta")", R"(ComponentName3="rz")",
                           R"(ComponentName2="theta")", R"(ComponentName8="thetatheta")"})
    EXPECT_NE(vtu.find(name), std::string::npos) << name;
}

}  // namespace
}  // namespace mpm
