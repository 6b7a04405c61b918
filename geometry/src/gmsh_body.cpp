// Particles from a Gmsh volume mesh (mpm/geometry/gmsh_body.hpp).
#include "mpm/geometry/gmsh_body.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <map>
#include <memory>
#include <mutex>

#include "mpm/geometry/element_moments.hpp"
#include "mpm/geometry/geometry_error.hpp"
#include "mpm/geometry/gmsh_mesh.hpp"

namespace mpm::geometry {

namespace {

/// The file's mesh, read on first use and kept for the process (the scene reader checks the group names with it, the
/// fill makes the particles).
const GmshMesh& gmsh_mesh(const std::string& file) {
  static std::mutex mutex;
  static std::map<std::string, std::unique_ptr<const GmshMesh>> meshes;
  const std::scoped_lock lock(mutex);
  auto& mesh = meshes[file];
  if (!mesh) mesh = std::make_unique<const GmshMesh>(read_gmsh(file));
  return *mesh;
}

/// The tags of the physical groups of `dimension` named `name`.
std::vector<int> group_tags(const GmshMesh& mesh, const std::string& name, int dimension) {
  std::vector<int> tags;
  for (const auto& [key, group] : mesh.physical_names)
    if (key.first == dimension && group == name) tags.push_back(key.second);
  return tags;
}

}  // namespace

std::vector<std::string> gmsh_group_names(const std::string& file, int dimension) {
  std::vector<std::string> names;
  for (const auto& [key, name] : gmsh_mesh(file).physical_names)
    if (key.first == dimension) names.push_back(name);
  return names;
}

int gmsh_dimension(const std::string& file) {
  int dimension = 0;
  for (const auto& e : gmsh_mesh(file).elements) dimension = std::max(dimension, e.dimension);
  if (dimension < 2) throw GeometryError(file, "the mesh has no 2D or 3D element");
  return dimension;
}

GmshParticles gmsh_particles(const GmshShape& shape, int dimension) {
  const GmshMesh& mesh = gmsh_mesh(shape.file);
  std::vector<int> chosen;  // physical tags; empty: every element of the dimension
  for (const auto& group : shape.groups) {
    const std::vector<int> tags = group_tags(mesh, group, dimension);
    if (tags.empty()) {
      const auto names = gmsh_group_names(shape.file, dimension);
      throw GeometryError(
          shape.file, fmt::format("no {}D physical group named '{}' in the file; its {}D groups: {}", dimension, group,
                                  dimension, names.empty() ? "none" : fmt::format("'{}'", fmt::join(names, "', '"))));
    }
    const bool used = std::any_of(mesh.elements.begin(), mesh.elements.end(), [&](const GmshElement& e) {
      return e.dimension == dimension && std::any_of(e.physicals.begin(), e.physicals.end(), [&](int p) {
               return std::find(tags.begin(), tags.end(), p) != tags.end();
             });
    });
    if (!used)
      throw GeometryError(shape.file,
                          fmt::format("the physical group '{}' has no {}D element (it is empty)", group, dimension));
    chosen.insert(chosen.end(), tags.begin(), tags.end());
  }
  const auto is_chosen = [&](const GmshElement& e) {
    if (e.dimension != dimension) return false;
    return chosen.empty() || std::any_of(e.physicals.begin(), e.physicals.end(), [&](int p) {
             return std::find(chosen.begin(), chosen.end(), p) != chosen.end();
           });
  };
  // Placed nodes (scale, then translation); moments about the first chosen node.
  GmshParticles out;
  const Vec<3> move(shape.translation[0], shape.translation[1], dimension == 3 ? shape.translation[2] : 0.0);
  GmshMesh placed;
  placed.file = mesh.file;
  placed.nodes.reserve(mesh.nodes.size());
  for (const auto& p : mesh.nodes) {
    const Vec<3> x = shape.scale * Vec<3>(p[0], p[1], dimension == 3 ? p[2] : 0.0) + move;
    placed.nodes.push_back({x[0], x[1], x[2]});
  }
  RawMoments total;
  Vec<3> origin = Vec<3>::Zero();
  bool first = true;
  for (const auto& e : mesh.elements) {
    if (!is_chosen(e)) continue;
    if (first) {
      const auto& p = placed.nodes[e.nodes.front()];
      origin = Vec<3>(p[0], p[1], p[2]);
      out.lo = out.hi = origin;
      first = false;
    }
    for (const std::size_t n : e.nodes) {
      const auto& p = placed.nodes[n];
      out.lo = out.lo.cwiseMin(Vec<3>(p[0], p[1], p[2]));
      out.hi = out.hi.cwiseMax(Vec<3>(p[0], p[1], p[2]));
    }
    const RawMoments m = element_moments(placed, e, dimension, origin);
    out.positions.emplace_back(origin + m.first / m.volume);
    out.volumes.push_back(m.volume);
    total.merge(m);
  }
  if (out.positions.empty())
    throw GeometryError(shape.file, fmt::format("the mesh has no {}D element ({}D bodies are made of {})", dimension,
                                                dimension, dimension == 3 ? "volume elements" : "surface elements"));
  out.exact = total.central(origin);
  return out;
}

}  // namespace mpm::geometry
