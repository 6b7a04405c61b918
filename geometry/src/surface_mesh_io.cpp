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
#include <fmt/ranges.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <iterator>

#include "mpm/geometry/geometry_error.hpp"
#include "obj_objects.hpp"
#include "soup_shells.hpp"
#include "soup_weld.hpp"

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

/// How the messages give coordinates: a mesh file's own (the checks run before its transform), or metres (a CAD
/// solid's tessellation, converted on reading).
enum class Coordinates { file, metres };

std::string point_text(const Point3& p) { return fmt::format("({:.6g}, {:.6g}, {:.6g})", p.x(), p.y(), p.z()); }

/// "A-B, C-D, E-F, ... (in the file's coordinates)": the first three of `places`, each a point or an edge.
std::string places_text(const std::vector<std::string>& places, Coordinates coordinates) {
  constexpr std::size_t shown = 3;
  std::string text;
  for (std::size_t k = 0; k < std::min(shown, places.size()); ++k) text += (k ? ", " : "") + places[k];
  if (places.size() > shown) text += ", ...";
  return text + (coordinates == Coordinates::file ? " (in the file's coordinates)" : " m");
}

/// The edges of the soup that more than two polygons share, each once, as "A-B".
std::vector<std::string> shared_edges(const std::vector<Point3>& points,
                                      const std::vector<std::vector<std::size_t>>& polygons) {
  std::vector<std::pair<std::size_t, std::size_t>> edges;
  for (const auto& polygon : polygons)
    for (std::size_t k = 0; k < polygon.size(); ++k) {
      const std::size_t a = polygon[k], b = polygon[(k + 1) % polygon.size()];
      edges.emplace_back(std::min(a, b), std::max(a, b));
    }
  std::sort(edges.begin(), edges.end());
  std::vector<std::string> shared;
  for (std::size_t k = 0; k < edges.size();) {
    std::size_t n = k + 1;
    while (n < edges.size() && edges[n] == edges[k]) ++n;
    if (n - k > 2) shared.push_back(point_text(points[edges[k].first]) + "-" + point_text(points[edges[k].second]));
    k = n;
  }
  return shared;
}

/// Refuses a soup that is not a manifold surface, naming where: the edges more than two faces share, or the points
/// where faces meet at a single vertex (which orient_polygon_soup duplicates, appending the copies). Two solids
/// touching along a face, an edge or a corner give either; a mesh file of several objects can make them two bodies.
void refuse_non_manifold(const std::string& file, std::vector<Point3>& points,
                         std::vector<std::vector<std::size_t>>& polygons, std::vector<std::string>* warnings,
                         Coordinates coordinates) {
  const std::string two_bodies =
      coordinates == Coordinates::file
          ? "where two solids touch, make them two bodies (a file each, or an OBJ object each chosen with "
            "`object: NAME`)"
          : "where two solids touch, make them two bodies";
  if (const auto edges = shared_edges(points, polygons); !edges.empty())
    throw GeometryError(file, fmt::format("the mesh is not manifold: {} edge{} {} shared by more than two faces, at "
                                          "{}; {}",
                                          edges.size(), edges.size() == 1 ? "" : "s", edges.size() == 1 ? "is" : "are",
                                          places_text(edges, coordinates), two_bodies));
  const std::size_t before = points.size();
  const bool oriented = PMP::orient_polygon_soup(points, polygons);
  if (!oriented || points.size() != before) {
    std::vector<std::string> corners;
    for (std::size_t k = before; k < points.size(); ++k)
      if (std::find(points.begin() + before, points.begin() + k, points[k]) == points.begin() + k)
        corners.push_back(point_text(points[k]));
    throw GeometryError(file, corners.empty()
                                  ? std::string("the mesh is not manifold: its faces cannot be oriented consistently")
                                  : fmt::format("the mesh is not manifold: faces meet at a single vertex at {}; {}",
                                                places_text(corners, coordinates), two_bodies));
  }
  if (warnings) warnings->push_back(file + ": faces with inconsistent orientation were flipped");
}

/// STL repeats every vertex per triangle: merge them; drop degenerate and duplicated faces.
void repair_soup(const std::string& file, std::vector<Point3>& points,
                 std::vector<std::vector<std::size_t>>& polygons) {
  PMP::repair_polygon_soup(points, polygons);
  if (polygons.empty()) throw GeometryError(file, "the mesh has no face of positive area");
}

/// An OBJ's named objects (`o NAME`): with `object: NAME` only that object's faces are kept (and no name is
/// returned); without it, the names of the objects the body merges.
std::vector<std::string> choose_obj_object(const MeshShape& shape, std::vector<std::vector<std::size_t>>& polygons) {
  const ObjObjects objects = read_obj_objects(shape.file);
  if (!shape.object) return objects.names;
  const std::string& name = *shape.object;
  if (objects.names.empty())
    throw GeometryError(shape.file,
                        fmt::format("object '{}': the file names no object (no `o NAME` line); a separate surface "
                                    "is chosen with `shell: INDEX`",
                                    name),
                        "object");
  const auto found = std::find(objects.names.begin(), objects.names.end(), name);
  if (found == objects.names.end())
    throw GeometryError(
        shape.file, fmt::format("no object '{}' in the file; its objects: {}", name, fmt::join(objects.names, ", ")),
        "object");
  if (objects.of_face.size() != polygons.size())  // our count of `f` lines against CGAL's polygons
    throw GeometryError(shape.file,
                        fmt::format("cannot tell the objects' faces apart ({} `f` lines, {} faces read)",
                                    objects.of_face.size(), polygons.size()),
                        "object");
  const auto chosen = static_cast<std::size_t>(found - objects.names.begin());
  std::vector<std::vector<std::size_t>> kept;
  for (std::size_t f = 0; f < polygons.size(); ++f)
    if (objects.of_face[f] == chosen) kept.push_back(std::move(polygons[f]));
  if (kept.empty()) throw GeometryError(shape.file, fmt::format("object '{}' has no face", name), "object");
  polygons = std::move(kept);
  return {};
}

