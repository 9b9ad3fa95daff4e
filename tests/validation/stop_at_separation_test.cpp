// The stop at separation (time.stop_at_separation) ends a run once contact has been over for
// kSeparationWindow and no two bodies can meet again within kSlapHorizon in free motion. The known
// answer: stopping must not change what the collision gives, so a stopped run matches the same run
// carried to its duration without the stop. A box glancing off a frictionless wall at 45-60 deg turns
// and slaps the wall with its tail; the rule that ended the run 0.02 s after the first contact
// reported about half the delta-V (14.5 of 23.0 mph at 45 deg, 7.6 of 17.1 at 60). A meeting beyond
// the slap horizon is not simulated but marked (may_meet_again); friction does not make a scrape
// along a wall read as closing (passed_through).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "dymesh/accel/embree_locator.h"
#include "dymesh/analysis/run_assessment.h"
#include "dymesh/analysis/summary.h"
#include "dymesh/core/simulation.h"
#include "dymesh/io/body_models.h"
#include "dymesh/io/scenario_json.h"

namespace dymesh {
namespace {

namespace u = dymesh::units;

constexpr double kSpeedMph = 30.0;

// how a run is set up besides the impact: step, frame turned about the vertical, body order, the
// box's mesh, contact options
struct Variant {
  const char* label;
  double step = 0.0005;      // [s]
  double frame_deg = 0.0;    // every pose and heading turned
  bool wall_first = false;
  int refine = 1;            // the box's segments times this (2: each face in four)
  const char* contact = "";  // the scenario's "contact" object, inside its braces
  const char* motion = "planar";
  double cg_drop = 0.0;      // [in] the box's CG below its centre (the wall's push then rolls and pitches a free body)
};

// a 180 x 66 x 30 in, 3000 lb box at 30 mph, `heading_deg` off the normal of a rigid wall (face at
// x = 0), placed 0.5 in from it; the run 1.5 s long
std::string BoxIntoWall(double heading_deg, double restitution, double mu, bool stop, const Variant& setup) {
  const double f = setup.frame_deg * u::kDegree;
  char box[800], wall[500], json[2000], cg[40] = "";
  if (setup.cg_drop != 0.0) std::snprintf(cg, sizeof cg, R"("cg": [0, 0, %g], )", setup.cg_drop);
  std::snprintf(box, sizeof box, R"({"name": "box", "mesh": {"box": {"length": 180, "width": 66, "height": 30,
      "segments": [%d, %d, %d]}}, "weight": 3000, %s"restitution": %g, "friction": %g, "motion": "%s",
      "stiffness": {"default": {"A": 300, "B": 100, "conversion_height": 30}},
      "initial": {"position": [%.9f, %.9f, -15], "heading": %.9f, "speed": %g,
      "place_at_contact": {"with": "wall", "gap": 0.5}}})",
                18 * setup.refine, 7 * setup.refine, 3 * setup.refine, cg, restitution, mu, setup.motion, -200.0 * std::cos(f),
                -200.0 * std::sin(f), heading_deg + setup.frame_deg, kSpeedMph);
  std::snprintf(wall, sizeof wall, R"({"name": "wall", "mesh": {"box": {"length": 40, "width": 1000, "height": 60,
      "segments": [1, 10, 1]}}, "rigid": true, "motion": "fixed", "friction": %g,
      "initial": {"position": [%.9f, %.9f, -30], "heading": %.9f}})",
                mu, 20.0 * std::cos(f), 20.0 * std::sin(f), setup.frame_deg);
  std::snprintf(json, sizeof json, R"({"units": "US", "time": {"step": %g, "duration": 1.5, "stop_at_separation": %s},
      "contact": {%s}, "bodies": [%s, %s]})", setup.step, stop ? "true" : "false", setup.contact, setup.wall_first ? wall : box,
                setup.wall_first ? box : wall);
  return json;
}

struct Outcome {
  Summary summary;
  RunAssessment assessment;
  double delta_v = 0.0, yaw_rate = 0.0;  // the box's [mph], [deg/s]
  double plan_delta_v = 0.0;             // [mph] the box's, in plan (what the gravity model's ground support leaves alone)
  double end = 0.0;                      // [s] the run's end
  std::vector<double> contact_times;     // [s] every step that carried a load
  bool Warned(const std::string& code) const {
    return std::any_of(assessment.warnings.begin(), assessment.warnings.end(),
                       [&](const RunWarning& w) { return w.code == code; });
  }
};

