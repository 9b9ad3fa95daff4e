// The step in which an approach ends (spec §6, contact.turn_within_step): a touching node's loading
// force acts over the part of the step before its approach ends, its rebound force after it.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "dymesh/analysis/summary.h"
#include "dymesh/io/scenario_json.h"
#include "run_to_end.h"
#include "test_scenarios.h"

namespace dymesh {
namespace {

namespace u = dymesh::units;

// the barrier box (spec §4 test case) at `speed_mph` with restitution e, the turn within the step on (the
// default since the 58th session)
Scenario TurningBarrier(double speed_mph, double e, double time_step) {
  Scenario s = testing::BarrierScenario(speed_mph, e, time_step);
  s.contact.turn_within_step = true;
  return s;
}

// every search, stop after one, 3 passes, dt/2, a turned frame, the wall listed first and the box meshed 1:4
std::vector<testing::ScenarioVariant> TurnVariants() {
  std::vector<testing::ScenarioVariant> variants = testing::ContactVariants();
  variants.insert(variants.begin(), {"default", [](Scenario*) {}});
  variants.push_back({"wall first", [](Scenario* s) { std::swap(s->bodies[0], s->bodies[1]); }});
  variants.push_back({"box mesh 1:4", [](Scenario* s) { s->bodies[0].mesh.box_segments = {1, 44, 20}; }});
  return variants;
}

// one variant's run of the turning barrier box, and which body is the box
struct VariantRun {
  Summary summary;
  int box = 0;
};

VariantRun RunVariant(Scenario s, const testing::ScenarioVariant& variant) {
  variant.second(&s);
  return {testing::RunToEnd(s), s.bodies[0].rigid ? 1 : 0};
}

// Known answer: with e = 0 the law gives nothing back (spec §6 Eq. 8), so the box stops at the wall:
// delta-V = v, no rebound. At parking-lot speeds the front stays inside the null band, where the law
// is the constant A (spec §3): 19,800 lbf on the whole front, 0.1 mph of the box's speed per 0.5 ms
// step, the whole of the slowest approach in one step. Held whole over the step in which the approach
// ends, it turned the box round (default options: at 0.5 mph this box leaves at 0.0135 of its speed,
// the taller box of README's known limits at 0.16). The turn is exact for the host's step on a flat front (its points turn together), so the
// bar is round-off of the trial motions: 1e-6 of v. In every variant above
TEST(TurnWithinStep, PlasticBoxStopsAtParkingLotSpeeds) {
  for (const testing::ScenarioVariant& variant : TurnVariants())
    for (double mph : {0.25, 0.5, 1.0, 2.0}) {
      const auto [sum, box] = RunVariant(TurningBarrier(mph, 0.0, 0.0005), variant);
      const std::string label = variant.first + ", " + std::to_string(mph) + " mph";
      std::printf("[measured] plastic box at %.2f mph, %s: delta-V %.6f mph, leaves at %.2e mph, energy balance "
                  "%.1e\n", mph, variant.first.c_str(), sum.bodies[box].delta_v / u::kMph,
                  sum.separation_speed / u::kMph, sum.energy_balance_error);
      EXPECT_NEAR(sum.bodies[box].delta_v, mph * u::kMph, 1e-6 * mph * u::kMph) << label;
      EXPECT_EQ(sum.status, RunStatus::kComplete) << label;
      // the ledger: the kinetic energy lost is the contact's work (2 %, the issue's bar)
      EXPECT_NEAR(sum.energy_balance_error, 0.0, 0.02) << label;
    }
}

// Known answer: the scaled rebound law returns e^2 of the loading work (spec §6), so the box leaves
// at e v. Within 3 %, the barrier test's bar at 0.1 ms steps; here at 0.5 ms, where the turn leaves
// the last loading step no overshoot (without it the rebound is the law's plus up to F dt / m). In every
// variant above, the ledger balanced within 2 % (the issue's bar)
TEST(TurnWithinStep, ReboundLeavesAtRestitutionTimesImpactSpeed) {
  for (const testing::ScenarioVariant& variant : TurnVariants())
    for (double mph : {5.0, 30.0}) {
      const auto [sum, box] = RunVariant(TurningBarrier(mph, 0.2, 0.0005), variant);
      const std::string label = variant.first + ", " + std::to_string(mph) + " mph";
      std::printf("[measured] box at %.0f mph, e 0.2, %s: leaves at %.4f of its speed, energy balance %.1e\n", mph,
                  variant.first.c_str(), sum.separation_speed / sum.closing_speed, sum.energy_balance_error);
      EXPECT_NEAR(sum.separation_speed, 0.2 * sum.closing_speed, 0.03 * 0.2 * sum.closing_speed) << label;
      EXPECT_NEAR(sum.energy_balance_error, 0.0, 0.02) << label;
    }
}

// Known answer: delta-V does not depend on the step (the reference: 0.1 ms). At a coarse 10 ms step
// (the barrier pulse is 0.1 s: ten steps) the last loading step's whole impulse overshot by up to
// F dt / m, +6 % on delta-V; with the turn within 1 %, the time-step guide's bar
TEST(TurnWithinStep, CoarseStepKeepsDeltaV) {
  const double reference = testing::RunToEnd(TurningBarrier(30.0, 0.1, 0.0001)).bodies[0].delta_v;
  const double coarse = testing::RunToEnd(TurningBarrier(30.0, 0.1, 0.01)).bodies[0].delta_v;
  std::printf("[measured] barrier at 10 ms steps: delta-V %+.2f %% of the 0.1 ms run's\n",
              100.0 * (coarse / reference - 1.0));
  EXPECT_NEAR(coarse, reference, 0.01 * reference);
}

// a 180 x 66 x 30 in, 3000 lb box at 30 mph, 45 deg off the normal of a frictionless rigid wall, e 0.3
Scenario BoxAt45Degrees(double time_step) {
  char json[1600];
  std::snprintf(json, sizeof json, R"({"units": "US",
    "time": {"step": %g, "duration": 0.6, "stop_at_separation": false},
    "bodies": [{"name": "box", "mesh": {"box": {"length": 180, "width": 66, "height": 30, "segments": [18, 7, 3]}},
      "weight": 3000, "restitution": 0.3, "friction": 0, "motion": "planar",
      "stiffness": {"default": {"A": 300, "B": 100, "conversion_height": 30}},
      "initial": {"position": [-200, 0, -15], "heading": 45, "speed": 30,
                  "place_at_contact": {"with": "wall", "gap": 0.5}}},
     {"name": "wall", "mesh": {"box": {"length": 40, "width": 1000, "height": 60, "segments": [1, 10, 1]}},
      "rigid": true, "motion": "fixed", "friction": 0, "initial": {"position": [20, 0, -30]}}]})",
                time_step);
  return ParseScenario(json, "(box at 45 deg)");
}

