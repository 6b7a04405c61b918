// ParticleSet copies (the stability guard's snapshots and roll-backs): every field, the on-demand ones
// included, is copied; fields the target has and the source lacks are dropped; a field of the same name
// and another type is replaced; and a copy into a set of the same shape reuses its storage.
#include <gtest/gtest.h>

#include <cstring>

#include "mpm/particles/particle_set.hpp"

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

namespace mpm {
namespace {

// ---- Every field as bytes (field_layout.hpp): what checkpoints and particle migration use ----

struct Pair {
  using scalar_type = Real;  // a struct of Reals: packed as 2 doubles
  Real a = 0, b = 0;
};

ParticleSet<2> three_particles_with_extras() {
  ParticleSet<2> p;
  for (int i = 0; i < 3; ++i) p.add(Vec<2>(0.1 * i, 0.2 * i), 1.0 + i, 0.01 * (i + 1));
  p.v[2] = VecU<2>(3, -4);
  p.F[1](0, 1) = 0.25;
  p.stress[0].c[3] = 7;
  p.add_field<Real>("temperature", 300)[1] = 450;
  p.add_field<int>("region", -1)[2] = 5;
  p.add_field<Pair>("pair", Pair{})[0] = Pair{1.5, -2.5};
  return p;
}

TEST(ParticleSetPacking, LayoutNamesEveryFieldWithItsScalarType) {
  const auto layout = three_particles_with_extras().field_layout();
  std::vector<std::string> names;
  for (const auto& f : layout) names.push_back(f.name);
  // the core fields in a fixed order, then the on-demand ones by name
  EXPECT_EQ(names, (std::vector<std::string>{"position", "velocity", "mass", "reference_volume", "deformation_gradient",
                                             "stress", "id", "pair", "region", "temperature"}));
  EXPECT_EQ(layout[0], (FieldLayout{"position", ScalarType::float64, 2}));
  EXPECT_EQ(layout[4], (FieldLayout{"deformation_gradient", ScalarType::float64, 4}));
  EXPECT_EQ(layout[5], (FieldLayout{"stress", ScalarType::float64, 4}));  // packed xx, yy, zz, xy
  EXPECT_EQ(layout[6], (FieldLayout{"id", ScalarType::uint32, 1}));
  EXPECT_EQ(layout[7], (FieldLayout{"pair", ScalarType::float64, 2}));
  EXPECT_EQ(layout[8], (FieldLayout{"region", ScalarType::int32, 1}));
}

TEST(ParticleSetPacking, PackFieldOfChosenParticlesThenUnpackRestoresThem) {
  const ParticleSet<2> p = three_particles_with_extras();
  const std::vector<Index> which{2, 0};
  std::vector<std::byte> bytes;
  p.pack_field("velocity", which, bytes);
  ASSERT_EQ(bytes.size(), 2 * 2 * sizeof(Real));
  Real v[4];
  std::memcpy(v, bytes.data(), sizeof v);
  EXPECT_EQ(v[0], 3);  // particle 2 first
  EXPECT_EQ(v[1], -4);
  EXPECT_EQ(v[2], 0);
  ParticleSet<2> q = three_particles_with_extras();
  q.unpack_field("velocity", 0, bytes);  // particles 0 and 1 get the velocities of 2 and 0
  EXPECT_EQ(q.v[0], VecU<2>(3, -4));
  EXPECT_EQ(q.v[1], VecU<2>(0, 0));
  std::vector<std::byte> pair;
  p.pack_field("pair", std::vector<Index>{0}, pair);
  q.unpack_field("pair", 2, pair);
  EXPECT_EQ(q.field<Pair>("pair")[2].b, -2.5);
  EXPECT_THROW(q.unpack_field("pair", 3, pair), std::out_of_range);                          // past the end
  EXPECT_THROW(q.unpack_field("pair", 0, std::span(pair).first(3)), std::invalid_argument);  // not whole
  EXPECT_THROW(p.pack_field("nothing", which, bytes), std::out_of_range);
}

TEST(ParticleSetPacking, PackedParticlesAppendToASetOfTheSameLayout) {
  // What a migration does: the leaving particles packed on one side, appended on the other.
  const ParticleSet<2> from = three_particles_with_extras();
  ParticleSet<2> to = three_particles_with_extras();
  std::vector<std::byte> bytes;
  from.pack(std::vector<Index>{1, 2}, bytes);
  std::size_t per_particle = 0;
  for (const auto& f : from.field_layout()) per_particle += f.bytes_per_particle();
  EXPECT_EQ(bytes.size(), 2 * per_particle);
  EXPECT_EQ(per_particle, from.bytes_per_particle());
  EXPECT_EQ(to.append_packed(bytes, 2), bytes.size());
  ASSERT_EQ(to.size(), 5);
  for (Index k = 0; k < 2; ++k) {
    const Index i = 1 + k, j = 3 + k;
    EXPECT_EQ(to.x[j], from.x[i]);
    EXPECT_EQ(to.v[j], from.v[i]);
    EXPECT_EQ(to.mass[j], from.mass[i]);
    EXPECT_EQ(to.volume0[j], from.volume0[i]);
    EXPECT_EQ(to.F[j], from.F[i]);
    EXPECT_EQ(to.stress[j].c[3], from.stress[i].c[3]);
    EXPECT_EQ(to.id[j], from.id[i]);
    EXPECT_EQ(to.field<Real>("temperature")[j], from.field<Real>("temperature")[i]);
    EXPECT_EQ(to.field<int>("region")[j], from.field<int>("region")[i]);
  }
  EXPECT_THROW(to.append_packed(std::span(bytes).first(10), 2), std::invalid_argument);
  EXPECT_EQ(to.size(), 5);  // unchanged by the refused append
}

}  // namespace
}  // namespace mpm
