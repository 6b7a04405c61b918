#pragma once
/// \file rigid_material.hpp
/// The material of rigid bodies (review §4.2.4 and §5.1.5, Alg. 4): no constitutive law. Its particles
/// keep zero stress and are skipped by the stress update; they only carry mass (used to find the contact
/// nodes and the rigid body's normals) and move with the velocity prescribed in the scene's `contact`
/// section (the contact module sets their nodal velocities).

#include <string_view>

#include "mpm/materials/material.hpp"

namespace mpm::contact {

template <int Dim>
class RigidMaterial final : public Material<Dim> {
 public:
  explicit RigidMaterial(Real density) : density_(density) {}
  std::string_view model() const override { return "rigid"; }
  Real density() const override { return density_; }
  /// Nothing to update: a rigid particle carries no stress and imposes no time-step bound.
  WaveSpeedBound<Dim> update_stress(ParticleSet<Dim>&, Index, Index, const MatU<Dim>*, Real) override { return {}; }
  WaveSpeedBound<Dim> wave_speed_bound(const ParticleSet<Dim>&) const override { return {}; }
  void add_strain_energy(const ParticleSet<Dim>&, ExactSum&) const override {}

 private:
  Real density_;
};

}  // namespace mpm::contact