Outcome Simulate(const std::string& json) {
  const Scenario s = ParseScenario(json, "(stop at separation test)");
  auto device = std::make_shared<const accel::EmbreeDevice>();
  Simulation sim(s, BuildBodyModels(s), accel::MakeEmbreeLocatorFactory(device));
  sim.Run();
  Outcome o;
  o.summary = Summarize(sim);
  o.assessment = AssessRun(sim, o.summary);
  const int box = s.bodies[0].name == "box" ? 0 : 1;
  o.delta_v = o.summary.bodies[box].delta_v / u::kMph;
  o.yaw_rate = o.summary.bodies[box].final_yaw_rate / u::kDegree;
  o.plan_delta_v = o.summary.bodies[box].delta_v_earth.head<2>().norm() / u::kMph;
  o.end = sim.time();
  for (const Sample& sample : sim.history())
    if (sample.bodies[box].loads.force_earth.squaredNorm() > 0.0) o.contact_times.push_back(sample.time);
  return o;
}

// whether contact resumed after a gap longer than the separation window (a second impact)
bool TouchedAgain(const std::vector<double>& contact_times) {
  for (std::size_t i = 1; i < contact_times.size(); ++i)
    if (contact_times[i] - contact_times[i - 1] > kSeparationWindow) return true;
  return false;
}

// runs the box into the wall with and without the stop and holds what stopping must keep: the run
// complete, the ledger within 2 % (the issue's bar), the slap in the stopped run, and either the later
// contact marked or the same result to round-off of the output (the same steps; the free motion after
// the last contact changes neither): delta-V in plan (the gravity model's ground support goes on
// damping a tumbling box's vertical motion) and, for a body that turns about the vertical only, the
// yaw rate (a tumbling body's keeps changing in free motion). Returns whether the two agreed (the run
// without the stop touched nothing more)
bool StopKeepsTheCollision(const std::string& what, double heading, double e, const Variant& setup) {
  const Outcome stopped = Simulate(BoxIntoWall(heading, e, 0.0, true, setup));
  const Outcome full = Simulate(BoxIntoWall(heading, e, 0.0, false, setup));
  const std::string label = what + ", " + std::to_string(heading) + " deg, e " + std::to_string(e);
  std::printf("[measured] box, %s: stopped at %.3f s, delta-V %.3f mph, yaw %.2f deg/s%s; to 1.5 s %.3f mph, "
              "%.2f deg/s, last contact %.3f s\n", label.c_str(), stopped.end, stopped.delta_v, stopped.yaw_rate,
              stopped.Warned("may_meet_again") ? " (may_meet_again)" : "", full.delta_v, full.yaw_rate,
              full.contact_times.back());
  EXPECT_EQ(stopped.assessment.status, RunStatus::kComplete) << label;
  EXPECT_NEAR(stopped.summary.energy_balance_error, 0.0, 0.02) << label;
  EXPECT_TRUE(TouchedAgain(stopped.contact_times)) << label << ": the slap is not in the stopped run";
  if (full.contact_times.back() > stopped.end) {
    EXPECT_TRUE(stopped.Warned("may_meet_again")) << label << ": a later contact not marked";
    return false;
  }
  EXPECT_NEAR(stopped.plan_delta_v, full.plan_delta_v, 1e-9 * full.plan_delta_v) << label;
  if (std::string(setup.motion) == "planar") {
    EXPECT_NEAR(stopped.yaw_rate, full.yaw_rate, 1e-9 * std::abs(full.yaw_rate) + 1e-9) << label;
  }
  return true;
}

// the default set-up, then dt/2, the wall listed first, a frame turned 30 deg, the box meshed 1:4, the
// other searches and 3 passes
std::vector<Variant> RunSetups() {
  return {Variant{"default"}, Variant{"dt/2", 0.00025}, Variant{"wall first", 0.0005, 0.0, true},
          Variant{"frame +30 deg", 0.0005, 30.0}, Variant{"box mesh 1:4", 0.0005, 0.0, false, 2},
          Variant{"local average normal", 0.0005, 0.0, false, 1, R"("search_direction": "local_average_normal")"},
          Variant{"polygon normal", 0.0005, 0.0, false, 1, R"("search_direction": "poly_normal")"},
          Variant{"3 passes", 0.0005, 0.0, false, 1, R"("passes_per_step": 3)"}};
}

// the box turns off the wall and slaps it with its tail within the slap horizon: the stopped run
// goes on through the slap (StopKeepsTheCollision). At either restitution, at dt/2, with the wall
// listed first, in a frame turned 30 deg, with the box meshed 1:4, with the other searches and 3 passes
TEST(StopAtSeparation, ATailSlapIsPartOfTheCollision) {
  int agreed = 0, runs = 0;
  for (const Variant& setup : RunSetups())
    for (double heading : {45.0, 60.0})
      for (double e : {0.0, 0.3}) {
        agreed += StopKeepsTheCollision(setup.label, heading, e, setup);
        ++runs;
      }
  // the comparison ran: a later (marked) contact is the exception, seven of the 32 runs, all with e 0:
  // dt/2 at 45 and 60 deg, the box meshed 1:4 at 45, and at 60 deg the default, the wall first, the
  // frame turned and 3 passes, which are one impact (a light touch 0.04 s after the stop: 0.05 % on
  // delta-V, 1 % on the yaw rate; it came with the wall's nodes pressing the faces beside a held corner)
  EXPECT_GE(agreed, runs - 7);
}

