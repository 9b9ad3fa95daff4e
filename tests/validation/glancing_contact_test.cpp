// What passed_through marks: a glancing contact is not a pass-through (two boxes brushing corners at
// 30 deg slide past each other, so along their sideways impulse they still close as they part); boxes
// that went through each other between their nodes are, and so are bodies whose contact search never
// found each other (no force at all).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <string>

#include "dymesh/accel/embree_locator.h"
#include "dymesh/analysis/plan_overlap.h"
#include "dymesh/analysis/run_assessment.h"
#include "dymesh/analysis/summary.h"
#include "dymesh/core/simulation.h"
#include "dymesh/io/body_models.h"
#include "test_scenarios.h"

namespace dymesh {
namespace {

namespace u = units;
constexpr double kPi = 3.14159265358979323846;

struct Outcome {
  Summary summary;
  double went_in = 0.0;  // [m] DeepestPlanOverlap along the pair's impulse
  bool separated = false;
  bool Warned(const std::string& code) const {
    return std::any_of(summary.warnings.begin(), summary.warnings.end(),
                       [&](const RunWarning& w) { return w.code == code; });
  }
};

Outcome Simulate(const Scenario& s) {
  Simulation sim(s, BuildBodyModels(s), accel::MakeEmbreeLocatorFactory(std::make_shared<const accel::EmbreeDevice>()));
  sim.Run();
  Outcome o{Summarize(sim)};
  o.separated = sim.separated();
  if (!o.summary.pairs.empty()) o.went_in = DeepestPlanOverlap(sim, 0, 1, o.summary.pairs[0].direction);
  return o;
}

// box "a" at 30 mph along x, placed 1 in from box "b", which comes the other way at 30 mph turned
// 150 deg, `offset_in` to the side: their corners meet
Scenario Brush(double offset_in, std::array<int, 3> segments) {
  Scenario s = testing::UsScenario("(brush)", 0.0005, 0.8);
  s.stop_at_separation = true;
  BodySpec a = testing::BoxVehicle("a", 180, 66, 30, segments, 3000, 300, 100, 30, 0.1);
  BodySpec b = a;
  b.name = "b";
  a.initial.position = Vec3(-300, 0, 0) * u::kInch;
  a.initial.velocity = Vec3(30 * u::kMph, 0, 0);
  a.place_at_contact = BodySpec::PlaceAtContact{1, 1.0 * u::kInch};
  const double heading = 150.0 * kPi / 180.0;
  b.initial.position = Vec3(0, offset_in, 0) * u::kInch;
  b.initial.yaw = heading;
  b.initial.velocity = 30 * u::kMph * Vec3(std::cos(heading), std::sin(heading), 0);
  for (BodySpec* body : {&a, &b}) body->friction = 0.3;
  s.bodies = {a, b};
  return s;
}

// boxes brushing with fine meshes (10 in cells): they crush where they meet and slide off (delta-V
// 0.2-5.7 mph of a 58 mph relative speed), ending at -0.75 to -0.98 of their closing speed along
// the impulse, which leans across their paths. Not gone inside each other (obstacle_inside, judged on
// these closed meshes, is silent), and their outlines went into each other along the impulse no
// farther than they crushed (15-25 in for 21-32 in). Before, each was voided as passed_through
TEST(GlancingContact, BoxesBrushingPastEachOtherAreNotPassingThrough) {
  for (double offset : {-165.0, -180.0, -190.0}) {
    const Outcome o = Simulate(Brush(offset, {18, 11, 5}));
    const std::string label = "offset " + std::to_string(offset) + " in";
    ASSERT_EQ(o.summary.pairs.size(), 1u) << label;
    const PairSummary& pair = o.summary.pairs[0];
    EXPECT_LT(pair.restitution(), kPassThroughSeparation) << label << ": the case the rule used to void";
    EXPECT_TRUE(o.separated) << label;
    EXPECT_EQ(o.summary.status, RunStatus::kComplete) << label;
    EXPECT_FALSE(o.Warned("obstacle_inside")) << label;
    EXPECT_FALSE(o.Warned("passed_through")) << label;
    const double crushed = o.summary.bodies[0].max_dynamic_crush + o.summary.bodies[1].max_dynamic_crush;
    EXPECT_LT(o.went_in, crushed) << label;
    std::printf("[measured] brush %s: delta-V %.2f mph, restitution along the impulse %.3f, went in %.1f in for "
                "%.1f in of crush\n", label.c_str(), o.summary.bodies[0].delta_v / u::kMph, pair.restitution(),
                o.went_in / u::kInch, crushed / u::kInch);
  }
}

// the 180 in brush across the step, the searches, the stop rule, passes, box a meshed 1:4, the bodies
// listed the other way round and the frame turned: never voided, and never farther into each other
// along the impulse than the two crushed (the rule's own bar, search reach added, is not needed)
TEST(GlancingContact, TheBrushIsNotVoidedAcrossStepSearchPassesMeshOrderAndFrame) {
  for (const testing::ScenarioVariant& variant : testing::ContactVariantsWithMeshAndOrder("a meshed 1:4", "b first")) {
    Scenario s = Brush(-180.0, {18, 11, 5});
    variant.second(&s);
    const Outcome o = Simulate(s);
    ASSERT_EQ(o.summary.pairs.size(), 1u) << variant.first;
    const double crushed = o.summary.bodies[0].max_dynamic_crush + o.summary.bodies[1].max_dynamic_crush;
    EXPECT_FALSE(o.Warned("passed_through")) << variant.first;
    EXPECT_LT(o.went_in, crushed) << variant.first;
    std::printf("[measured] brush 180 in over, %s: restitution along the impulse %.3f, went in %.1f in for %.1f in\n",
                variant.first.c_str(), o.summary.pairs[0].restitution(), o.went_in / u::kInch, crushed / u::kInch);
  }
}

// the same brush with boxes of one cell along their length (180 in faces): a's corner goes in between
// b's nodes and on through it. Marked, by both signs
TEST(GlancingContact, TheSameBrushWithCoarseBoxesGoesThroughAndIsMarked) {
  const Outcome o = Simulate(Brush(-150.0, {1, 11, 5}));
  EXPECT_TRUE(o.Warned("obstacle_inside"));
  EXPECT_TRUE(o.Warned("passed_through"));
}

// the coarse boxes head-on (single-quad faces, 30 mph each), `offset` to the side so their fronts
// overlap by 66 in less that: each side's nodes miss the other's faces and they go through each other.
// obstacle_inside is silent here, so the mark rests on how far along the impulse one went into the
// other: past the other's length (180 in), against 25 in of crush
TEST(GlancingContact, BoxesGoneThroughEachOtherWithTheirCornersOverlappingAreMarked) {
  for (double offset : {40.0, 60.0}) {
    Scenario s = testing::UsScenario("(coarse boxes)", 0.0005, 0.5);
    s.stop_at_separation = true;
    BodySpec a = testing::BoxVehicle("a", 180, 66, 30, {1, 1, 1}, 3000, 300, 100, 30, 0.1);
    BodySpec b = a;
    b.name = "b";
    a.initial.velocity = Vec3(30 * u::kMph, 0, 0);
    b.initial.position = Vec3(181, offset, 0) * u::kInch;
    b.initial.yaw = kPi;
    b.initial.velocity = Vec3(-30 * u::kMph, 0, 0);
    s.bodies = {a, b};
    const Outcome o = Simulate(s);
    const std::string label = "offset " + std::to_string(offset) + " in";
    ASSERT_EQ(o.summary.pairs.size(), 1u) << label;
    EXPECT_LT(o.summary.pairs[0].restitution(), kPassThroughSeparation) << label;
    EXPECT_FALSE(o.Warned("obstacle_inside")) << label;
    EXPECT_GT(o.went_in, 180.0 * u::kInch) << label;
    EXPECT_TRUE(o.Warned("passed_through")) << label;
    std::printf("[measured] coarse boxes head-on %s: restitution %.3f, went in %.1f in for %.1f in of crush\n",
                label.c_str(), o.summary.pairs[0].restitution(), o.went_in / u::kInch,
                (o.summary.bodies[0].max_dynamic_crush + o.summary.bodies[1].max_dynamic_crush) / u::kInch);
  }
}

// the barrier box at 30 mph with the specified search direction: along the box's -x (its front pushed
// back) it stops as the velocity search does, at (1 + e) v; along its y the nodes never look ahead, so
// the box runs 2.8 m into the wall with no force. Before, that read "no_contact: the bodies never
// touched", not voiding: a sample kept at delta-V 0
TEST(GlancingContact, BodiesWhoseSearchNeverFoundEachOtherPassedThrough) {
  auto run = [](const Vec3& direction) {
    Scenario s = testing::BarrierScenario(30.0, 0.1, 0.0005);
    s.contact.search_direction = SearchDirection::kSpecified;
    s.contact.specified_direction = direction;
    return Simulate(s);
  };
  const Outcome back = run(Vec3(-1, 0, 0));
  EXPECT_NEAR(back.summary.bodies[0].delta_v, 1.1 * 30.0 * u::kMph, 0.01 * 1.1 * 30.0 * u::kMph);
  EXPECT_FALSE(back.Warned("passed_through"));
  const Outcome sideways = run(Vec3(0, 1, 0));
  EXPECT_EQ(sideways.summary.bodies[0].delta_v, 0.0);
  EXPECT_TRUE(sideways.Warned("passed_through"));
  EXPECT_FALSE(sideways.Warned("no_contact"));
  EXPECT_TRUE(WarningVoidsResults("passed_through"));
  // a wall beside the box's path, never met: no_contact, not passed_through
  Scenario beside = testing::BarrierScenario(30.0, 0.1, 0.0005);
  beside.bodies[1].initial.position.y() = 300.0 * u::kInch;
  const Outcome missed = Simulate(beside);
  EXPECT_TRUE(missed.Warned("no_contact"));
  EXPECT_FALSE(missed.Warned("passed_through"));
  std::printf("[measured] specified -x: delta-V %.3f mph (closed form %.3f); along y: %.3f mph\n",
              back.summary.bodies[0].delta_v / u::kMph, 1.1 * 30.0, sideways.summary.bodies[0].delta_v / u::kMph);
}

}  // namespace
}  // namespace dymesh
