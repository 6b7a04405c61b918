// The batched plastic material (plastic_batch.hpp) runs whole packs of particles through the vector form
// of the point law (lanes.hpp), the last one padded. It must give the scalar law's result: here 2 packs + 3
// particles, each with its own random velocity-gradient history (stretch, shear
// and spin), every option of the law switched on (Johnson-Cook flow with rate and thermal softening,
// Mie-Gruneisen EOS, damage to failure, adiabatic heating, thermal expansion, artificial viscosity), in
// 1D, 2D and 3D, are stepped through PlasticBatch::update_stress and, particle by particle, through
// Elastoplastic::update_point. Reference: the scalar law itself; tolerance 1e-9 of the stress scale and
// of each history variable (the packs use Eigen's vector log, exp and square root, exact to about 1 ulp,
// and the steps add up a few hundred of them).
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <random>

#include "mpm/plasticity/plastic_batch.hpp"

namespace mpm::plasticity {
namespace {

using Shock = Elastoplastic<JohnsonCookFlow, MieGruneisenEos>;
using Voce = Elastoplastic<HardeningFlow, LinearEos>;

/// Weldox-like steel with every option on: damage starts at a few percent of plastic strain so that
/// some particles fail within the run.
Shock::Params everything_on() {
  Shock::Params c;
  c.density = 7850;
  c.shear_modulus = 80e9;
  c.bulk_modulus = 160e9;
  c.flow = {490e6, 383e6, 0.45, 0.0123, 0.94};
  c.eos = {7850, 4570, 1.49, 1.93};
  c.damage_enabled = true;
  c.damage = {0.02, 0.5, -1.5, 0.002, 0.6, 10};
  c.thermal = true;
  c.softening = true;
  c.specific_heat = 452;
  c.melting_temperature = 1800;
  c.thermal_expansion = 1.2e-5;
  c.viscosity_linear = 0.06;
  c.viscosity_quadratic = 1.2;
  return c;
}

Voce::Params voce() {
  Voce::Params c;
  c.density = 2700;
  c.shear_modulus = 26e9;
  c.bulk_modulus = 68e9;
  c.eos.bulk_modulus = 68e9;
  c.flow = {300e6, 0, 120e6, 15};
  return c;
}

template <int Dim, class Model>
void check_batch_matches_scalar(const typename Model::Params& c, Real rate, int steps, unsigned seed) {
  constexpr int n = 2 * lane_count + 3;
  PlasticBatch<Dim, Model> batch("test", c);
  ParticleSet<Dim> p;
  for (int i = 0; i < n; ++i) p.add(Vec<Dim>::Zero(), 1, 1e-9);
  batch.prepare_particles(p);
  ParticleSet<Dim> ref = p;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<Real> u(-1, 1);
  std::vector<Mat<Dim>> L0(n);
  for (auto& L : L0)
    for (int k = 0; k < Dim * Dim; ++k) L.data()[k] = rate * u(rng);
  std::vector<MatU<Dim>> L(n);
  const Real dt = 2e-5 / rate;  // rotation steps well below the Newton tolerance (no borderline iteration counts)
  for (int s = 0; s < steps; ++s) {
    for (int i = 0; i < n; ++i) {
      // a slowly turning gradient: the principal directions and the spin change along the path
      const Real phase = 0.002 * s + i;
      L[i] = L0[i] * std::cos(phase) + L0[(i + 1) % n] * std::sin(phase);
      p.F[i] = (Mat<Dim>::Identity() + dt * Mat<Dim>(L[i])) * Mat<Dim>(p.F[i]);
      ref.F[i] = p.F[i];
    }
    batch.update_stress(p, 0, n, L.data(), dt);
    auto& state = ref.template field<PlasticState<Dim>>("plasticity");
    Real* temperature = c.thermal ? ref.template field<Real>("temperature").data() : nullptr;
    for (int i = 0; i < n; ++i) {
      const Mat<Dim> F = ref.F[i];
      const Real J = F.determinant();
      Model::template update_point<Dim>(c, F, Mat<Dim>(L[i]), J, dt, ref.volume0[i] * J, state[i],
                                        temperature ? temperature + i : nullptr, ref.stress[i]);
    }
  }
  const auto& got = p.template field<PlasticState<Dim>>("plasticity");
  const auto& want = ref.template field<PlasticState<Dim>>("plasticity");
  Real stress_scale = 0, max_strain = 0, max_damage = 0;
  for (int i = 0; i < n; ++i) {
    for (Real v : ref.stress[i].c) stress_scale = std::max(stress_scale, std::abs(v));
    max_strain = std::max(max_strain, want[i].plastic_strain);
    max_damage = std::max(max_damage, want[i].damage);
  }
  for (int i = 0; i < n; ++i) {
    for (int k = 0; k < SymTensor<Dim>::size; ++k)
      EXPECT_NEAR(p.stress[i].c[k], ref.stress[i].c[k], 1e-9 * stress_scale) << "particle " << i << " component " << k;
    EXPECT_NEAR(got[i].plastic_strain, want[i].plastic_strain, 1e-9 * (1 + want[i].plastic_strain)) << i;
    EXPECT_NEAR(got[i].damage, want[i].damage, 1e-9) << i;
    EXPECT_NEAR(got[i].damage_initiation, want[i].damage_initiation, 1e-9 * (1 + want[i].damage_initiation)) << i;
    EXPECT_NEAR(got[i].plastic_work, want[i].plastic_work, 1e-9 * (1 + want[i].plastic_work)) << i;
    if (c.thermal) {
      EXPECT_NEAR(p.template field<Real>("temperature")[i], ref.template field<Real>("temperature")[i], 1e-9 * 300)
          << i;
    }
  }
  // the run exercised the law: plastic flow everywhere it was asked for
  EXPECT_GT(max_strain, 0.02);
  ::testing::Test::RecordProperty("max_plastic_strain", std::to_string(max_strain));
  ::testing::Test::RecordProperty("max_damage", std::to_string(max_damage));
}

TEST(PlasticityLanes, Batch3DMatchesScalarLaw) {
  check_batch_matches_scalar<3, Shock>(everything_on(), 1e4, 6000, 1);
  check_batch_matches_scalar<3, Voce>(voce(), 1e3, 6000, 2);
}
TEST(PlasticityLanes, Batch2DMatchesScalarLaw) { check_batch_matches_scalar<2, Shock>(everything_on(), 1e4, 6000, 3); }
TEST(PlasticityLanes, Batch1DMatchesScalarLaw) { check_batch_matches_scalar<1, Shock>(everything_on(), 1e4, 6000, 4); }

// Damage to failure happens inside a pack: with the steel above, some lanes fail while others still
// flow, and the failed ones keep no deviatoric stress (docs/errata.md #28), in the pack as in the scalar law.
TEST(PlasticityLanes, FailedLanesInsideAPack) {
  Shock::Params c = everything_on();
  c.thermal_expansion = 0;  // no pressure from heating: triaxiality near 0, failure near 0.55 plastic strain
  c.eos.gruneisen_gamma = 0;
  PlasticBatch<3, Shock> batch("test", c);
  ParticleSet<3> p;
  for (int i = 0; i < lane_count; ++i) p.add(Vec<3>::Zero(), 1, 1e-9);
  batch.prepare_particles(p);
  std::vector<MatU<3>> L(lane_count, MatU<3>::Zero());
  const Real dt = 1e-7;
  for (int s = 0; s < 4000; ++s) {
    for (int i = 0; i < lane_count; ++i) {
      const Real rate = 250 * (i + 1);  // lane i stretches at (i + 1) x 250 /s
      L[i] = Vec3(rate, -0.5 * rate, -0.5 * rate).asDiagonal();
      p.F[i] = (Mat3::Identity() + dt * Mat3(L[i])) * Mat3(p.F[i]);
    }
    batch.update_stress(p, 0, lane_count, L.data(), dt);
  }
  const auto& st = p.field<PlasticState<3>>("plasticity");
  int failed = 0;
  for (int i = 0; i < lane_count; ++i) {
    if (st[i].damage < 1) continue;
    ++failed;
    const Mat3 s = p.stress[i].full();
    const Mat3 dev = s - s.trace() / 3 * Mat3::Identity();
    EXPECT_LT(dev.norm(), 1e-6) << "lane " << i;
  }
  EXPECT_GT(failed, 0);
  EXPECT_LT(failed, lane_count);
}

// A lane whose rotation jumps by nearly pi in one step defeats the warm-started Newton iterations; that
// lane falls back to the closed form, like the scalar law, while the others keep their Newton result.
TEST(PlasticityLanes, PolarFallbackPerLane) {
  Pack F[3][3], q[4];
  Real F_lane[lane_count][3][3];
  for (int l = 0; l < lane_count; ++l) {
    const Real angle = l == 3 ? 3.1 : 0.01 * l;
    const Mat3 R = Eigen::AngleAxisd(angle, Vec3(1, -2, 0.5).normalized()).toRotationMatrix();
    const Mat3 Fl = R * Vec3(1.2, 0.9, 1.05).asDiagonal();
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) F[i][j][l] = F_lane[l][i][j] = Fl(i, j);
  }
  for (int k = 0; k < 4; ++k) q[k] = Pack::Constant(k == 0 ? 1.0 : 0.0);
  polar_update_warm(F, q);
  for (int l = 0; l < lane_count; ++l) {
    Real ql[4] = {1, 0, 0, 0};
    polar_update_warm(F_lane[l], ql);
    Mat3 Fl;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) Fl(i, j) = F_lane[l][i][j];
    const Real qp[4] = {q[0][l], q[1][l], q[2][l], q[3][l]};
    EXPECT_LT((rotation_of(qp) - rotation_of(ql)).norm(), 1e-12) << "lane " << l;
    EXPECT_LT((rotation_of(qp) - polar_rotation(Fl)).norm(), 1e-6) << "lane " << l;
  }
}

