// `particles: FILE` (1D, 2D, 3D; docs/scene-reference.md, bodies[].shape): a body seeded from a particle file (.vtu
// or .csv): the particles' positions and volumes, and, when the file has them, their velocity, stress, mass and id.
// Its particles are its own (not the lattice's), so it is the whole shape of a body and gives no CPDI domains.
#include <fmt/format.h>

#include <cmath>
#include <set>

#include "kinds.hpp"
#include "mpm/io/particle_file.hpp"
#include "mpm/scene/yaml_reader.hpp"

namespace mpm::shapes {
namespace {
// The helpers are named in a namespace of this file's own, so that the folder's sources also compile as
// one translation unit (scripts/tidy.sh).
namespace particle_file {

const std::vector<io::KeySpec>& keys() {
  using io::KeyType;
  static const std::vector<io::KeySpec> k{
      {.name = "particles",
       .type = KeyType::name,
       .required = true,
       .description = "a `.vtu` or `.csv` particle file, relative to the scene file's folder (see below)"},
      {.name = "body",
       .type = KeyType::integer,
       .range = io::Range::at_least(0),
       .absent = "every row",
       .description = "only the rows whose field `body` has this value"},
  };
  return k;
}

std::any parse(const io::YamlReader& reader, const io::YamlMap& map, const ShapeContext& context) {
  const io::YamlValue file = *map.find("particles");
  map.allow({"particles", "body"});
  ParticleFileShape shape;
  shape.file = read_shape_file(reader, file, context.scene_file, {".vtu", ".csv"}, "particle");
  if (const auto body = map.find("body")) shape.body = reader.integer(*body, 0);
  return shape;
}

std::string file_of(const std::any& spec) { return std::any_cast<const ParticleFileShape&>(spec).file; }

/// The rows of the file (of the selected body). Throws ShapeError at the key `particles` naming the file (and the
/// row) for a file that cannot be read, a missing `volume`, a volume or mass that is not positive, a particle outside
/// the grid, ids that are not distinct whole numbers, or no particle of the selected `body`.
template <int Dim>
std::optional<ParticleSeeds<Dim>> fill(const std::any& spec, const GridGeometry<Dim>& grid) {
  const auto& shape = std::any_cast<const ParticleFileShape&>(spec);
  auto fail = [&](const std::string& message) { throw ShapeError("", message, "particles"); };
  io::ParticleFile file;
  try {
    file = io::read_particle_file(shape.file);
  } catch (const io::ParticleFileError& e) {
    fail(e.what());
  }
  const io::FieldArray* volume = file.field("volume");
  if (!volume || volume->components != 1)
    fail(shape.file +
         ": no scalar field 'volume' (the particle volume, m^3; m^2 in 2D): a particle file needs "
         "positions and volumes");
  const io::FieldArray* body = file.field("body");
  if (shape.body && !body)
    fail(shape.file + ": no field 'body' to select body " + std::to_string(*shape.body) + " from");
  const io::FieldArray* velocity = file.field("velocity");
  const io::FieldArray* stress = file.field("stress");
  const io::FieldArray* mass = file.field("mass");
  const io::FieldArray* id = file.field("id");
  if (velocity && velocity->components < Dim)
    fail(
        fmt::format("{}: 'velocity' has {} components, fewer than the {} axes", shape.file, velocity->components, Dim));
  if (stress && stress->components != 6 && stress->components != 9)
    fail(fmt::format("{}: 'stress' has {} components; expected 6 (xx, yy, zz, xy, yz, xz) or 9", shape.file,
                     stress->components));
  ParticleSeeds<Dim> seed;
  if (velocity) seed.velocity.emplace();
  if (stress) seed.stress.emplace();
  if (mass) seed.mass.emplace();
  if (id) seed.id.emplace();
  const Vec<Dim> upper = grid.upper();
  std::set<double> ids;
  for (std::size_t i = 0; i < file.cloud.size(); ++i) {
    if (shape.body && body->values[i * body->components] != *shape.body) continue;
    Vec<Dim> x;
    for (int d = 0; d < Dim; ++d) x[d] = file.cloud.points[3 * i + d];
    if ((x.array() < grid.origin.array()).any() || (x.array() > upper.array()).any())
      fail(fmt::format("{}: the particle lies outside the grid box", file.row(i)));
    const double V = volume->values[i];
    if (!(V > 0)) fail(fmt::format("{}: volume = {} is not > 0", file.row(i), V));
    seed.positions.push_back(x);
    seed.volumes.push_back(V);
    if (velocity) {
      VecU<Dim> v;
      for (int d = 0; d < Dim; ++d) v[d] = velocity->values[i * velocity->components + d];
      seed.velocity->push_back(v);
    }
    if (stress) {
      const double* s = stress->values.data() + i * stress->components;
      Mat3 m;
      if (stress->components == 6)
        m << s[0], s[3], s[5], s[3], s[1], s[4], s[5], s[4], s[2];
      else
        m << s[0], 0.5 * (s[1] + s[3]), 0.5 * (s[2] + s[6]), 0.5 * (s[1] + s[3]), s[4], 0.5 * (s[5] + s[7]),
            0.5 * (s[2] + s[6]), 0.5 * (s[5] + s[7]), s[8];
      seed.stress->push_back(SymTensor<Dim>::from(m));
    }
    if (mass) {
      const double m = mass->values[i];
      if (!(m > 0)) fail(fmt::format("{}: mass = {} is not > 0", file.row(i), m));
      seed.mass->push_back(m);
    }
    if (id) {
      const double k = id->values[i];
      if (k < 0 || k != std::floor(k) || k > 4294967295.0 || !ids.insert(k).second)
        fail(fmt::format("{}: id = {} is not a whole number distinct from the other particles' ids", file.row(i), k));
      seed.id->push_back(static_cast<std::uint32_t>(k));
    }
  }
  if (seed.positions.empty())
    fail(shape.body ? fmt::format("{}: no particle has body = {}", shape.file, *shape.body)
                    : shape.file + ": the file holds no particle");
  return seed;
}

std::optional<OwnParticleCount> own_count(const std::any&, int) { return OwnParticleCount{}; }

}  // namespace particle_file
}  // namespace

ShapeKind particle_file_kind() {
  using namespace particle_file;
  ShapeKind k;
  k.name = "particles";
  k.noun = "a particle file";
  k.description =
      "a particle set from a `.vtu` or `.csv` file: positions, volumes and optionally velocity, stress, "
      "mass and id";
  k.keyed = true;
  k.keys = keys();
  k.traits.not_operand =
      "a particle file is the whole shape of a body, not part of a union, intersection or difference";
  k.traits.not_cpdi = "a particle file gives no particle domains";
  k.parse = parse;
  k.file = file_of;
  k.fill_1d = fill<1>;
  k.fill_2d = fill<2>;
  k.fill_3d = fill<3>;
  k.own_count = own_count;
  return k;
}

}  // namespace mpm::shapes
