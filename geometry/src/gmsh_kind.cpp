// `gmsh: FILE` (2D, 3D; docs/scene-reference.md, bodies[].shape): the elements of a Gmsh .msh mesh (gmsh_body.cpp)
// become particles, one per element at its centroid with its volume; physical groups are chosen by name (`group`)
// or make one body each (`groups`). The file is read while the scene is (once per process), so that a group name the
// file does not define is reported at its line. Its region is the elements' bounding box (the grid check) with their
// exact volume and properties; its particles are its own.
#include <fmt/format.h>

#include <algorithm>

#include "known_properties.hpp"
#include "mpm/geometry/geometry_error.hpp"
#include "mpm/geometry/gmsh_body.hpp"
#include "mpm/scene/yaml_reader.hpp"
#include "shape_kinds.hpp"

namespace mpm::geometry {
namespace {
namespace gmsh {  // named: the library compiles in unity batches (cmake/unity_libraries.cmake)

const std::vector<io::KeySpec>& keys() {
  using io::KeyType;
  static const std::vector<io::KeySpec> k{
      {.name = "gmsh",
       .type = KeyType::name,
       .required = true,
       .description = "a Gmsh mesh `.msh` (ASCII, format 2.2 or 4.1), relative to the scene file's folder: every "
                      "element of the body's dimension (3D: tetrahedra, hexahedra, prisms; 2D: triangles, quadrangles "
                      "in the plane z = 0; first order) becomes one particle at its centroid with its volume"},
      {.name = "group",
       .type = KeyType::list,
       .absent = "all elements of the body's dimension",
       .description = "the elements of the physical groups with these names (of the body's dimension)",
       .type_text = "name, or list of names"},
      {.name = "groups",
       .type = KeyType::list,
       .absent = "one body",
       .description = "one body per physical group, named `<name>_<group>`, with the body's other keys (whole shape "
                      "only)",
       .type_text = "list of names"},
      {.name = "scale",
       .type = KeyType::number,
       .unit = "-",
       .range = io::Range::above(0),
       .default_value = 1.0,
       .description = "factor on the file's coordinates, which are in the scene's length unit (m, or that of "
                      "`units`; .msh files carry no unit): `1.0e-3` for a file in millimetres in an SI scene; applied "
                      "first"},
      {.name = "translation",
       .type = KeyType::list,
       .unit = "m",
       .absent = "none",
       .description = "added last",
       .type_text = "list of `dimension` numbers"},
  };
  return k;
}

/// Checks the choice against the file now, so that a wrong name is reported at its line.
void check_groups(const io::YamlReader& reader, const io::YamlValue& at, const GmshShape& gmsh, int dimension) {
  try {
    gmsh_particles(gmsh, dimension);
  } catch (const GeometryError& e) {
    reader.fail(at, e.what());
  }
}

std::vector<std::string> names_of(const io::YamlReader& reader, const io::YamlValue& value) {
  std::vector<std::string> names;
  if (!value.node.IsSequence()) return {reader.name(value)};
  const auto items = reader.list(value, std::nullopt, "group names");
  if (items.empty()) reader.fail(value, "expected at least one group name");
  names.reserve(items.size());
  for (const auto& item : items) names.push_back(reader.name(item));
  return names;
}

std::any parse(const io::YamlReader& reader, const io::YamlMap& map, const ShapeContext& context) {
  const io::YamlValue file = *map.find("gmsh");
  const int dimension = context.dimension;
  if (dimension == 1) reader.fail(file, "Gmsh bodies are available in 2D (triangles, quadrangles) and 3D");
  map.allow({"gmsh", "group", "groups", "scale", "translation"});
  GmshShape gmsh;
  gmsh.file = read_shape_file(reader, file, context.scene_file, {".msh"}, "Gmsh mesh");
  if (const auto scale = map.find("scale")) gmsh.scale = reader.number(*scale, io::Range::above(0), "");
  gmsh.scale *= reader.unit_system().length_unit();  // the file's coordinates are in the scene's length unit
  if (const auto translation = map.find("translation"))
    gmsh.translation = reader.vector(*translation, dimension, io::Range::any(), "m");
  if (const auto group = map.find("group")) {
    gmsh.groups = names_of(reader, *group);
    check_groups(reader, *group, gmsh, dimension);
  } else if (!map.find("groups")) {
    check_groups(reader, file, gmsh, dimension);
  }
  if (const auto groups = map.find("groups")) {
    if (map.find("group")) reader.fail(*groups, "give groups (one body each) or group, not both");
    if (!context.bodies || !context.whole_shape)
      reader.fail(*groups, "groups (one body per group) needs the mesh to be the whole shape of the body; use group");
    const auto items = reader.list(*groups, std::nullopt, "group names");
    if (items.empty()) reader.fail(*groups, "expected at least one group name");
    std::vector<std::string> names;
    for (const auto& item : items) {
      GmshShape one = gmsh;
      one.groups = {reader.name(item)};
      if (std::find(names.begin(), names.end(), one.groups.front()) != names.end())
        reader.fail(item, fmt::format("group '{}' is listed twice", one.groups.front()));
      check_groups(reader, item, one, dimension);
      names.push_back(one.groups.front());
      context.bodies->emplace_back(one.groups.front(), std::move(one));
    }
  }
  return gmsh;
}

std::string file_of(const std::any& spec) { return std::any_cast<const GmshShape&>(spec).file; }

/// The elements' bounding box and exact volume (and, in 3D, properties); no point is inside (the particles are the
/// kind's own).
template <int Dim>
class GmshRegion : public Region<Dim>, public detail::KnownProperties {
 public:
  explicit GmshRegion(GmshParticles particles) : particles_(std::move(particles)) {}
  bool contains(const Vec<Dim>&) const override { return false; }
  Box<Dim> bounds() const override { return {particles_.lo.head<Dim>(), particles_.hi.head<Dim>()}; }
  std::optional<Real> exact_volume() const override { return particles_.exact.volume; }
  MassProperties mass_properties() const override { return particles_.exact; }
  std::string properties_source() const override { return "volume mesh (exact element integrals)"; }

