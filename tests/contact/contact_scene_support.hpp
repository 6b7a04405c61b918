#pragma once
// Helpers of the contact tests: scenes from YAML text with @KEY@ placeholders, the contact module of a
// built simulation, and centre-of-mass quantities of a body.
#include <gtest/gtest.h>

#include <string>

#include "../libmpm/scene_fixture.hpp"
#include "mpm/contact/multi_velocity_contact.hpp"

namespace mpm::test {

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
