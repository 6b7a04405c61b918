/// \file bench_fill.cpp
/// Fill time of a CAD mesh: a closed UV sphere of about 100,000 triangles written as a binary STL file is
/// read, checked (closed, manifold, no self-intersection, orientation) and filled with about 10^6
/// particles on the grid lattice (2 per cell per axis), on one core. Prints the read+check time, the fill
/// time (AABB tree built on the first inside query), particles per second, and the volume errors: the
/// particle volumes against the exact polyhedron volume (should be round-off) and the lattice count x
/// sub-cell volume against it (the fill's discretisation error).
///
/// This is a program, not a test: timings depend on the machine. See bench/README.md.
///   bench_fill [--triangles N] [--particles N]

#include <fmt/format.h>
#include <tbb/global_control.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "mpm/geometry/mesh_region.hpp"
#include "mpm/geometry/primitive_filler.hpp"

namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

struct Sphere {
  std::vector<std::array<float, 3>> points;
  std::vector<std::array<int, 3>> triangles;
};

/// UV sphere of radius r about (c, c, c): n rings and 2n segments, 4 n (n - 1) triangles, float points.
Sphere uv_sphere(double r, double c, int n) {
  Sphere s;
  const int segments = 2 * n;
  s.points.push_back({float(c), float(c), float(c + r)});
  s.points.push_back({float(c), float(c), float(c - r)});
  for (int i = 1; i < n; ++i)
    for (int j = 0; j < segments; ++j) {
      const double th = M_PI * i / n, ph = 2 * M_PI * j / segments;
      s.points.push_back({float(c + r * std::sin(th) * std::cos(ph)), float(c + r * std::sin(th) * std::sin(ph)),
                          float(c + r * std::cos(th))});
    }
  const auto id = [&](int i, int j) { return 2 + (i - 1) * segments + (j % segments); };
  for (int j = 0; j < segments; ++j) s.triangles.push_back({0, id(1, j), id(1, j + 1)});
  for (int i = 1; i < n - 1; ++i)
    for (int j = 0; j < segments; ++j) {
      s.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      s.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  for (int j = 0; j < segments; ++j) s.triangles.push_back({1, id(n - 1, j + 1), id(n - 1, j)});
  return s;
}

void write_binary_stl(const std::filesystem::path& file, const Sphere& s) {
  std::ofstream out(file, std::ios::binary);
  const std::string header(80, ' ');
  out.write(header.data(), 80);
  const auto n = static_cast<std::uint32_t>(s.triangles.size());
  out.write(reinterpret_cast<const char*>(&n), 4);
  for (const auto& t : s.triangles) {
    float values[12] = {0, 0, 0};  // the normal is not used by the reader
    for (int k = 0; k < 3; ++k)
      for (int d = 0; d < 3; ++d) values[3 + 3 * k + d] = s.points[t[k]][d];
    out.write(reinterpret_cast<const char*>(values), sizeof values);
    const std::uint16_t attribute = 0;
    out.write(reinterpret_cast<const char*>(&attribute), 2);
  }
}

/// Exact volume of the polyhedron (divergence theorem, in double from the float points).
double polyhedron_volume(const Sphere& s) {
  double v = 0;
  for (const auto& t : s.triangles) {
    const auto &a = s.points[t[0]], &b = s.points[t[1]], &c = s.points[t[2]];
    const double ax = a[0], ay = a[1], az = a[2], bx = b[0], by = b[1], bz = b[2], cx = c[0], cy = c[1], cz = c[2];
    v += ax * (by * cz - bz * cy) - ay * (bx * cz - bz * cx) + az * (bx * cy - by * cx);
  }
  return v / 6;
}

}  // namespace

int main(int argc, char** argv) {
  long triangles = 100000, particles = 1000000;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string key = argv[i];
    if (key == "--triangles")
      triangles = std::atol(argv[i + 1]);
    else if (key == "--particles")
      particles = std::atol(argv[i + 1]);
    else {
      fmt::print(stderr, "usage: bench_fill [--triangles N] [--particles N]\n");
      return 2;
    }
  }
  tbb::global_control one_core(tbb::global_control::max_allowed_parallelism, 1);
  const double r = 0.5, c = 0.6;
  const int rings = std::max(3, static_cast<int>(std::lround(std::sqrt(triangles / 4.0))));
  const Sphere sphere = uv_sphere(r, c, rings);
  const auto dir = std::filesystem::temp_directory_path() / ("mpm_bench_fill_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const auto file = dir / "sphere.stl";
  write_binary_stl(file, sphere);

  // Sub-cell spacing s for `particles` in the ball: (4/3) pi r^3 / s^3; cells of 2 s.
  const double s = std::cbrt(4.0 / 3 * M_PI * r * r * r / static_cast<double>(particles)), h = 2 * s;
  const int cells = static_cast<int>(std::ceil(2 * c / h));
  const mpm::GridGeometry<3> grid(mpm::Vec<3>::Zero(), mpm::Vec<3>::Constant(h), {cells, cells, cells});

  mpm::geometry::MeshShape shape;
  shape.file = file.string();
  const auto t0 = Clock::now();
  mpm::geometry::MeshSummary summary;
  const auto region = mpm::geometry::make_mesh_region(shape, nullptr, &summary);
  const double read_s = seconds_since(t0);
  const auto t1 = Clock::now();
  const auto seeds = mpm::geometry::fill_region<3>(*region, grid, {2, 2, 2});
  const double fill_s = seconds_since(t1);
  std::filesystem::remove_all(dir);

  const double exact = polyhedron_volume(sphere);
  const double n = static_cast<double>(seeds.positions.size());
  fmt::print("mesh: UV sphere r = {} m, {} triangles, {} vertices (binary STL)\n", r, summary.triangles,
             summary.vertices);
  fmt::print("grid: {}^3 cells of {:.5g} m, 2 particles per cell per axis\n", cells, h);
  fmt::print("read + check (closed, manifold, self-intersection, orientation, volume): {:.3f} s\n", read_s);
  fmt::print("fill (AABB tree built on the first inside test): {:.3f} s, {} particles, {:.3g} particles/s\n", fill_s,
             seeds.positions.size(), n / fill_s);
  fmt::print("total: {:.3f} s on one core\n", read_s + fill_s);
  fmt::print("particle volume sum vs polyhedron volume: relative error {:.3g}\n", n * seeds.volume / exact - 1);
  fmt::print("lattice (count x sub-cell volume) vs polyhedron volume: relative error {:.3g}\n",
             n * seeds.sub_cell_volume / exact - 1);
  fmt::print("polyhedron vs sphere volume: relative difference {:.3g}\n", exact / (4.0 / 3 * M_PI * r * r * r) - 1);
  return 0;
}
