// An oblique impact into a rigid wall with friction against the impulse-momentum closed form, in the
// sliding regime (friction impulse mu times the normal impulse) and in the sticking regime (the
// friction impulse stops the contact point's slide, no more).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "dymesh/io/body_models.h"
#include "dymesh/accel/embree_locator.h"
#include "dymesh/analysis/summary.h"
#include "dymesh/core/simulation.h"
#include "test_scenarios.h"

namespace dymesh {
namespace {

namespace u = dymesh::units;

// a 100 x 60 x 30 in, 3000 lb box, square to the wall, at 10 mph into it and 3 mph along it; e = 0.
// Its yaw inertia is made 10^4 times a box's so that it slides without turning: the flat face's
// couple against yawing then plays no part, and the contact point moves with the CG
constexpr double kLength = 100.0, kWidth = 60.0;  // [in]
constexpr double kNormalMph = 10.0, kSlideMph = 3.0;

// how a run is set up besides mu: step, frame, search method and which body is listed first
struct Variant {
  const char* label;
  double time_step = 0.0005;    // [s]
  double frame_angle = 0.0;     // [rad] every pose and velocity turned about the vertical
  SearchDirection direction = SearchDirection::kVelocity;
  bool wall_first = false;
};

Mat3 Rz(double angle) { return BodyToEarth(0.0, 0.0, angle); }

Scenario SlidingScenario(double mu, const Variant& v) {
  Scenario s;
  s.file = "(wall friction test)";
  s.units = UnitSystem::kUS;
  s.time_step = v.time_step;
  s.duration = 0.4;
  s.contact.search_direction = v.direction;
  BodySpec box = testing::BoxVehicle("box", kLength, kWidth, 30, {1, 20, 10}, 3000, 300, 100, 30, 0.0);
  const double box_izz = box.mass * (std::pow(kLength * u::kInch, 2) + std::pow(kWidth * u::kInch, 2)) / 12;
  box.inertia_diagonal = Vec3(1, 1, 1) * 1e4 * box_izz;
  box.initial.velocity = Vec3(kNormalMph, kSlideMph, 0) * u::kMph;
  box.friction = mu;
  BodySpec wall = testing::RigidWall(kLength / 2 + 0.5);
  wall.friction = mu;  // the pair's mu is the mean of the two
  for (BodySpec* b : {&box, &wall}) {
    b->initial.position = Rz(v.frame_angle) * b->initial.position;
    b->initial.velocity = Rz(v.frame_angle) * b->initial.velocity;
    b->initial.yaw += v.frame_angle;
  }
  s.bodies = v.wall_first ? std::vector<BodySpec>{wall, box} : std::vector<BodySpec>{box, wall};
  return s;
}

// closed form of a plastic impact of a body that does not turn: the normal impulse m v_n stops the
// approach; Coulomb friction takes mu m v_n from the slide, or the whole slide v_t if that is less
// (it sticks: the slide is stopped, not reversed). Slide delta-V = min(mu v_n, v_t)
double SlideDeltaV(double mu) { return std::min(mu * kNormalMph, kSlideMph) * u::kMph; }

void ExpectClosedForm(double mu, const Variant& v) {
  const Scenario scenario = SlidingScenario(mu, v);
  auto device = std::make_shared<const accel::EmbreeDevice>();
  Simulation sim(scenario, BuildBodyModels(scenario), accel::MakeEmbreeLocatorFactory(device));
  sim.Run();
  const Summary s = Summarize(sim);
  // delta-V in the wall's frame: normal (x) and along the wall (y)
  const Vec3 dv = Rz(v.frame_angle).transpose() * s.bodies[v.wall_first ? 1 : 0].delta_v_earth;
  const double expected = SlideDeltaV(mu);
  // 3 %: the null band (1 in/s, 2 % of the 3 mph slide) could leave a slide that slow unresisted
  EXPECT_NEAR(-dv.x(), kNormalMph * u::kMph, 0.03 * kNormalMph * u::kMph) << "mu " << mu << " " << v.label;
  EXPECT_NEAR(-dv.y(), expected, 0.03 * expected) << "mu " << mu << " " << v.label;
  EXPECT_NEAR(s.energy_balance_error, 0.0, 0.02) << "mu " << mu << " " << v.label;
  std::printf("[measured] wall friction mu %.2f, %s: slide delta-V %.4f m/s (closed form %.4f, %s), normal %.4f m/s\n",
              mu, v.label, -dv.y(), expected, mu * kNormalMph >= kSlideMph ? "sticks" : "slides", -dv.x());
}

// the default run, then a half step, a turned frame, the other search methods and the other body order
const Variant kVariants[] = {{"default"},
                             {"dt/2", 0.00025},
                             {"frame +30 deg", 0.0005, 30.0 * u::kDegree},
                             {"local average normal", 0.0005, 0.0, SearchDirection::kLocalAverageNormal},
                             {"polygon normal", 0.0005, 0.0, SearchDirection::kPolyNormal},
                             {"wall listed first", 0.0005, 0.0, SearchDirection::kVelocity, true}};

TEST(WallFriction, SlidingTakesMuTimesTheNormalImpulse) {
  for (const Variant& v : kVariants) ExpectClosedForm(0.1, v);
}
TEST(WallFriction, StickingStopsTheSlideAndNoMore) {
  for (const Variant& v : kVariants) ExpectClosedForm(0.5, v);
}

}  // namespace
}  // namespace dymesh