// a free or gravity box (6 degrees of freedom) is forecast as a planar one is, its outline's points
// also departing from it as fast as it rolls and pitches (core/separation.h, WobbleSpeed). The rule
// before (0.02 s after the last force) ended these runs before the tail slap: 7.5-16.8 of 15.9-27.5
// mph. Held as the planar box is (StopKeepsTheCollision), its CG centred, and 10 in low so that the
// wall's push rolls and pitches it; tumbling, also at dt/2, the wall first, a turned frame, the box
// meshed 1:4, the other searches and 3 passes
TEST(StopAtSeparation, FreeAndGravityBodiesAreForecastToo) {
  int agreed = 0, runs = 0;
  for (const char* motion : {"free", "gravity"})
    for (double cg_drop : {0.0, 10.0})
      for (double heading : {45.0, 60.0})
        for (double e : {0.0, 0.3}) {
          Variant setup{motion};
          setup.motion = motion;
          setup.cg_drop = cg_drop;
          agreed += StopKeepsTheCollision(std::string(motion) + ", CG " + std::to_string(cg_drop) + " in low", heading,
                                          e, setup);
          ++runs;
        }
  EXPECT_EQ(agreed, runs);  // measured: no later contact in any of the 16
  // the free box tumbling (CG low) in every other set-up (RunSetups after the default, run above):
  // measured, no later contact in any of the 28 either
  int later = 0;
  for (Variant setup : RunSetups()) {
    if (std::string(setup.label) == "default") continue;
    setup.motion = "free";
    setup.cg_drop = 10.0;
    for (double heading : {45.0, 60.0})
      for (double e : {0.0, 0.3})
        later += !StopKeepsTheCollision(std::string(setup.label) + ", free, CG 10 in low", heading, e, setup);
  }
  EXPECT_EQ(later, 0);
}

// at 30 deg the tail meets the wall 0.3 s after the first contact ends, beyond the slap horizon: the
// run stops and is marked may_meet_again; the warning is true (the run without the stop touches the
// wall again after the stopped run's end, no earlier than the forecast) and it matters (delta-V)
TEST(StopAtSeparation, ALaterSecondImpactIsMarked) {
  const Outcome stopped = Simulate(BoxIntoWall(30.0, 0.0, 0.0, true, Variant{"default"}));
  const Outcome full = Simulate(BoxIntoWall(30.0, 0.0, 0.0, false, Variant{"default"}));
  ASSERT_TRUE(stopped.Warned("may_meet_again"));
  EXPECT_EQ(stopped.assessment.status, RunStatus::kComplete);
  const auto later = std::find_if(full.contact_times.begin(), full.contact_times.end(),
                                  [&](double t) { return t > stopped.end; });
  ASSERT_NE(later, full.contact_times.end()) << "no contact after the stop";
  std::printf("[measured] box at 30 deg: stopped at %.3f s (%.3f mph), touches again at %.3f s (%.3f mph)\n",
              stopped.end, stopped.delta_v, *later, full.delta_v);
  // it matters: +26 % here; 5 % is beyond what a step or mesh change moves this box's delta-V (the
  // slap rows above: 0.2-0.4 %)
  EXPECT_GT(full.delta_v - stopped.delta_v, 0.05 * stopped.delta_v);
}

// with friction the whole impulse leans toward the slide: a box scraping along the wall at 70 deg
// (mu 0.5) read as still closing at 0.69 of its closing speed and was marked passed_through. Along
// the normal impulse (the wall's normal) it closes at v cos 70 deg and leaves: within 1e-4 of v, as
// the wall's top edge presses the box's side face along that face's normal in 8 steps (an edge has
// no normal of its own), which turns the normal impulse by 2e-5 rad
TEST(StopAtSeparation, AScrapeAlongAWallWithFrictionIsNotPassingThrough) {
  const Outcome o = Simulate(BoxIntoWall(70.0, 0.0, 0.5, true, Variant{"default"}));
  EXPECT_FALSE(o.Warned("passed_through"));
  const PairSummary& pair = o.summary.pairs.at(0);
  EXPECT_NEAR(pair.closing_speed, kSpeedMph * u::kMph * std::cos(70.0 * u::kDegree), 1e-4 * kSpeedMph * u::kMph);
  EXPECT_GE(pair.restitution(), -0.2);  // the README's stopped band for eccentric impacts
  std::printf("[measured] box at 70 deg, mu 0.5: closing %.3f mph, restitution %.3f\n", pair.closing_speed / u::kMph,
              pair.restitution());
}

}  // namespace
}  // namespace dymesh
