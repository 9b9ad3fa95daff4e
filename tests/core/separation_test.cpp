// The free-motion forecast of the stop at separation (core/separation.h) against closed forms: a
// translation closes a gap at the relative speed; a rod turning beside a wall reaches it when its
// half-extent toward the wall, (L/2) sin(wt) + (w/2) cos(wt), equals the distance; an interlocked
// corner may go `deepening` deeper; a body free to roll and pitch departs from its outline posed by
// its yaw alone at most at its wobble speed.
#include "dymesh/core/separation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "dymesh/core/mesh.h"

namespace dymesh {
namespace {

// a box body of length (x) by width (y), 1 m high, at (x, y) heading 0, with velocity and yaw rate
BodyState Box(double length, double width, double x, double y, const Vec3& velocity = Vec3::Zero(), double yaw_rate = 0.0) {
  BodyState s;
  s.vertices = MakeBox(length, width, 1.0, 2, 2, 2).vertices;
  s.rigid.position = Vec3(x, y, 0.0);
  s.rigid.velocity = velocity;
  s.rigid.omega = Vec3(0.0, 0.0, yaw_rate);
  return s;
}

// a wall 100 m long (x), 1 m thick, whose face toward -y is at y = face
BodyState Wall(double face) { return Box(100.0, 1.0, 0.0, face + 0.5); }

// the forecast for two bodies as they are now
double Meeting(const BodyState& a, const BodyState& b, double horizon, double deepening) {
  return SoonestMeeting(PlanMotionOf(a), PlanMotionOf(b), horizon, deepening);
}

TEST(SoonestMeeting, ATranslationClosesTheGapAtTheRelativeSpeed) {
  // 2 x 2 m squares 3 m apart, the second coming at 1 m/s: they meet at 3 s (one advancement step,
  // exact); within a shorter horizon, or moving apart or alongside, never
  const BodyState a = Box(2, 2, 0, 0), b = Box(2, 2, 5, 0, Vec3(-1, 0, 0));
  EXPECT_NEAR(Meeting(a, b, 10.0, 0.1), 3.0, 1e-12);
  EXPECT_EQ(Meeting(a, b, 2.9, 0.1), INFINITY);
  EXPECT_EQ(Meeting(a, Box(2, 2, 5, 0, Vec3(1, 0, 0)), 10.0, 0.1), INFINITY);
  EXPECT_EQ(Meeting(a, Box(2, 2, 0, 3, Vec3(5, 0, 0)), 10.0, 0.1), INFINITY);
}

TEST(SoonestMeeting, ARodTurningBesideAWallReachesItWhenItsHalfExtentDoes) {
  // a 4 x 0.2 m rod along the wall, its CG 1.5 m from the face, turning at 1 rad/s: it reaches the
  // face at the angle where 2 sin(a) + 0.1 cos(a) = 1.5 (bisection), at a / w
  const double length = 4.0, width = 0.2, distance = 1.5, rate = 1.0;
  double lo = 0.0, hi = 0.5 * M_PI;
  for (int i = 0; i < 100; ++i) {
    const double mid = 0.5 * (lo + hi);
    (0.5 * length * std::sin(mid) + 0.5 * width * std::cos(mid) < distance ? lo : hi) = mid;
  }
  const double meet = lo / rate;
  const double forecast = Meeting(Box(length, width, 0, 0, Vec3::Zero(), rate), Wall(distance), 5.0, 0.1);
  // conservative (never after the meeting, to round-off) and converged: the corner closes at 1.3 m/s
  // against the 2 m/s bound, so each pose takes a third of the margin left
  EXPECT_LE(forecast, meet + 1e-12);
  EXPECT_NEAR(forecast, meet, 1e-9);
  // the same turn the other way, and the rod listed second
  EXPECT_NEAR(Meeting(Wall(distance), Box(length, width, 0, 0, Vec3::Zero(), -rate), 5.0, 0.1), meet, 1e-9);
  EXPECT_EQ(Meeting(Box(length, width, 0, 0, Vec3::Zero(), rate), Wall(distance), 0.9 * meet, 0.1), INFINITY);
}

TEST(SoonestMeeting, AnInterlockedCornerMayGoOnlyDeepeningDeeper) {
  // a 2 x 2 m square 0.1 m into the wall (as crushed bodies end, no node there carrying load): moving
  // out, never; moving in at 1 m/s, once 0.05 m deeper, at 0.05 s
  const double face = 0.9;
  EXPECT_EQ(Meeting(Box(2, 2, 0, 0, Vec3(0, -1, 0)), Wall(face), 10.0, 0.05), INFINITY);
  EXPECT_NEAR(Meeting(Box(2, 2, 0, 0, Vec3(0, 1, 0)), Wall(face), 10.0, 0.05), 0.05, 1e-12);
}

// a free body of unit mass with principal inertias (1, 2, 3) kg m^2
BodyModel FreeBody() {
  BodyModel m;
  m.mass = 1.0;
  m.inertia = Vec3(1.0, 2.0, 3.0).asDiagonal();
  return m;
}

TEST(WobbleSpeed, IsTheTurnOffTheVerticalTimesTheFarthestVertex) {
  // a 4 x 0.2 x 0.2 m rod (farthest vertex sqrt(2^2 + 0.1^2 + 0.1^2) m) spinning about a principal
  // axis keeps its angular velocity: pitching at 1 rad/s it departs at 1 rad/s times that reach;
  // turning about the vertical, not at all; a planar body never
  const double reach = std::sqrt(4.0 + 0.02);
  BodyState rod = Box(4.0, 0.2, 0, 0);
  rod.vertices = MakeBox(4.0, 0.2, 0.2, 2, 2, 2).vertices;
  rod.rigid.omega = Vec3(0.0, 1.0, 0.0);
  EXPECT_NEAR(WobbleSpeed(FreeBody(), MotionModel::kFree6Dof, rod, 0.2, 0.0005), reach, 1e-12);
  EXPECT_NEAR(WobbleSpeed(FreeBody(), MotionModel::kGravityGround, rod, 0.2, 0.0005), reach, 1e-12);
  EXPECT_EQ(WobbleSpeed(FreeBody(), MotionModel::kPlanar, rod, 0.2, 0.0005), 0.0);
  rod.rigid.omega = Vec3(0.0, 0.0, 1.0);
  EXPECT_EQ(WobbleSpeed(FreeBody(), MotionModel::kFree6Dof, rod, 0.2, 0.0005), 0.0);
  // past kMaxWobbleSteps, the energy bound: |w| <= sqrt(w.Iw / I_min), plus the turn about the vertical
  rod.rigid.omega = Vec3(0.0, 1.0, 0.5);
  const double bound = reach * (std::sqrt(2.0 * 1.0 + 3.0 * 0.25) + 0.5);
  EXPECT_NEAR(WobbleSpeed(FreeBody(), MotionModel::kFree6Dof, rod, 100.0, 0.0005), bound, 1e-12);
  // tumbling about the middle axis (unstable), integrated: at least its start, within the bound
  const double tumbling = WobbleSpeed(FreeBody(), MotionModel::kFree6Dof, rod, 2.0, 0.0005);
  EXPECT_GE(tumbling, reach);
  EXPECT_LE(tumbling, bound);
}

TEST(SoonestMeeting, ARodPitchingBesideAWallIsForecastNoLaterThanItMeetsIt) {
  // the rod standing 4 m tall, 1.5 m from the face, pitching at 1 rad/s: its lower end swings toward
  // the wall and reaches it where 2 sin(a) + 0.1 cos(a) = 1.5 (as the turning rod above). Its outline
  // posed by its yaw alone stands still; it departs at the wobble speed, so the forecast is the
  // clearance over that speed, (1.5 - 0.1) / wobble: conservative, 12 % early
  BodyState rod = Box(0.2, 0.2, 0, 0);
  rod.vertices = MakeBox(0.2, 0.2, 4.0, 2, 2, 2).vertices;
  rod.rigid.omega = Vec3(0.0, 1.0, 0.0);
  PlanMotion plan = PlanMotionOf(rod);
  plan.wobble_speed = WobbleSpeed(FreeBody(), MotionModel::kFree6Dof, rod, 5.0, 0.0005);
  double lo = 0.0, hi = 0.5 * M_PI;
  for (int i = 0; i < 100; ++i) {
    const double mid = 0.5 * (lo + hi);
    (2.0 * std::sin(mid) + 0.1 * std::cos(mid) < 1.5 ? lo : hi) = mid;
  }
  const double forecast = SoonestMeeting(plan, PlanMotionOf(Wall(1.5)), 5.0, 0.1);
  EXPECT_NEAR(forecast, 1.4 / plan.wobble_speed, 1e-9);
  EXPECT_LE(forecast, lo);
  std::printf("[measured] pitching rod: forecast %.4f s, meets the wall at %.4f s\n", forecast, lo);
}

}  // namespace
}  // namespace dymesh
