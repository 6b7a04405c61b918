// The surface meshes a process has read, kept: a scene's mesh is asked for by the memory estimate, the lattice fill,
// the conforming domains and the fidelity certificate, and `mpm particles` asks for its region before filling it;
// each used to read and check the file again (a 1M-triangle STL takes seconds), and each repeated the warnings of its
// repairs. The inside test is kept with the mesh, so that its AABB tree too is built once. An entry is keyed by the
// file's content (its bytes hashed), not its name or time, so a file rewritten in place is read again, and by every key
// of the shape that changes the mesh.
#include <fmt/format.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>

#include "surface_mesh_io.hpp"

namespace mpm::geometry::detail {

namespace {

/// FNV-1a over the file's bytes (about 1 GB/s: 50 ms for a 1M-triangle binary STL), or 0 when it cannot be read.
std::uint64_t mesh_file_hash(const std::string& file) {
  std::ifstream in(file, std::ios::binary);
  std::uint64_t hash = 1469598103934665603ull;
  std::vector<char> buffer(1 << 16);
  while (in) {
    in.read(buffer.data(), static_cast<std::streamsize>(buffer.size()));
    for (std::streamsize k = 0; k < in.gcount(); ++k)
      hash = (hash ^ static_cast<unsigned char>(buffer[static_cast<std::size_t>(k)])) * 1099511628211ull;
  }
  return hash;
}

/// Everything the mesh depends on: the content and the shape's keys that act on it (hexadecimal floats: exact).
std::string mesh_cache_key(const MeshShape& shape) {
  return fmt::format("{}|{:x}|{:a}|{:a},{:a},{:a}|{:a},{:a},{:a}|{}|{}|{}", shape.file, mesh_file_hash(shape.file),
                     shape.scale, shape.rotation[0], shape.rotation[1], shape.rotation[2], shape.translation[0],
                     shape.translation[1], shape.translation[2], shape.weld ? fmt::format("{:a}", *shape.weld) : "-",
                     shape.object ? "o" + *shape.object : "-", shape.shell ? std::to_string(*shape.shell) : "-");
}

struct CachedSurfaceMesh {
  ClosedSurface surface;
  std::vector<std::string> warnings;  ///< of its repairs: given to every caller, who prints each once
};

}  // namespace

ClosedSurface ClosedSurface::of(SurfaceMesh mesh) {
  ClosedSurface surface;
  surface.mesh = std::make_shared<const SurfaceMesh>(std::move(mesh));
  surface.inside = std::make_shared<const InsideTest>(*surface.mesh);
  return surface;
}

ClosedSurface shared_surface_mesh(const MeshShape& shape, std::vector<std::string>* warnings) {
  static std::mutex mutex;
  static std::map<std::string, CachedSurfaceMesh> meshes;
  std::error_code error;
  if (!std::filesystem::is_regular_file(shape.file, error))  // not found, a folder: the reader's messages
    return ClosedSurface::of(load_surface_mesh(shape, warnings));
  const std::string key = mesh_cache_key(shape);
  const std::scoped_lock lock(mutex);
  auto found = meshes.find(key);
  if (found == meshes.end()) {  // a bad mesh throws here and is not kept
    CachedSurfaceMesh entry;
    entry.surface = ClosedSurface::of(load_surface_mesh(shape, &entry.warnings));
    found = meshes.emplace(key, std::move(entry)).first;
  }
  if (warnings) warnings->insert(warnings->end(), found->second.warnings.begin(), found->second.warnings.end());
  return found->second.surface;
}

}  // namespace mpm::geometry::detail
