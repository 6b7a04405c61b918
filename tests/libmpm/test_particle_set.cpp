// ParticleSet copies (the stability guard's snapshots and roll-backs): every field, the on-demand ones
// included, is copied; fields the target has and the source lacks are dropped; a field of the same name
// and another type is replaced; and a copy into a set of the same shape reuses its storage.
#include <gtest/gtest.h>

#include "mpm/particle_set.hpp"

namespace mpm {
namespace {

ParticleSet<2> two_particles() {
  ParticleSet<2> p;
  p.add(Vec<2>(0.1, 0.2), 1.5, 0.01);
  p.add(Vec<2>(0.3, 0.4), 2.5, 0.02);
  p.v[1] = VecU<2>(3, -4);
  p.stress[0].c[3] = 7;
  p.add_field<Real>("temperature", 300)[1] = 450;
  return p;
}

TEST(ParticleSet, CopyAssignmentCopiesEveryField) {
  const ParticleSet<2> source = two_particles();
  ParticleSet<2> target;
  target.add(Vec<2>(9, 9), 1, 1);
  target.add_field<int>("stale", 4);
  target.add_field<int>("temperature", 1);  // same name, another type
  target = source;
  ASSERT_EQ(target.size(), 2);
  EXPECT_EQ(target.x[1], source.x[1]);
  EXPECT_EQ(target.v[1], source.v[1]);
  EXPECT_EQ(target.mass[1], 2.5);
  EXPECT_EQ(target.stress[0].c[3], 7);
  EXPECT_FALSE(target.has_field("stale"));
  EXPECT_EQ(target.field<Real>("temperature")[1], 450);
  target.add(Vec<2>(0, 0), 1, 1);  // the copied field keeps its initial value for new particles
  EXPECT_EQ(target.field<Real>("temperature")[2], 300);
}

TEST(ParticleSet, CopyIntoSameShapeReusesStorage) {
  ParticleSet<2> source = two_particles();
  ParticleSet<2> snapshot = source;
  const Real* x_storage = &snapshot.x[0][0];
  const Real* temperature_storage = snapshot.field<Real>("temperature").data();
  source.field<Real>("temperature")[0] = 77;
  source.x[0] = VecU<2>(5, 6);
  snapshot = source;
  EXPECT_EQ(&snapshot.x[0][0], x_storage);
  EXPECT_EQ(snapshot.field<Real>("temperature").data(), temperature_storage);
  EXPECT_EQ(snapshot.field<Real>("temperature")[0], 77);
  EXPECT_EQ(snapshot.x[0], VecU<2>(5, 6));
}

}  // namespace
}  // namespace mpm
