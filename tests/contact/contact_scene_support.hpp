#pragma once
// Helpers of the contact tests: scenes from YAML text with @KEY@ placeholders, the contact module of a
// built simulation, and centre-of-mass quantities of a body.
#include <gtest/gtest.h>

#include <string>

#include "../libmpm/scene_fixture.hpp"
#include "mpm/contact/multi_velocity_contact.hpp"

namespace mpm::test {

/// The two elastic disks of review §6.1.2 with the contact module: @SCHEME@ (may carry more solver keys, e.g.
/// "musl, velocity_transfer: apic"), @SHAPE@, @ONSET@, @MU@ (friction), @NORMALS@.
inline const std::string two_disks_scene = R"(
dimension: 2
grid: {origin: [0, 0], extent: [1, 1], cell_size: 0.05}
materials:
  elastic: {model: linear_elastic, density: 1000, youngs_modulus: 1000, poisson_ratio: 0.3}
bodies:
  - {name: lower_left, material: elastic, shape: {type: disk, center: [0.2, 0.2], radius: 0.2},
     particles_per_cell: 2, velocity: [0.1, 0.1]}
  - {name: upper_right, material: elastic, shape: {type: disk, center: [0.8, 0.8], radius: 0.2},
     particles_per_cell: 2, velocity: [-0.1, -0.1]}
solver: {scheme: @SCHEME@, shape_function: @SHAPE@, dt: 0.001, end_time: 3.5}
contact: {onset: @ONSET@, friction: @MU@, normals: @NORMALS@}
)";

/// `scheme` (the value of @SCHEME@, which may carry more solver keys) with the papers' transfer, pure FLIP, unless
/// it gives one: a scene with contact otherwise takes APIC (contact/README.md, "Defaults").
inline std::string with_paper_transfer(const std::string& scheme) {
  return scheme.find("velocity_transfer") == std::string::npos ? scheme + ", velocity_transfer: flip" : scheme;
}

template <int Dim>
contact::MultiVelocityContact<Dim>* contact_module(Simulation<Dim>& sim) {
  for (const auto& m : sim.modules())
    if (auto* c = dynamic_cast<contact::MultiVelocityContact<Dim>*>(m.get())) return c;
  return nullptr;
}

/// Mass-weighted mean velocity of a body.
template <int Dim>
Vec<Dim> body_velocity(const Body<Dim>& body) {
  Vec<Dim> mv = Vec<Dim>::Zero();
  Real m = 0;
  for (Index i = 0; i < body.particles.size(); ++i) {
    mv += body.particles.mass[i] * Vec<Dim>(body.particles.v[i]);
    m += body.particles.mass[i];
  }
  return mv / m;
}

/// Least-squares slope of y(t).
inline double slope(const std::vector<double>& t, const std::vector<double>& y) {
  double st = 0, sy = 0, stt = 0, sty = 0;
  const double n = static_cast<double>(t.size());
  for (std::size_t i = 0; i < t.size(); ++i) st += t[i], sy += y[i], stt += t[i] * t[i], sty += t[i] * y[i];
  return (n * sty - st * sy) / (n * stt - st * st);
}

}  // namespace mpm::test