// Every particle runs the vector law, and a lane's result depends on its own particle only: however TBB splits
// the particles into blocks (which depends on the thread count and on timing) and wherever a particle is
// stored (sorting; later the rank it migrated to), its update is the same bits (docs/distributed.md §1). Here
// the whole set in one block, the same set in blocks that cut packs (13 and 29 are not multiples of
// lane_count), and the set stored rotated by 3 (every particle in another lane, the last ones in full packs,
// others in the padded one) give equal bytes after many steps with damage and heating on (the scalar law
// differs from the vector law in round-off, and pack-mates differ, so any dependence would show).
TEST(PlasticityLanes, ResultDoesNotDependOnTheBlocks) {
  constexpr int n = 4 * lane_count + 5;
  const Shock::Params c = everything_on();
  PlasticBatch<3, Shock> batch("test", c);
  ParticleSet<3> whole;
  for (int i = 0; i < n; ++i) whole.add(Vec<3>::Zero(), 1, 1e-9);
  batch.prepare_particles(whole);
  ParticleSet<3> split = whole, rotated = whole;
  constexpr int shift = 3;  // particle i of `whole` is particle (i + shift) % n of `rotated`
  std::mt19937 rng(7);
  std::uniform_real_distribution<Real> u(-1, 1);
  std::vector<MatU<3>> L(n), L_rotated(n);
  for (auto& l : L)
    for (int k = 0; k < 9; ++k) l.data()[k] = 1e4 * u(rng);
  for (int i = 0; i < n; ++i) L_rotated[(i + shift) % n] = L[i];
  const Real dt = 2e-9;
  for (int step = 0; step < 500; ++step) {
    for (int i = 0; i < n; ++i)
      whole.F[i] = split.F[i] = rotated.F[(i + shift) % n] = (Mat3::Identity() + dt * Mat3(L[i])) * Mat3(whole.F[i]);
    batch.update_stress(whole, 0, n, L.data(), dt);
    batch.update_stress(rotated, 0, n, L_rotated.data(), dt);
    for (const auto& [begin, end] : {std::pair{0, 13}, std::pair{13, 29}, std::pair{29, n}})
      batch.update_stress(split, begin, end, L.data() + begin, dt);
  }
  const auto& a = whole.field<PlasticState<3>>("plasticity");
  const auto& b = split.field<PlasticState<3>>("plasticity");
  const auto& r = rotated.field<PlasticState<3>>("plasticity");
  Real max_strain = 0;
  for (int i = 0; i < n; ++i) {
    for (int k = 0; k < 6; ++k) EXPECT_EQ(whole.stress[i].c[k], split.stress[i].c[k]) << "particle " << i;
    EXPECT_EQ(a[i].plastic_strain, b[i].plastic_strain) << i;
    EXPECT_EQ(a[i].damage, b[i].damage) << i;
    EXPECT_EQ(whole.field<Real>("temperature")[i], split.field<Real>("temperature")[i]) << i;
    const int j = (i + shift) % n;
    for (int k = 0; k < 6; ++k) EXPECT_EQ(whole.stress[i].c[k], rotated.stress[j].c[k]) << "particle " << i;
    EXPECT_EQ(a[i].plastic_strain, r[j].plastic_strain) << i;
    EXPECT_EQ(a[i].damage, r[j].damage) << i;
    EXPECT_EQ(whole.field<Real>("temperature")[i], rotated.field<Real>("temperature")[j]) << i;
    max_strain = std::max(max_strain, a[i].plastic_strain);
  }
  EXPECT_GT(max_strain, 0.01);  // the law did flow
}

}  // namespace
}  // namespace mpm::plasticity
