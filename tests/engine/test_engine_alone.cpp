// The engine layer alone (libmpm/README.md, "Layers"): this program links mpm::engine and GoogleTest only, no
// scene reader and no writers (no yaml-cpp, no VTK), so that the build fails the day an engine source needs them.
// It builds a simulation through the engine's C++ interface — a body, a material law, a scheme class, no face
// conditions — and checks it against closed forms: an elastic block in free fall keeps zero stress and moves with
// v = g t after n steps of dt (t = n dt) and x = x0 + g dt^2 n (n + 1) / 2 (the position follows the updated
// velocity, symplectic Euler) to round-off: a uniform motion is exact in MUSL's transfers, every shape function
// reproducing constants (eq. 3.4); its momentum is M g t.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

#include "mpm/boundary/grid_boundary.hpp"
#include "mpm/materials/linear_elastic.hpp"
#include "mpm/materials/material_batch.hpp"
#include "mpm/schemes/musl.hpp"
#include "mpm/shape/linear_hat.hpp"
#include "mpm/simulation/simulation.hpp"

namespace {

using namespace mpm;

/// A 0.2 x 0.2 m soft elastic block (E = 20 MPa, so that the fixed dt = 1e-4 s is below its stable step, about
/// 7.6e-4 s: above it the round-off of sum grad N = 0 grows until the block flies apart) of 4 x 4 particles per cell
/// on a 1 m grid of 0.05 m cells, at rest, with gravity g = -9.81 m/s^2 along y; MUSL with linear hats, pure FLIP.
std::unique_ptr<Simulation<2>> falling_block() {
  const GridGeometry<2> geometry(Vec<2>::Zero(), Vec<2>::Constant(0.05), {20, 20});
  Body<2> block;
  block.name = "block";
  const auto soft = ElasticConstants::from_young_poisson(7800, 2e7, 0.3);
  block.material = std::make_shared<MaterialBatch<2, LinearElastic>>(soft);
  const Real spacing = 0.0125, volume = spacing * spacing;
  for (int i = 0; i < 16; ++i)
    for (int j = 0; j < 16; ++j)
      block.particles.add(Vec<2>(0.4 + (i + 0.5) * spacing, 0.6 + (j + 0.5) * spacing), soft.density * volume, volume);
  std::vector<Body<2>> bodies;
  bodies.push_back(std::move(block));
  SimulationSettings<2> settings;
  settings.transfer.gravity = Vec<2>(0, -9.81);
  settings.transfer.mass_cutoff = 1e-12;
  settings.fixed_dt = 1e-4;
  settings.end_time = 0.02;
  return std::make_unique<Simulation<2>>(geometry, std::move(bodies), std::make_unique<Musl<2, LinearHat>>(),
                                         GridBoundary<2>(), settings);
}

TEST(EngineAlone, AFallingBlockFollowsTheClosedForm) {
  auto sim = falling_block();
  const std::vector<VecU<2>> x0 = sim->bodies()[0].particles.x;
  sim->run();
  const Real t = sim->time(), g = -9.81, dt = 1e-4;
  ASSERT_NEAR(t, 0.02, 1e-12);
  const Real n = std::round(t / dt);
  const auto& p = sim->bodies()[0].particles;
  Real momentum = 0, mass = 0, largest_stress = 0;
  for (Index k = 0; k < p.size(); ++k) {
    EXPECT_NEAR(p.v[k][1], g * t, 1e-10) << "particle " << k;
    EXPECT_NEAR(p.v[k][0], 0, 1e-12) << "particle " << k;
    // by id: the simulation reorders the particles by cell every sort_interval steps
    EXPECT_NEAR(p.x[k][1] - x0[p.id[k]][1], 0.5 * g * dt * dt * n * (n + 1), 1e-10) << "particle " << p.id[k];
    momentum += p.mass[k] * p.v[k][1];
    mass += p.mass[k];
    largest_stress = std::max(largest_stress, p.stress[k].block().cwiseAbs().maxCoeff());
  }
  EXPECT_NEAR(momentum / (mass * g * t), 1, 1e-10);
  EXPECT_LT(largest_stress, 1e-6);  // Pa: a uniform motion strains nothing (round-off of a 2e7 Pa modulus)
}

}  // namespace