// Known answer: the result does not depend on the step. The box above turns on the wall and its tail
// slaps it; as the box turns off, each node column's approach ends in a step of its own. Read from
// the step's end alone (the loading impulse capped to stop the approach there), a column whose rebound
// had parted it by the step's end lost its whole step of loading: the box left turning at 18.9 deg/s
// at 0.5 ms steps, 7.9 at 0.25 ms. Delta-V and the yaw rate after at 0.5 ms within 2 % (the issue's
// convergence bar) of a 0.125 ms run's
TEST(TurnWithinStep, TailSlapDoesNotDependOnTheStep) {
  const Summary fine = testing::RunToEnd(BoxAt45Degrees(0.000125));
  const Summary coarse = testing::RunToEnd(BoxAt45Degrees(0.0005));
  std::printf("[measured] box at 45 deg, e 0.3: delta-V %.3f / %.3f mph, yaw rate after %.2f / %.2f deg/s (0.5 / "
              "0.125 ms)\n", coarse.bodies[0].delta_v / u::kMph, fine.bodies[0].delta_v / u::kMph,
              coarse.bodies[0].final_yaw_rate / u::kDegree, fine.bodies[0].final_yaw_rate / u::kDegree);
  EXPECT_NEAR(coarse.bodies[0].delta_v, fine.bodies[0].delta_v, 0.02 * fine.bodies[0].delta_v);
  EXPECT_NEAR(coarse.bodies[0].final_yaw_rate, fine.bodies[0].final_yaw_rate,
              0.02 * std::abs(fine.bodies[0].final_yaw_rate));
}

}  // namespace
}  // namespace dymesh
