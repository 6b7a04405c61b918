// Set membership at t = 0 (sets/particle_sets.hpp).
#include "mpm/sets/particle_sets.hpp"

#include <algorithm>

#include "mpm/body_shape/shape_kind.hpp"
#include "mpm/core/expression.hpp"
#include "mpm/particles/field_keys.hpp"
#include "mpm/scene/scene_error.hpp"
#include "mpm/schemes/scheme_registry.hpp"
#include "mpm/sets/set_conditions.hpp"

namespace mpm {

int find_set(const SceneDescription& scene, const std::string& name) {
  for (std::size_t k = 0; k < scene.sets.size(); ++k)
    if (scene.sets[k].name == name) return static_cast<int>(k);
  return -1;
}

namespace {

bool takes_body(const SetDescription& set, int body) {
  return set.bodies.empty() || std::find(set.bodies.begin(), set.bodies.end(), body) != set.bodies.end();
}

bool takes_id(const SetDescription& set, std::uint32_t id) {
  if (set.ids.empty()) return true;
  return std::any_of(set.ids.begin(), set.ids.end(), [&](const auto& r) { return id >= r[0] && id <= r[1]; });
}

/// The particles of set `k` get the condition's initial velocity (expressions of x, y, z).
template <int Dim>
void set_initial_velocity(const SetConditionDescription& c, std::uint32_t mask, ParticleSet<Dim>& p) {
  std::array<std::optional<Expression>, 3> v;
  for (int d = 0; d < Dim; ++d)
    if (const auto& text = c.initial_velocity[static_cast<std::size_t>(d)])
      v[static_cast<std::size_t>(d)].emplace(*text, std::vector<std::string>{"x", "y", "z"});
  const auto& bits = p.field(keys::particle_sets);
  for (Index i = 0; i < p.size(); ++i) {
    if ((bits[static_cast<std::size_t>(i)] & mask) == 0) continue;
    Vec3 x = Vec3::Zero();
    x.template head<Dim>() = p.x[i];
    for (int d = 0; d < Dim; ++d)
      if (const auto& e = v[static_cast<std::size_t>(d)]) p.v[i][d] = (*e)(x[0], x[1], x[2], 0);
  }
}

/// The particles of the set get the condition's initial stress (expressions of x, y, z; the stress field's order).
template <int Dim>
void set_initial_stress(const SetConditionDescription& c, std::uint32_t mask, ParticleSet<Dim>& p) {
  constexpr auto components = static_cast<std::size_t>(SymTensor<Dim>::size);
  std::array<std::optional<Expression>, components> s;
  for (std::size_t k = 0; k < components; ++k)
    if (const auto& text = c.initial_stress[k]) s[k].emplace(*text, std::vector<std::string>{"x", "y", "z"});
  const auto& bits = p.field(keys::particle_sets);
  for (Index i = 0; i < p.size(); ++i) {
    if ((bits[static_cast<std::size_t>(i)] & mask) == 0) continue;
    Vec3 x = Vec3::Zero();
    x.template head<Dim>() = p.x[i];
    for (std::size_t k = 0; k < components; ++k)
      if (const auto& e = s[k]) p.stress[i].c[k] = (*e)(x[0], x[1], x[2], 0);
  }
}

}  // namespace

template <int Dim>
void mark_particle_sets(const SceneDescription& scene, Body<Dim>& body) {
  if (scene.sets.empty()) return;
  auto& p = body.particles;
  add_set_fields(scene, body);
  auto& bits = p.field(keys::particle_sets);
  for (std::size_t k = 0; k < scene.sets.size(); ++k) {
    const SetDescription& set = scene.sets[k];
    if (!takes_body(set, body.index)) continue;
    const std::unique_ptr<Region<Dim>> region = set.region ? make_shape_region<Dim>(*set.region) : nullptr;
    const std::uint32_t bit = set_bit(static_cast<int>(k));
    for (Index i = 0; i < p.size(); ++i)
      if (takes_id(set, p.id[static_cast<std::size_t>(i)]) && (!region || region->contains(p.x[i])))
        bits[static_cast<std::size_t>(i)] |= bit;
  }
  for (const auto& c : scene.conditions)
    if (std::any_of(c.initial_velocity.begin(), c.initial_velocity.end(), [](const auto& v) { return v.has_value(); }))
      set_initial_velocity(c, set_bit(c.set), p);
  for (const auto& c : scene.conditions)
    if (std::any_of(c.initial_stress.begin(), c.initial_stress.end(), [](const auto& s) { return s.has_value(); }))
      set_initial_stress(c, set_bit(c.set), p);
}

namespace {

template <std::size_t N>
bool any_given(const std::array<std::optional<std::string>, N>& components) {
  return std::any_of(components.begin(), components.end(), [](const auto& v) { return v.has_value(); });
}

std::vector<int> set_bodies(const SceneDescription& scene, int set) {
  std::vector<int> bodies = scene.sets[static_cast<std::size_t>(set)].bodies;
  if (bodies.empty())
    for (int b = 0; b < static_cast<int>(scene.bodies.size()); ++b) bodies.push_back(b);
  return bodies;
}

std::array<std::shared_ptr<Expression>, 3> expressions(const std::array<std::optional<std::string>, 3>& text,
                                                       const std::vector<std::string>& variables) {
  std::array<std::shared_ptr<Expression>, 3> out;
  for (std::size_t d = 0; d < 3; ++d)
    if (text[d]) out[d] = std::make_shared<Expression>(*text[d], variables);
  return out;
}

}  // namespace

template <int Dim>
void add_set_fields(const SceneDescription& scene, Body<Dim>& body) {
  if (scene.sets.empty()) return;
  body.particles.add_field(keys::particle_sets, std::uint32_t{0});
  for (const auto& c : scene.conditions) {
    if (!any_given(c.force)) continue;
    const auto bodies = set_bodies(scene, c.set);
    if (std::find(bodies.begin(), bodies.end(), body.index) != bodies.end())
      body.particles.add_field(keys::body_force<Dim>, VecU<Dim>::Zero());
  }
}

template <int Dim>
std::shared_ptr<Module<Dim>> scene_set_conditions(const SceneDescription& scene) {
  std::vector<HeldSet> held;
  std::vector<LoadedSet> loaded;
  const SchemeTraits& traits = scheme_of(scene.solver).traits;
  for (const auto& c : scene.conditions) {
    const bool holds = any_given(c.velocity), loads = any_given(c.force);
    if (!holds && !loads) continue;
    if (traits.unconditionally_stable)
      throw SceneError(c.where, c.path + (holds ? ".velocity" : ".force"),
                       "the scheme '" + scene.solver.scheme +
                           "' runs none of the grid-velocity stages and body forces through which conditions on "
                           "particle sets act; use an explicit scheme (musl, usf, usl, tlmpm)");
    const SetDescription& set = scene.sets[static_cast<std::size_t>(c.set)];
    if (holds)
      held.push_back({.name = set.name,
                      .mask = set_bit(c.set),
                      .bodies = set_bodies(scene, c.set),
                      .velocity = expressions(c.velocity, {"x", "y", "z", "t"})});
    if (loads)
      loaded.push_back(
          {.mask = set_bit(c.set), .bodies = set_bodies(scene, c.set), .force = expressions(c.force, {"t"})});
  }
  const Real pic_share = scene.solver.velocity_transfer == VelocityTransfer::flip ? 1 - scene.solver.flip_fraction : 1;
  return make_set_conditions<Dim>(std::move(held), std::move(loaded), scene.solver.shape_function,
                                  traits.total_lagrangian, pic_share);
}

template void add_set_fields<1>(const SceneDescription&, Body<1>&);
template void add_set_fields<2>(const SceneDescription&, Body<2>&);
template void add_set_fields<3>(const SceneDescription&, Body<3>&);
template std::shared_ptr<Module<1>> scene_set_conditions<1>(const SceneDescription&);
template std::shared_ptr<Module<2>> scene_set_conditions<2>(const SceneDescription&);
template std::shared_ptr<Module<3>> scene_set_conditions<3>(const SceneDescription&);
template void mark_particle_sets<1>(const SceneDescription&, Body<1>&);
template void mark_particle_sets<2>(const SceneDescription&, Body<2>&);
template void mark_particle_sets<3>(const SceneDescription&, Body<3>&);

}  // namespace mpm
