#pragma once
// Triangle meshes for the geometry tests (a cube, a UV sphere, a torus), their exact polyhedral volume
// (divergence theorem, independent of CGAL) and writers for every format the geometry module reads.
#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace mpm::test {

struct TriMesh {
  std::vector<std::array<double, 3>> points;
  std::vector<std::array<int, 3>> triangles;  ///< counter-clockwise seen from outside
};

/// Unit cube [0, 1]^3, 12 triangles.
inline TriMesh cube_mesh() {
  TriMesh m;
  for (int k = 0; k < 8; ++k) m.points.push_back({double(k & 1), double((k >> 1) & 1), double((k >> 2) & 1)});
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : quads) {
    m.triangles.push_back({q[0], q[1], q[2]});
    m.triangles.push_back({q[0], q[2], q[3]});
  }
  return m;
}

/// UV sphere of radius r about c: n_theta rings, n_phi segments, 2 n_phi (n_theta - 1) triangles.
inline TriMesh sphere_mesh(double r, std::array<double, 3> c, int n_theta, int n_phi) {
  TriMesh m;
  m.points.push_back({c[0], c[1], c[2] + r});
  m.points.push_back({c[0], c[1], c[2] - r});
  for (int i = 1; i < n_theta; ++i)
    for (int j = 0; j < n_phi; ++j) {
      const double th = M_PI * i / n_theta, ph = 2 * M_PI * j / n_phi;
      m.points.push_back(
          {c[0] + r * std::sin(th) * std::cos(ph), c[1] + r * std::sin(th) * std::sin(ph), c[2] + r * std::cos(th)});
    }
  const auto id = [&](int i, int j) { return 2 + (i - 1) * n_phi + (j % n_phi); };
  for (int j = 0; j < n_phi; ++j) m.triangles.push_back({0, id(1, j), id(1, j + 1)});
  for (int i = 1; i < n_theta - 1; ++i)
    for (int j = 0; j < n_phi; ++j) {
      m.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      m.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  for (int j = 0; j < n_phi; ++j) m.triangles.push_back({1, id(n_theta - 1, j + 1), id(n_theta - 1, j)});
  return m;
}

/// Torus about the z axis through c: major radius R, minor radius a, n_u x n_v quads split in two.
inline TriMesh torus_mesh(double R, double a, std::array<double, 3> c, int n_u, int n_v) {
  TriMesh m;
  for (int i = 0; i < n_u; ++i)
    for (int j = 0; j < n_v; ++j) {
      const double u = 2 * M_PI * i / n_u, v = 2 * M_PI * j / n_v;
      m.points.push_back({c[0] + (R + a * std::cos(v)) * std::cos(u), c[1] + (R + a * std::cos(v)) * std::sin(u),
                          c[2] + a * std::sin(v)});
    }
  const auto id = [&](int i, int j) { return (i % n_u) * n_v + (j % n_v); };
  for (int i = 0; i < n_u; ++i)
    for (int j = 0; j < n_v; ++j) {
      m.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      m.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return m;
}

/// Exact volume of the closed polyhedron: sum of the signed tetrahedra (origin, a, b, c) / 6.
inline double polyhedron_volume(const TriMesh& m) {
  double v = 0;
  for (const auto& t : m.triangles) {
    const auto &a = m.points[t[0]], &b = m.points[t[1]], &c = m.points[t[2]];
    v += a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0]);
  }
  return v / 6;
}

inline void write_off(const std::filesystem::path& file, const TriMesh& m) {
  std::ofstream out(file);
  out.precision(17);
  out << "OFF\n" << m.points.size() << ' ' << m.triangles.size() << " 0\n";
  for (const auto& p : m.points) out << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
  for (const auto& t : m.triangles) out << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
}

inline void write_obj(const std::filesystem::path& file, const TriMesh& m) {
  std::ofstream out(file);
  out.precision(17);
  for (const auto& p : m.points) out << "v " << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
  for (const auto& t : m.triangles) out << "f " << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << '\n';
}

inline void write_ply(const std::filesystem::path& file, const TriMesh& m) {
  std::ofstream out(file);
  out.precision(17);
  out << "ply\nformat ascii 1.0\nelement vertex " << m.points.size()
      << "\nproperty double x\nproperty double y\nproperty double z\nelement face " << m.triangles.size()
      << "\nproperty list uchar int vertex_indices\nend_header\n";
  for (const auto& p : m.points) out << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
  for (const auto& t : m.triangles) out << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
}

inline std::array<double, 3> normal(const TriMesh& m, const std::array<int, 3>& t) {
  const auto &a = m.points[t[0]], &b = m.points[t[1]], &c = m.points[t[2]];
  const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
  std::array<double, 3> n{u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
  const double l = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  for (auto& x : n) x /= l;
  return n;
}

inline void write_stl_ascii(const std::filesystem::path& file, const TriMesh& m) {
  std::ofstream out(file);
  out.precision(17);
  out << "solid test\n";
  for (const auto& t : m.triangles) {
    const auto n = normal(m, t);
    out << "facet normal " << n[0] << ' ' << n[1] << ' ' << n[2] << "\nouter loop\n";
    for (int k = 0; k < 3; ++k) {
      const auto& p = m.points[t[k]];
      out << "vertex " << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
    }
    out << "endloop\nendfacet\n";
  }
  out << "endsolid test\n";
}

/// Binary STL: 80-byte header, triangle count, then per triangle 12 floats and a 2-byte attribute.
inline void write_stl_binary(const std::filesystem::path& file, const TriMesh& m) {
  std::ofstream out(file, std::ios::binary);
  const std::string header(80, ' ');
  out.write(header.data(), 80);
  const std::uint32_t n = static_cast<std::uint32_t>(m.triangles.size());
  out.write(reinterpret_cast<const char*>(&n), 4);
  for (const auto& t : m.triangles) {
    const auto nn = normal(m, t);
    float values[12];
    for (int d = 0; d < 3; ++d) values[d] = static_cast<float>(nn[d]);
    for (int k = 0; k < 3; ++k)
      for (int d = 0; d < 3; ++d) values[3 + 3 * k + d] = static_cast<float>(m.points[t[k]][d]);
    out.write(reinterpret_cast<const char*>(values), sizeof values);
    const std::uint16_t attribute = 0;
    out.write(reinterpret_cast<const char*>(&attribute), 2);
  }
}

}  // namespace mpm::test
