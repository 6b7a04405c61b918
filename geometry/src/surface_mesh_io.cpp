#include "surface_mesh_io.hpp"

#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <fmt/format.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <iterator>

#include "mpm/geometry/geometry_error.hpp"

namespace mpm::geometry::detail {

namespace PMP = CGAL::Polygon_mesh_processing;

namespace {

std::string lower_extension(const std::string& file) {
  std::string ext = std::filesystem::path(file).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

/// x -> R (scale x) + t with R = Rz Ry Rx (rotations about x, then y, then z, in degrees).
Eigen::Matrix3d rotation_matrix(const std::array<double, 3>& degrees) {
  const double to_rad = M_PI / 180;
  return (Eigen::AngleAxisd(degrees[2] * to_rad, Eigen::Vector3d::UnitZ()) *
          Eigen::AngleAxisd(degrees[1] * to_rad, Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(degrees[0] * to_rad, Eigen::Vector3d::UnitX()))
      .toRotationMatrix();
}

}  // namespace

SurfaceMesh load_surface_mesh(const MeshShape& shape, std::vector<std::string>* warnings) {
  const std::string& file = shape.file;
  std::error_code error;
  if (!std::filesystem::exists(file, error)) throw GeometryError(file, "mesh file not found");
  if (std::filesystem::is_directory(file, error)) throw GeometryError(file, "is a directory, not a mesh file");
  const std::string ext = lower_extension(file);
  const std::vector<std::string> formats{".stl", ".obj", ".off", ".ply"};
  if (std::find(formats.begin(), formats.end(), ext) == formats.end())
    throw GeometryError(file, fmt::format("unsupported mesh format '{}' (supported: .stl, .obj, .off, .ply)", ext));
  if (std::filesystem::file_size(file, error) == 0) throw GeometryError(file, "the mesh file is empty");

  std::vector<Point3> points;
  std::vector<std::vector<std::size_t>> polygons;
  if (!CGAL::IO::read_polygon_soup(file, points, polygons)) {
    std::string format = ext.substr(1);
    std::transform(format.begin(), format.end(), format.begin(), [](unsigned char c) { return std::toupper(c); });
    throw GeometryError(file, fmt::format("cannot read the {} file (corrupt, truncated or not {})", format, format));
  }
  if (polygons.empty()) throw GeometryError(file, "the mesh has no face");
  for (const auto& polygon : polygons)
    for (const std::size_t v : polygon)
      if (v >= points.size())
        throw GeometryError(file, fmt::format("a face refers to vertex {} of {}", v, points.size()));

  // Scale, rotate, translate.
  const Eigen::Matrix3d R = rotation_matrix(shape.rotation);
  for (auto& p : points) {
    const Eigen::Vector3d x = R * (shape.scale * Eigen::Vector3d(p.x(), p.y(), p.z())) +
                              Eigen::Vector3d(shape.translation[0], shape.translation[1], shape.translation[2]);
    p = Point3(x[0], x[1], x[2]);
  }

  return close_polygon_soup(file, std::move(points), std::move(polygons), warnings);
}

SurfaceMesh close_polygon_soup(const std::string& file, std::vector<Point3> points,
                               std::vector<std::vector<std::size_t>> polygons, std::vector<std::string>* warnings) {
  // STL repeats every vertex per triangle: merge them; drop degenerate and duplicated faces.
  PMP::repair_polygon_soup(points, polygons);
  if (polygons.empty()) throw GeometryError(file, "the mesh has no face of positive area");
  if (!PMP::is_polygon_soup_a_polygon_mesh(polygons)) {
    const std::size_t before = points.size();
    if (!PMP::orient_polygon_soup(points, polygons) || points.size() != before)
      throw GeometryError(file,
                          "the mesh is not manifold: an edge is shared by more than two faces or faces meet at a "
                          "single vertex");
    if (warnings) warnings->push_back(file + ": faces with inconsistent orientation were flipped");
  }
  SurfaceMesh mesh;
  PMP::polygon_soup_to_polygon_mesh(points, polygons, mesh);
  if (!CGAL::is_triangle_mesh(mesh)) PMP::triangulate_faces(mesh);
  if (!CGAL::is_closed(mesh)) {
    std::size_t border = 0;
    for (const auto h : mesh.halfedges())
      if (mesh.is_border(h)) ++border;
    throw GeometryError(file, fmt::format("the mesh is open: {} edge{} bound{} a single face (the surface has a hole)",
                                          border, border == 1 ? "" : "s", border == 1 ? "s" : ""));
  }
  if (PMP::does_self_intersect(mesh)) {
    std::vector<std::pair<SurfaceMesh::Face_index, SurfaceMesh::Face_index>> pairs;
    PMP::self_intersections(mesh, std::back_inserter(pairs));
    throw GeometryError(
        file, fmt::format("the mesh intersects itself ({} pair{} of faces cross, e.g. faces {} and {})", pairs.size(),
                          pairs.size() == 1 ? "" : "s", pairs.empty() ? 0 : std::size_t(pairs[0].first),
                          pairs.empty() ? 0 : std::size_t(pairs[0].second)));
  }
  const double before = PMP::volume(mesh);
  PMP::orient_to_bound_a_volume(mesh);
  const double after = PMP::volume(mesh);
  if (after != before && warnings)
    warnings->push_back(
        fmt::format("{}: the mesh was inside out (signed volume {:.6g} m^3); its faces were reversed", file, before));
  if (!(after > 0)) throw GeometryError(file, "the mesh encloses no volume");
  return mesh;
}

SurfaceMesh box_mesh(const Box<3>& box) {
  const Vec<3>&lo = box.lo, &hi = box.hi;
  SurfaceMesh mesh;
  std::array<SurfaceMesh::Vertex_index, 8> v;
  for (int k = 0; k < 8; ++k)
    v[k] = mesh.add_vertex(Point3(k & 1 ? hi[0] : lo[0], k & 2 ? hi[1] : lo[1], k & 4 ? hi[2] : lo[2]));
  // Outward quads (corner bits: x = 1, y = 2, z = 4), each as two triangles.
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : quads) {
    mesh.add_face(v[q[0]], v[q[1]], v[q[2]]);
    mesh.add_face(v[q[0]], v[q[2]], v[q[3]]);
  }
  return mesh;
}

}  // namespace mpm::geometry::detail
