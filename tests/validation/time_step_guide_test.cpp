// The contact period the time-step guide estimates, against the closed form of a linear spring
// (a box with B only, its whole front on a rigid wall), and the step it recommends against the
// barrier delta-V at finer steps.
#include <gtest/gtest.h>

#include <cmath>

#include "dymesh/io/body_models.h"
#include "dymesh/accel/embree_locator.h"
#include "dymesh/analysis/summary.h"
#include "dymesh/analysis/run_assessment.h"
#include "dymesh/core/simulation.h"
#include "dymesh/core/time_step_guide.h"
#include "test_scenarios.h"

namespace dymesh {
namespace {

constexpr double kPi = 3.14159265358979323846;
namespace u = units;

// the barrier box with A = 0: force = B/H * (front area) * crush, a linear spring of that stiffness
Scenario LinearSpringBox(double time_step) {
  Scenario s = testing::BarrierScenario(30.0, 0.1, time_step);
  const Stiffness k = StiffnessFrom2D(0.0, 100.0 * u::PoundPerInchPow(2), 30.0 * u::kInch);
  s.bodies[0].stiffness.fill(k);
  return s;
}

// the spring of that box: k = B3 * 66 in * 30 in, the car's mass (the wall is fixed)
double SpringOmega() {
  const double b3 = 100.0 * u::PoundPerInchPow(2) / (30.0 * u::kInch);
  const double k = b3 * (66.0 * u::kInch) * (30.0 * u::kInch);
  return std::sqrt(k / (3000.0 * u::kPoundMass));
}

TEST(TimeStepGuide, PeriodIsTheLinearSpringsClosedForm) {
  const Scenario s = LinearSpringBox(0.0005);
  const TimeStepGuide g = GuideTimeStep(s, BuildBodyModels(s));
  ASSERT_TRUE(g.bounded);
  EXPECT_EQ(g.body_a, 0);
  EXPECT_EQ(g.body_b, 1);
  EXPECT_NEAR(g.contact_period, kPi / SpringOmega(), 1e-12);
  EXPECT_NEAR(g.stable_limit, 2.0 / SpringOmega(), 1e-12);
  EXPECT_NEAR(g.recommended_step, g.contact_period / kMinStepsPerContact, 1e-15);
}

TEST(TimeStepGuide, SimulatedLoadingLastsAQuarterOfTheSpringPeriod) {
  // the box reaches its deepest crush (zero velocity) after pi / (2 omega): the simulated spring
  // is the guide's spring; 1 % covers the half-step of the detection and the slight tilt of nodes
  const Scenario s = LinearSpringBox(0.0001);
  Simulation sim(s, BuildBodyModels(s), accel::MakeEmbreeLocatorFactory(std::make_shared<const accel::EmbreeDevice>()));
  double stop_time = -1.0;
  sim.Run([&](double t) {
    if (stop_time < 0.0 && sim.engine().state(0).rigid.velocity.x() <= 0.0) stop_time = t;
    return stop_time < 0.0;
  });
  const double contact = stop_time - sim.first_contact_time();
  EXPECT_NEAR(contact, kPi / (2.0 * SpringOmega()), 0.01 * kPi / (2.0 * SpringOmega()));
}

// barrier delta-V of the spec §4 box at `step`
double BarrierDeltaV(double step) {
  Simulation sim(testing::BarrierScenario(30.0, 0.1, step), BuildBodyModels(testing::BarrierScenario(30.0, 0.1, step)), accel::MakeEmbreeLocatorFactory(std::make_shared<const accel::EmbreeDevice>()));
  sim.Run();
  return Summarize(sim).bodies[0].delta_v;
}

TEST(TimeStepGuide, RecommendedStepResolvesDeltaVToOnePercentAndCoarseStepsAreWarned) {
  const Scenario s = testing::BarrierScenario(30.0, 0.1, 0.0005);
  const TimeStepGuide g = GuideTimeStep(s, BuildBodyModels(s));
  const double reference = BarrierDeltaV(g.recommended_step / 8.0);
  const double at_recommended = BarrierDeltaV(g.recommended_step);
  EXPECT_NEAR(at_recommended, reference, 0.01 * reference);
  // the 10 ms step: fewer than 50 steps per contact, a delta-V error beyond 1 %, a warning
  Scenario coarse = s;
  coarse.time_step = 0.01;
  Simulation sim(coarse, BuildBodyModels(coarse), accel::MakeEmbreeLocatorFactory(std::make_shared<const accel::EmbreeDevice>()));
  sim.Run();
  const Summary summary = Summarize(sim);
  EXPECT_GT(std::abs(summary.bodies[0].delta_v - reference), 0.01 * reference);
  bool warned = false;
  for (const RunWarning& w : summary.warnings) warned = warned || (w.code == "time_step_coarse" && w.field == "time.step");
  EXPECT_TRUE(warned);
  std::printf("[measured] barrier delta-V: reference %.4f m/s, recommended step %.3g s %+.3f %%, 10 ms %+.2f %%\n",
              reference, g.recommended_step, 100 * (at_recommended / reference - 1),
              100 * (summary.bodies[0].delta_v / reference - 1));
}

TEST(TimeStepGuide, StepBeyondTheStableLimitIsRefused) {
  Scenario s = LinearSpringBox(0.0005);
  s.time_step = 2.01 / SpringOmega();
  s.duration = 10 * s.time_step;
  try {
    Simulation sim(s, BuildBodyModels(s), accel::MakeEmbreeLocatorFactory(std::make_shared<const accel::EmbreeDevice>()));
    FAIL() << "accepted an unstable step";
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "time.step");
  }
  s.time_step = 1.99 / SpringOmega();
  EXPECT_NO_THROW(Simulation(s, BuildBodyModels(s), accel::MakeEmbreeLocatorFactory(std::make_shared<const accel::EmbreeDevice>())));
}

}  // namespace
}  // namespace dymesh
