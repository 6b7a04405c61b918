// Volume, centroid and inertia of particles, closed triangle meshes and tetrahedra, and the fidelity certificate
// (mpm/geometry/mass_properties.hpp).
#include "mpm/geometry/mass_properties.hpp"

#include <fmt/format.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <cmath>
#include <utility>

namespace mpm::geometry {

void RawMoments::add_tetrahedron(const Vec<3>& a, const Vec<3>& b, const Vec<3>& c, const Vec<3>& d) {
  // int x dV = V (a + b + c + d) / 4; int x x^T dV = V / 20 (sum_i v_i v_i^T + s s^T), s = a + b + c + d (the
  // second moments of a simplex, e.g. Tonon, J. Math. Stat. 1 (2004) 8-11).
  const Real v = (b - a).cross(c - a).dot(d - a) / 6;
  const Vec<3> s = a + b + c + d;
  volume += v;
  first += v / 4 * s;
  second +=
      v / 20 * (a * a.transpose() + b * b.transpose() + c * c.transpose() + d * d.transpose() + s * s.transpose());
}

void RawMoments::add_point(const Vec<3>& x, Real v) {
  volume += v;
  first += v * x;
  second += v * x * x.transpose();
}

void RawMoments::merge(const RawMoments& other) {
  volume += other.volume;
  first += other.first;
  second += other.second;
}

MassProperties RawMoments::central(const Vec<3>& origin) const {
  MassProperties p;
  p.volume = volume;
  if (!(volume != 0)) return p;
  const Vec<3> c = first / volume;  // relative to origin
  p.centroid = origin + c;
  const Mat<3> covariance = second - volume * c * c.transpose();  // int r r^T dV about the centroid
  p.inertia = covariance.trace() * Mat<3>::Identity() - covariance;
  return p;
}

MassProperties particle_properties(const std::vector<Vec<3>>& positions, const std::vector<Real>& volumes) {
  RawMoments m;
  const Vec<3> origin = positions.empty() ? Vec<3>::Zero() : positions.front();
  for (std::size_t k = 0; k < positions.size(); ++k) m.add_point(positions[k] - origin, volumes[k]);
  return m.central(origin);
}

MassProperties mesh_properties(const std::vector<Vec<3>>& points,
                               const std::vector<std::array<std::size_t, 3>>& triangles) {
  RawMoments m;
  const Vec<3> origin = points.empty() ? Vec<3>::Zero() : points.front();
  const Vec<3> apex = Vec<3>::Zero();
  for (const auto& t : triangles)
    m.add_tetrahedron(apex, points[t[0]] - origin, points[t[1]] - origin, points[t[2]] - origin);
  return m.central(origin);
}

MassProperties combine(const MassProperties& a, const MassProperties& b) {
  // Back to raw moments about a's centroid: covariance C = tr(I) / 2 Id - I, second moment C + V c c^T.
  const auto raw = [&](const MassProperties& p) {
    RawMoments m;
    const Vec<3> c = p.centroid - a.centroid;
    m.volume = p.volume;
    m.first = p.volume * c;
    m.second = p.inertia.trace() / 2 * Mat<3>::Identity() - p.inertia + p.volume * c * c.transpose();
    return m;
  };
  RawMoments m = raw(a);
  m.merge(raw(b));
  return m.central(a.centroid);
}

FidelityCertificate certify(const MassProperties& exact, const MassProperties& particles, std::string source) {
  FidelityCertificate c;
  c.exact = exact;
  c.particles = particles;
  c.source = std::move(source);
  c.volume_error = exact.volume != 0 ? particles.volume / exact.volume - 1 : 0;
  const Real gyration = std::sqrt(std::abs(exact.inertia.trace()) / (2 * std::abs(exact.volume)));
  c.centroid_error = gyration > 0 ? (particles.centroid - exact.centroid).norm() / gyration : 0;
  const Real principal = Eigen::SelfAdjointEigenSolver<Mat<3>>(exact.inertia).eigenvalues().cwiseAbs().maxCoeff();
  c.inertia_error = principal > 0 ? (particles.inertia - exact.inertia).cwiseAbs().maxCoeff() / principal : 0;
  return c;
}

namespace {

std::string vector_text(const Vec<3>& x) { return fmt::format("({:.6g}, {:.6g}, {:.6g})", x[0], x[1], x[2]); }

std::string diagonal_text(const Mat<3>& m) {
  return fmt::format("[{:.6g}, {:.6g}, {:.6g}; {:.6g}, {:.6g}, {:.6g}]", m(0, 0), m(1, 1), m(2, 2), m(0, 1), m(0, 2),
                     m(1, 2));
}

}  // namespace

std::string format_certificate(const FidelityCertificate& c, const std::string& indent) {
  return fmt::format(
      "{0}fidelity against the {1}:\n"
      "{0}  volume    {2:.10g} m^3, particles {3:.10g} m^3 (relative error {4:.3g})\n"
      "{0}  centroid  {5} m, particles {6} m (error {7:.3g} of the radius of gyration)\n"
      "{0}  inertia   [xx, yy, zz; xy, xz, yz] per unit density {8} m^5, particles {9} m^5 (largest error {10:.3g} of "
      "the largest principal moment)\n",
      indent, c.source, c.exact.volume, c.particles.volume, c.volume_error, vector_text(c.exact.centroid),
      vector_text(c.particles.centroid), c.centroid_error, diagonal_text(c.exact.inertia),
      diagonal_text(c.particles.inertia), c.inertia_error);
}

}  // namespace mpm::geometry