/// The separate shells of a repaired soup: with `shell: INDEX` that shell alone is kept; without it, a body of
/// several shells (or of an OBJ's several objects) is said to merge them, since two parts exported into one file
/// would otherwise silently become one body. A hollow body (an outer and an inner shell) is one body, rightly.
void choose_shell(const MeshShape& shape, const std::vector<std::string>& objects, std::vector<Point3>& points,
                  std::vector<std::vector<std::size_t>>& polygons, std::vector<std::string>* warnings) {
  const std::vector<std::size_t> shell_of = soup_shells(points.size(), polygons);
  const std::size_t shells = shell_of.empty() ? 0 : *std::max_element(shell_of.begin(), shell_of.end()) + 1;
  if (shape.shell) {
    if (*shape.shell >= shells)
      throw GeometryError(
          shape.file,
          fmt::format("shell {} does not exist: the mesh has {} separate shell{} (0{})", *shape.shell, shells,
                      shells == 1 ? "" : "s", shells == 1 ? "" : fmt::format(" to {}", shells - 1)),
          "shell");
    std::vector<std::vector<std::size_t>> kept;
    for (std::size_t f = 0; f < polygons.size(); ++f)
      if (shell_of[f] == *shape.shell) kept.push_back(std::move(polygons[f]));
    polygons = std::move(kept);
    repair_soup(shape.file, points, polygons);  // drops the other shells' points
    return;
  }
  if (!warnings) return;
  const std::string names = fmt::format("{}", fmt::join(objects, ", "));
  if (shells > 1)
    warnings->push_back(fmt::format(
        "{}: {} separate shells{} were merged into one body; if they are separate parts, make each a body with "
        "`shell: INDEX` (0 to {}){} (a hollow body has an inner shell: then this is right)",
        shape.file, shells, objects.size() > 1 ? " (objects " + names + ")" : "", shells - 1,
        objects.size() > 1 ? " or `object: NAME`" : ""));
  else if (objects.size() > 1)
    warnings->push_back(
        fmt::format("{}: the objects {} were merged into one body; make each a body with "
                    "`object: NAME`",
                    shape.file, names));
}

/// The checks of a repaired soup and its mesh: manifold, closed, not self-intersecting, enclosing a volume; an
/// inside-out or inconsistently oriented surface is repaired with a warning.
SurfaceMesh checked_mesh(const std::string& file, std::vector<Point3> points,
                         std::vector<std::vector<std::size_t>> polygons, std::vector<std::string>* warnings,
                         Coordinates coordinates) {
  if (!PMP::is_polygon_soup_a_polygon_mesh(polygons))
    refuse_non_manifold(file, points, polygons, warnings, coordinates);
  SurfaceMesh mesh;
  PMP::polygon_soup_to_polygon_mesh(points, polygons, mesh);
  if (!CGAL::is_triangle_mesh(mesh)) PMP::triangulate_faces(mesh);
  if (!CGAL::is_closed(mesh)) {
    std::size_t border = 0;
    std::vector<std::string> edges;
    for (const auto h : mesh.halfedges())
      if (mesh.is_border(h)) {
        ++border;
        if (edges.size() < 4)
          edges.push_back(point_text(mesh.point(mesh.source(h))) + "-" + point_text(mesh.point(mesh.target(h))));
      }
    throw GeometryError(
        file, fmt::format("the mesh is open: {} edge{} bound{} a single face (the surface has a hole), at {}{}", border,
                          border == 1 ? "" : "s", border == 1 ? "s" : "", places_text(edges, coordinates),
                          coordinates == Coordinates::file
                              ? "; a mesh whose corners were written a little apart closes with `weld: DISTANCE` "
                                "(in the file's coordinates)"
                              : ""));
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
    warnings->push_back(fmt::format("{}: the mesh was inside out (signed volume {:.6g} {}); its faces were reversed",
                                    file, before,
                                    coordinates == Coordinates::file ? "in the file's units cubed" : "m^3"));
  if (!(after > 0)) throw GeometryError(file, "the mesh encloses no volume");
  return mesh;
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

  // The checks run on the file's coordinates, so that their messages give places a user finds in the file and
  // `weld` is a length in them; scale, rotation and translation keep a closed, oriented mesh so (det R > 0).
  const std::vector<std::string> objects =
      ext == ".obj" ? choose_obj_object(shape, polygons) : std::vector<std::string>{};
  if (shape.weld) weld_soup_points(points, polygons, *shape.weld);
  repair_soup(file, points, polygons);
  choose_shell(shape, objects, points, polygons, warnings);
  SurfaceMesh mesh = checked_mesh(file, std::move(points), std::move(polygons), warnings, Coordinates::file);

  const Eigen::Matrix3d R = rotation_matrix(shape.rotation);
  for (const auto v : mesh.vertices()) {
    const Point3& p = mesh.point(v);
    const Eigen::Vector3d x = R * (shape.scale * Eigen::Vector3d(p.x(), p.y(), p.z())) +
                              Eigen::Vector3d(shape.translation[0], shape.translation[1], shape.translation[2]);
    mesh.point(v) = Point3(x[0], x[1], x[2]);
  }
  return mesh;
}

SurfaceMesh close_polygon_soup(const std::string& file, std::vector<Point3> points,
                               std::vector<std::vector<std::size_t>> polygons, std::vector<std::string>* warnings) {
  repair_soup(file, points, polygons);
  return checked_mesh(file, std::move(points), std::move(polygons), warnings, Coordinates::metres);
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
