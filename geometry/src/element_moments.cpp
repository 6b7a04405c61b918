// Exact moments of first-order mesh elements (mpm/geometry/element_moments.hpp).
#include "mpm/geometry/element_moments.hpp"

#include <fmt/format.h>

#include <Eigen/Geometry>
#include <cmath>

#include "mpm/geometry/geometry_error.hpp"

namespace mpm::geometry {

namespace {

/// A point of the reference element, its weight, the shape functions there and their derivatives.
struct QuadraturePoint {
  double weight = 0;
  std::vector<double> shape;
  std::vector<Vec<3>> gradient;  ///< d shape / d reference coordinates (unused axes 0)
};

/// Gauss-Legendre, 3 points on [-1, 1] (exact to degree 5).
constexpr std::array<double, 3> gauss_x{-0.774596669241483377, 0.0, 0.774596669241483377};
constexpr std::array<double, 3> gauss_w{5.0 / 9, 8.0 / 9, 5.0 / 9};

/// Dunavant's 6-point rule on the triangle (0,0), (1,0), (0,1), exact to degree 4; weights sum to 1 (area 1/2).
struct TrianglePoint {
  double u, v, w;
};
const std::array<TrianglePoint, 6>& triangle_rule() {
  constexpr double a = 0.445948490915965, b = 0.091576213509771;
  constexpr double wa = 0.223381589678011, wb = 0.109951743655322;
  static const std::array<TrianglePoint, 6> rule{
      {{a, a, wa}, {1 - 2 * a, a, wa}, {a, 1 - 2 * a, wa}, {b, b, wb}, {1 - 2 * b, b, wb}, {b, 1 - 2 * b, wb}}};
  return rule;
}

/// Hexahedron (Gmsh order: corners of z = -1 counter-clockwise, then of z = +1), 27 points.
std::vector<QuadraturePoint> hexahedron_rule() {
  static const int corner[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                   {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
  std::vector<QuadraturePoint> points;
  points.reserve(27);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) {
        const double x = gauss_x[i], y = gauss_x[j], z = gauss_x[k];
        QuadraturePoint q;
        q.weight = gauss_w[i] * gauss_w[j] * gauss_w[k];
        for (const auto& c : corner) {
          const double fx = 1 + c[0] * x, fy = 1 + c[1] * y, fz = 1 + c[2] * z;
          q.shape.push_back(fx * fy * fz / 8);
          q.gradient.emplace_back(c[0] * fy * fz / 8, c[1] * fx * fz / 8, c[2] * fx * fy / 8);
        }
        points.push_back(std::move(q));
      }
  return points;
}

/// Prism (Gmsh order: triangle (0,0), (1,0), (0,1) at z = -1, then at z = +1), 18 points.
std::vector<QuadraturePoint> prism_rule() {
  std::vector<QuadraturePoint> points;
  points.reserve(18);
  for (const auto& t : triangle_rule())
    for (int k = 0; k < 3; ++k) {
      const double z = gauss_x[k];
      QuadraturePoint q;
      q.weight = t.w / 2 * gauss_w[k];
      const std::array<double, 3> l{1 - t.u - t.v, t.u, t.v};
      const std::array<Vec<3>, 3> dl{Vec<3>(-1, -1, 0), Vec<3>(1, 0, 0), Vec<3>(0, 1, 0)};
      for (const double side : {-1.0, 1.0}) {
        const double f = (1 + side * z) / 2;
        for (int c = 0; c < 3; ++c) {
          q.shape.push_back(l[c] * f);
          q.gradient.push_back(dl[c] * f + Vec<3>(0, 0, l[c] * side / 2));
        }
      }
      points.push_back(std::move(q));
    }
  return points;
}

/// Quadrangle (corners (-1,-1), (1,-1), (1,1), (-1,1)), 9 points.
std::vector<QuadraturePoint> quadrangle_rule() {
  static const int corner[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  std::vector<QuadraturePoint> points;
  points.reserve(9);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const double x = gauss_x[i], y = gauss_x[j];
      QuadraturePoint q;
      q.weight = gauss_w[i] * gauss_w[j];
      for (const auto& c : corner) {
        q.shape.push_back((1 + c[0] * x) * (1 + c[1] * y) / 4);
        q.gradient.emplace_back(c[0] * (1 + c[1] * y) / 4, c[1] * (1 + c[0] * x) / 4, 0);
      }
      points.push_back(std::move(q));
    }
  return points;
}

[[noreturn]] void refuse(const GmshMesh& mesh, const GmshElement& e, const std::string& problem) {
  throw GeometryError(mesh.file, fmt::format("line {}: element {} {}", e.line, e.tag, problem));
}

/// The moments by quadrature; the Jacobian's sign must not change (an element numbered clockwise counts positive).
RawMoments integrate(const GmshMesh& mesh, const GmshElement& e, const std::vector<Vec<3>>& x,
                     const std::vector<QuadraturePoint>& rule, int dimension) {
  RawMoments m;
  int positive = 0, negative = 0;
  for (const auto& q : rule) {
    Vec<3> point = Vec<3>::Zero();
    Mat<3> jacobian = Mat<3>::Zero();
    for (std::size_t a = 0; a < x.size(); ++a) {
      point += q.shape[a] * x[a];
      jacobian += x[a] * q.gradient[a].transpose();
    }
    const double det = dimension == 3 ? jacobian.determinant() : jacobian.topLeftCorner<2, 2>().determinant();
    (det > 0 ? positive : negative) += 1;
    m.add_point(point, q.weight * det);
  }
  if (positive > 0 && negative > 0) refuse(mesh, e, "is inverted or degenerate (its Jacobian changes sign)");
  if (negative > 0) {  // numbered the other way round
    m.volume = -m.volume;
    m.first = -m.first;
    m.second = -m.second;
  }
  if (!(m.volume > 0)) refuse(mesh, e, "has no volume (degenerate)");
  return m;
}

/// The simplex's moments in closed form (mass_properties.hpp; a triangle: int x x^T dA = A / 12 (sum v v^T + s s^T)).
RawMoments simplex(const GmshMesh& mesh, const GmshElement& e, const std::vector<Vec<3>>& x) {
  RawMoments m;
  if (x.size() == 4) {
    m.add_tetrahedron(x[0], x[1], x[2], x[3]);
    if (m.volume < 0) {
      m = RawMoments();
      m.add_tetrahedron(x[0], x[2], x[1], x[3]);
    }
  } else {
    const double area = std::abs((x[1] - x[0]).cross(x[2] - x[0])[2]) / 2;
    const Vec<3> s = x[0] + x[1] + x[2];
    m.volume = area;
    m.first = area / 3 * s;
    m.second =
        area / 12 * (x[0] * x[0].transpose() + x[1] * x[1].transpose() + x[2] * x[2].transpose() + s * s.transpose());
  }
  if (!(m.volume > 0)) refuse(mesh, e, "has no volume (degenerate)");
  return m;
}

}  // namespace

RawMoments element_moments(const GmshMesh& mesh, const GmshElement& e, int dimension, const Vec<3>& origin) {
  std::vector<Vec<3>> x;
  x.reserve(e.nodes.size());
  for (const std::size_t n : e.nodes) {
    const auto& p = mesh.nodes[n];
    x.emplace_back(p[0] - origin[0], p[1] - origin[1], dimension == 3 ? p[2] - origin[2] : 0.0);
  }
  static const std::vector<QuadraturePoint> hexahedron = hexahedron_rule(), prism = prism_rule(),
                                            quadrangle = quadrangle_rule();
  if (dimension == 3 && e.type == 4) return simplex(mesh, e, x);
  if (dimension == 3 && e.type == 5) return integrate(mesh, e, x, hexahedron, 3);
  if (dimension == 3 && e.type == 6) return integrate(mesh, e, x, prism, 3);
  if (dimension == 2 && e.type == 2) return simplex(mesh, e, x);
  if (dimension == 2 && e.type == 3) return integrate(mesh, e, x, quadrangle, 2);
  refuse(mesh, e,
         fmt::format("has element type {} ({} nodes), which is not read: {}D bodies take first-order {} (Gmsh: "
                     "Mesh.ElementOrder = 1)",
                     e.type, e.nodes.size(), dimension,
                     dimension == 3 ? "tetrahedra (4), hexahedra (5) and prisms (6)"
                                    : "triangles (2) and "
                                      "quadrangles (3)"));
}

}  // namespace mpm::geometry
