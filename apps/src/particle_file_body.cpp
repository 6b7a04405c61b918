#include "particle_file_body.hpp"

#include <fmt/format.h>

#include <cmath>
#include <set>

#include "mpm/io/particle_file.hpp"
#include "mpm/scene/scene_error.hpp"

namespace mpm::app {
namespace {

std::string shape_key(int index) { return "bodies[" + std::to_string(index) + "].shape.particles"; }

}  // namespace

template <int Dim>
SeedParticles<Dim> read_seed_particles(const BodyDescription& bd, int index, const GridGeometry<Dim>& grid) {
  const auto& where = bd.shape.where;
  auto fail = [&](const std::string& message) {
    throw SceneError(where, shape_key(index), "body '" + bd.name + "': " + message);
  };
  io::ParticleFile file;
  try {
    file = io::read_particle_file(bd.shape.file);
  } catch (const io::ParticleFileError& e) {
    fail(e.what());
  }
  const io::FieldArray* volume = file.field("volume");
  if (!volume || volume->components != 1)
    fail(bd.shape.file +
         ": no scalar field 'volume' (the particle volume, m^3; m^2 in 2D): a particle file needs "
         "positions and volumes");
  const io::FieldArray* body = file.field("body");
  if (bd.shape.particle_body && !body)
    fail(bd.shape.file + ": no field 'body' to select body " + std::to_string(*bd.shape.particle_body) + " from");
  const io::FieldArray* velocity = file.field("velocity");
  const io::FieldArray* stress = file.field("stress");
  const io::FieldArray* mass = file.field("mass");
  const io::FieldArray* id = file.field("id");
  if (velocity && velocity->components < Dim)
    fail(fmt::format("{}: 'velocity' has {} components, fewer than the {} axes", bd.shape.file, velocity->components,
                     Dim));
  if (stress && stress->components != 6 && stress->components != 9)
    fail(fmt::format("{}: 'stress' has {} components; expected 6 (xx, yy, zz, xy, yz, xz) or 9", bd.shape.file,
                     stress->components));
  SeedParticles<Dim> seed;
  if (velocity) seed.velocity.emplace();
  if (stress) seed.stress.emplace();
  if (mass) seed.mass.emplace();
  if (id) seed.id.emplace();
  const Vec<Dim> upper = grid.upper();
  std::set<double> ids;
  for (std::size_t i = 0; i < file.cloud.size(); ++i) {
    if (bd.shape.particle_body && body->values[i * body->components] != *bd.shape.particle_body) continue;
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
    fail(bd.shape.particle_body ? fmt::format("{}: no particle has body = {}", bd.shape.file, *bd.shape.particle_body)
                                : bd.shape.file + ": the file holds no particle");
  return seed;
}

template <int Dim>
void apply_seed_state(Body<Dim>& body, const SeedParticles<Dim>& seed) {
  auto& p = body.particles;
  for (std::size_t i = 0; i < seed.positions.size(); ++i) {
    if (seed.velocity) p.v[i] = (*seed.velocity)[i];
    if (seed.stress) p.stress[i] = (*seed.stress)[i];
    if (seed.mass) p.mass[i] = (*seed.mass)[i];
    if (seed.id) p.id[i] = (*seed.id)[i];
  }
}

template SeedParticles<1> read_seed_particles<1>(const BodyDescription&, int, const GridGeometry<1>&);
template SeedParticles<2> read_seed_particles<2>(const BodyDescription&, int, const GridGeometry<2>&);
template SeedParticles<3> read_seed_particles<3>(const BodyDescription&, int, const GridGeometry<3>&);
template void apply_seed_state<1>(Body<1>&, const SeedParticles<1>&);
template void apply_seed_state<2>(Body<2>&, const SeedParticles<2>&);
template void apply_seed_state<3>(Body<3>&, const SeedParticles<3>&);

}  // namespace mpm::app