 private:
  GmshParticles particles_;
};

template <int Dim>
std::unique_ptr<Region<Dim>> region(const std::any& spec, std::vector<std::string>*) {
  return std::make_unique<GmshRegion<Dim>>(gmsh_particles(std::any_cast<const GmshShape&>(spec), Dim));
}

template <int Dim>
std::optional<ParticleSeeds<Dim>> fill(const std::any& spec, const GridGeometry<Dim>&) {
  GmshParticles particles = gmsh_particles(std::any_cast<const GmshShape&>(spec), Dim);
  ParticleSeeds<Dim> seeds;
  seeds.positions.reserve(particles.positions.size());
  for (const auto& x : particles.positions) seeds.positions.emplace_back(x.head<Dim>());
  seeds.volume = particles.exact.volume / static_cast<Real>(particles.volumes.size());  // the mean
  seeds.sub_cell_volume = seeds.volume;
  seeds.volumes = std::move(particles.volumes);
  return seeds;
}

std::optional<OwnParticleCount> own_count(const std::any& spec, int dimension) {
  return OwnParticleCount{
      static_cast<double>(gmsh_particles(std::any_cast<const GmshShape&>(spec), dimension).positions.size()), true};
}

}  // namespace gmsh
}  // namespace

ShapeKind gmsh_kind() {
  using namespace gmsh;
  ShapeKind k;
  k.name = "gmsh";
  k.noun = "a Gmsh mesh";
  k.description = "the elements of a Gmsh .msh volume mesh, one particle per element at its centroid with its volume";
  k.keyed = true;
  k.keys = keys();
  k.traits.dimensions = {false, true, true};
  k.traits.exact_volume = true;
  k.traits.exact_by_default = true;
  k.traits.not_operand = "a Gmsh mesh places its own particles (one per element)";
  k.traits.not_cpdi = "a Gmsh mesh's particles have no domains yet (one particle per element)";
  k.parse = parse;
  k.file = file_of;
  k.region_2d = region<2>;
  k.region_3d = region<3>;
  k.fill_2d = fill<2>;
  k.fill_3d = fill<3>;
  k.own_count = own_count;
  return k;
}

}  // namespace mpm::geometry
