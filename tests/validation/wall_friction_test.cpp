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

Scenario SlidingScenario(double mu) {
  Scenario s;
  s.file = "(wall friction test)";
  s.units = UnitSystem::kUS;
  s.time_step = 0.0005;
  s.duration = 0.4;
  BodySpec box = testing::BoxVehicle("box", kLength, kWidth, 30, {1, 20, 10}, 3000, 300, 100, 30, 0.0);
  const double box_izz = box.mass * (std::pow(kLength * u::kInch, 2) + std::pow(kWidth * u::kInch, 2)) / 12;
  box.inertia_diagonal = Vec3(1, 1, 1) * 1e4 * box_izz;
  box.initial.velocity = Vec3(kNormalMph, kSlideMph, 0) * u::kMph;
  box.friction = mu;
  BodySpec wall = testing::RigidWall(kLength / 2 + 0.5);
  wall.friction = mu;  // the pair's mu is the mean of the two
  s.bodies = {box, wall};
  return s;
}

// closed form of a plastic impact of a body that does not turn: the normal impulse m v_n stops the
// approach; Coulomb friction takes mu m v_n from the slide, or the whole slide v_t if that is less
// (it sticks: the slide is stopped, not reversed). Slide delta-V = min(mu v_n, v_t)
double SlideDeltaV(double mu) { return std::min(mu * kNormalMph, kSlideMph) * u::kMph; }

void ExpectClosedForm(double mu) {
  const Scenario scenario = SlidingScenario(mu);
  auto device = std::make_shared<const accel::EmbreeDevice>();
  Simulation sim(scenario, BuildBodyModels(scenario), accel::MakeEmbreeLocatorFactory(device));
  sim.Run();
  const Summary s = Summarize(sim);
  const Vec3 dv = s.bodies[0].delta_v_earth;
  const double expected = SlideDeltaV(mu);
  // 3 %: the null band (1 in/s, 2 % of the 3 mph slide) leaves a slide that slow unresisted
  EXPECT_NEAR(-dv.x(), kNormalMph * u::kMph, 0.03 * kNormalMph * u::kMph) << "mu " << mu;
  EXPECT_NEAR(-dv.y(), expected, 0.03 * expected) << "mu " << mu;
  EXPECT_NEAR(s.energy_balance_error, 0.0, 0.02) << "mu " << mu;
  std::printf("[measured] wall friction mu %.2f: slide delta-V %.4f m/s (closed form %.4f, %s), normal %.4f m/s\n",
              mu, -dv.y(), expected, mu * kNormalMph >= kSlideMph ? "sticks" : "slides", -dv.x());
}

TEST(WallFriction, SlidingTakesMuTimesTheNormalImpulse) { ExpectClosedForm(0.1); }
TEST(WallFriction, StickingStopsTheSlideAndNoMore) { ExpectClosedForm(0.5); }

}  // namespace
}  // namespace dymesh
