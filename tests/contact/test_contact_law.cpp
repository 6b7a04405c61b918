// Unit tests of the nodal contact correction (contact/include/mpm/contact/contact_law.hpp), review §5.1:
// frictionless eq. 5.5 (Remark 31: normal component of v_cm, tangential unchanged), Coulomb eqs 5.6-5.8,
// and momentum conservation at a node shared by two bodies with equal and opposite normals.
#include <gtest/gtest.h>

#include "mpm/contact/contact_law.hpp"

namespace mpm::contact {
namespace {

TEST(ContactLaw, FrictionlessTakesTheNormalComponentOfTheCentreOfMass) {
  Vec<2> v(1.0, 0.5), v_cm(0.2, 0.0);
  const Vec<2> n(1.0, 0.0);
  ASSERT_TRUE(correct_velocity<2>(v, v_cm, n, 0.0));
  EXPECT_DOUBLE_EQ(v.dot(n), v_cm.dot(n));  // Remark 31
  EXPECT_DOUBLE_EQ(v[1], 0.5);              // tangential part unchanged
}

TEST(ContactLaw, ReleaseLeavesTheVelocity) {
  Vec<2> v(-1.0, 0.5);
  ASSERT_FALSE(correct_velocity<2>(v, Vec<2>(0.2, 0.0), Vec<2>(1.0, 0.0), 0.3));  // eq. 5.2: separating
  EXPECT_EQ(v, Vec<2>(-1.0, 0.5));
}

TEST(ContactLaw, CoulombSlipReducesTheTangentialVelocityByMuTimesTheNormalJump) {
  // dv = (1, 2): D = 1, slip |t| = 2 > mu D: sliding, tangential change mu D = 0.3 (eq. 5.8).
  Vec<2> v(1.0, 2.0);
  ASSERT_TRUE(correct_velocity<2>(v, Vec<2>::Zero(), Vec<2>(1.0, 0.0), 0.3));
  EXPECT_NEAR(v[0], 0.0, 1e-15);
  EXPECT_NEAR(v[1], 2.0 - 0.3, 1e-15);
}

TEST(ContactLaw, CoulombSticksWhenFrictionCanStopTheSlip) {
  // |t| / D = 0.5 < mu = 0.8: mu' = 0.5, full stick at v_cm (eq. 5.7).
  Vec<3> v(2.0, 1.0, 0.0);
  const Vec<3> v_cm(0.1, 0.2, 0.3);
  const Vec<3> n = Vec<3>(1.0, 0.0, 0.0);
  v += v_cm;
  ASSERT_TRUE(correct_velocity<3>(v, v_cm, n, 0.8));
  EXPECT_NEAR((v - v_cm).norm(), 0.0, 1e-15);
}

TEST(ContactLaw, EqualAndOppositeNormalsConserveMomentumWithFriction) {
  const Real m1 = 2.0, m2 = 3.0;
  Vec<2> v1(1.0, 0.7), v2(-0.5, -0.2);
  const Vec<2> v_cm = (m1 * v1 + m2 * v2) / (m1 + m2);  // eq. 5.3
  const Vec<2> p0 = m1 * v1 + m2 * v2;
  const Vec<2> n = Vec<2>(1.0, 0.3).normalized();
  ASSERT_TRUE(correct_velocity<2>(v1, v_cm, n, 0.25));
  ASSERT_TRUE(correct_velocity<2>(v2, v_cm, Vec<2>(-n), 0.25));
  EXPECT_NEAR((m1 * v1 + m2 * v2 - p0).norm(), 0.0, 1e-14);
  EXPECT_NEAR((v1 - v2).dot(n), 0.0, 1e-14);  // no interpenetration after the correction
}

}  // namespace
}  // namespace mpm::contact
