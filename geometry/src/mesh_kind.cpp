// `mesh: FILE` (2D, 3D; docs/scene-reference.md, bodies[].shape): a closed surface (.stl, .obj, .off, .ply) read
// with CGAL (mesh_region.cpp), transformed by scale, rotation and translation; in 2D its section by the plane
// z = section. Its volume (or section area) comes with the file, and `volume` defaults to it; `domains: conforming`
// meshes it.
#include <fmt/format.h>

#include <cctype>
#include <filesystem>

#include "mpm/geometry/mesh_region.hpp"
#include "mpm/scene/yaml_reader.hpp"
#include "shape_kinds.hpp"

namespace mpm::geometry {
namespace {
namespace mesh {  // named: the library compiles in unity batches (cmake/unity_libraries.cmake)

const std::vector<io::KeySpec>& keys() {
  using io::KeyType;
  static const std::vector<io::KeySpec> k{
      {.name = "mesh",
       .type = KeyType::name,
       .required = true,
       .description = "a closed triangle (or polygon) surface file: `.stl` (ASCII or binary), `.obj`, `.off` or "
                      "`.ply`, relative to the scene file's folder"},
      {.name = "scale",
       .type = KeyType::number,
       .unit = "-",
       .range = io::Range::above(0),
       .default_value = 1.0,
       .description = "factor on the file's coordinates, which are in the scene's length unit (m, or that of `units`): "
                      "`1.0e-3` for a file in millimetres in an SI scene; applied first"},
      {.name = "rotation",
       .type = KeyType::list,
       .unit = "degrees",
       .absent = "none",
       .description = "angles about x, then y, then z, applied after the scale",
       .type_text = "list of 3 numbers"},
      {.name = "translation",
       .type = KeyType::list,
       .unit = "m",
       .absent = "none",
       .description = "added last",
       .type_text = "list of 3 numbers"},
      {.name = "weld",
       .type = KeyType::number,
       .unit = "-",
       .range = io::Range::above(0),
       .absent = "off (only exactly repeated vertices are merged)",
       .description = "vertices closer than this (in the file's coordinates, before `scale`) are merged into their "
                      "mean before the checks, so that a surface whose triangles carry slightly different copies of "
                      "their shared corners is closed; keep it well below the smallest edge of the mesh"},
      {.name = "object",
       .type = KeyType::name,
       .absent = "all objects, one body",
       .description = "`.obj` only: the faces of the named object (`o NAME` line) alone; an unknown name is refused "
                      "with the file's names"},
      {.name = "shell",
       .type = KeyType::integer,
       .range = io::Range::at_least(0),
       .absent = "all shells, one body",
       .description = "the connected surface with this index alone, 0-based in the order of its first face in the "
                      "file (after `object`): one part of a file that holds several"},
      {.name = "section",
       .type = KeyType::number,
       .unit = "m",
       .absent = "required in 2D",
       .description = "2D only: the body is the cut of the (transformed) mesh by the plane z = `section`"},
  };
  return k;
}

std::any parse(const io::YamlReader& reader, const io::YamlMap& map, const ShapeContext& context) {
  const io::YamlValue file = *map.find("mesh");
  if (context.dimension == 1) reader.fail(file, "mesh bodies are available in 2D (a section of the mesh) and 3D");
  std::vector<std::string> allowed{"mesh", "scale", "rotation", "translation", "weld", "object", "shell"};
  if (context.dimension == 2) allowed.push_back("section");
  map.allow(allowed);
  MeshShape mesh;
  mesh.file = read_shape_file(reader, file, context.scene_file, {".stl", ".obj", ".off", ".ply"}, "mesh");
  if (const auto scale = map.find("scale")) mesh.scale = reader.number(*scale, io::Range::above(0), "");
  mesh.scale *= reader.unit_system().length_unit();  // the file's coordinates are in the scene's length unit
  if (const auto rotation = map.find("rotation"))
    mesh.rotation = reader.vector(*rotation, 3, io::Range::any(), "degrees");
  if (const auto translation = map.find("translation"))
    mesh.translation = reader.vector(*translation, 3, io::Range::any(), "m");
  if (const auto weld = map.find("weld")) mesh.weld = reader.number(*weld, io::Range::above(0), "");
  if (const auto object = map.find("object")) {
    mesh.object = reader.name(*object);
    std::string extension = std::filesystem::path(mesh.file).extension().string();
    for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (extension != ".obj")
      reader.fail(*object,
                  "object: only an .obj file names objects (`o NAME`); choose a separate surface of another "
                  "format with shell: INDEX");
  }
  if (const auto shell = map.find("shell")) mesh.shell = static_cast<std::size_t>(reader.integer(*shell, 0));
  if (context.dimension == 2)
    mesh.section = reader.number(
        map.required("section", "key", " (a 2D body is the section of the mesh by the plane z = section, m)"));
  return mesh;
}

std::string file_of(const std::any& spec) { return std::any_cast<const MeshShape&>(spec).file; }

std::unique_ptr<Region<2>> section(const std::any& spec, std::vector<std::string>* warnings) {
  return make_mesh_section(std::any_cast<const MeshShape&>(spec), warnings);
}

std::unique_ptr<Region<3>> solid(const std::any& spec, std::vector<std::string>* warnings) {
  return make_mesh_region(std::any_cast<const MeshShape&>(spec), warnings);
}

}  // namespace mesh
}  // namespace

ShapeKind mesh_kind() {
  using namespace mesh;
  ShapeKind k;
  k.name = "mesh";
  k.noun = "a mesh";
  k.description = "a closed surface mesh file (CGAL); in 2D its section by a plane z = const";
  k.keyed = true;
  k.keys = keys();
  k.traits.dimensions = {false, true, true};
  k.traits.exact_volume = true;
  k.traits.exact_by_default = true;
  k.traits.conforming_mesh = true;
  k.parse = parse;
  k.file = file_of;
  k.region_2d = section;
  k.region_3d = solid;
  return k;
}

}  // namespace mpm::geometry
