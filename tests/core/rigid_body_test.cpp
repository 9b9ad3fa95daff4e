#include "dymesh/core/rigid_body.h"

#include <gtest/gtest.h>

#include <cmath>

namespace dymesh {
namespace {

BodyModel Block() {
  BodyModel m;
  m.mass = 1500.0;
  m.inertia = Vec3(500.0, 2500.0, 2800.0).asDiagonal();
  return m;
}

TEST(RigidBody, ConstantForceGivesUniformAcceleration) {
  // v = F t / m exactly; semi-implicit Euler puts x within a t dt of a t^2 / 2
  const BodyModel m = Block();
  RigidState s;
  const Vec3 force(3000.0, -1500.0, 0.0);
  const double dt = 1e-3;
  for (int i = 0; i < 100; ++i) IntegrateRigidBody(m, MotionModel::kFree6Dof, force, Vec3::Zero(), dt, &s);
  const Vec3 a = force / m.mass;
  EXPECT_TRUE(s.velocity.isApprox(a * 0.1, 1e-12));
  EXPECT_NEAR(s.position.x(), 0.5 * a.x() * 0.01, a.x() * 0.1 * dt);
}

TEST(RigidBody, PlanarHoldsHeightRollAndPitch) {
  const BodyModel m = Block();
  RigidState s;
  s.velocity = Vec3(10, 0, 0);
  // a vertical force and roll/pitch moments do nothing; the yaw moment gives r' = Mz / Izz
  for (int i = 0; i < 10; ++i) {
    IntegrateRigidBody(m, MotionModel::kPlanar, Vec3(0, 0, 5e4), Vec3(1e4, 1e4, 2800.0), 1e-3, &s);
  }
  EXPECT_EQ(s.position.z(), 0.0);
  EXPECT_EQ(s.roll, 0.0);
  EXPECT_EQ(s.pitch, 0.0);
  EXPECT_NEAR(s.omega.z(), 1.0 * 0.01, 1e-12);
}

TEST(RigidBody, PlanarDropsRollAndPitchRatesItIsGiven) {
  // a host (or a C caller) may hand a planar body roll and pitch rates: they are dropped, the yaw
  // rate kept (before 2026-11-24 the body pitched at the rate it was given)
  const BodyModel m = Block();
  RigidState s;
  s.omega = Vec3(0.3, 0.5, 0.2);
  for (int i = 0; i < 10; ++i) IntegrateRigidBody(m, MotionModel::kPlanar, Vec3::Zero(), Vec3::Zero(), 1e-3, &s);
  EXPECT_EQ(s.roll, 0.0);
  EXPECT_EQ(s.pitch, 0.0);
  EXPECT_EQ(s.omega, Vec3(0.0, 0.0, 0.2));
  EXPECT_NEAR(s.yaw, 0.2 * 0.01, 1e-15);
}

TEST(RigidBody, TorqueFreeSpinAboutPrincipalAxisKeepsEnergy) {
  const BodyModel m = Block();
  RigidState s;
  s.omega = Vec3(0, 0, 2.0);
  const double before = KineticEnergy(m, s);
  EXPECT_DOUBLE_EQ(before, 0.5 * 2800.0 * 4.0);
  for (int i = 0; i < 1000; ++i) IntegrateRigidBody(m, MotionModel::kFree6Dof, Vec3::Zero(), Vec3::Zero(), 1e-3, &s);
  EXPECT_DOUBLE_EQ(KineticEnergy(m, s), before);
  EXPECT_NEAR(s.yaw, 2.0, 1e-12);  // one second at 2 rad/s
}

TEST(RigidBody, GravityGroundSupportHoldsTheBodyUp) {
  // weight against the ground spring: the CG settles 1 mm below its rest height (static deflection)
  const BodyModel m = Block();
  RigidState s;
  for (int i = 0; i < 2000; ++i) {
    const ExternalLoads loads = MotionModelLoads(MotionModel::kGravityGround, m, s, 0.0);
    IntegrateRigidBody(m, MotionModel::kGravityGround, loads.force_earth, loads.moment_body, 1e-4, &s);
  }
  EXPECT_NEAR(s.position.z(), 0.0, 1e-3 + 1e-5);
  EXPECT_NEAR(s.velocity.z(), 0.0, 1e-3);
}

TEST(RigidBody, FixedDoesNotMove) {
  const BodyModel m = Block();
  RigidState s;
  IntegrateRigidBody(m, MotionModel::kFixed, Vec3(1e6, 0, 0), Vec3(0, 0, 1e6), 1e-3, &s);
  EXPECT_EQ(s.position, Vec3::Zero());
  EXPECT_EQ(s.yaw, 0.0);
}

}  // namespace
}  // namespace dymesh
