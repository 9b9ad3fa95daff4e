// A rigid body that goes inside a deformable one deeper than the body crushed there is marked: it
// went in between the nodes. The test's own measure: the pole's intrusion into the box's rest
// shape, from where the run ended, against the box's deepest crush anywhere.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "dymesh/accel/embree_locator.h"
#include "dymesh/analysis/run_assessment.h"
#include "dymesh/analysis/summary.h"
#include "dymesh/core/simulation.h"
#include "dymesh/core/units.h"
#include "dymesh/io/body_models.h"
#include "dymesh/io/scenario_json.h"

namespace dymesh {
namespace {

namespace u = units;

// a scenario's JSON text run to its end, with its summary and assessment (the simulation kept for its
// states)
struct AssessedRun {
  std::shared_ptr<const accel::EmbreeDevice> device;
  std::unique_ptr<Simulation> sim;
  Summary summary;
  RunAssessment assessment;
};
AssessedRun RunAndAssess(const char* json, const std::string& file) {
  const Scenario s = ParseScenario(json, file);
  AssessedRun r;
  r.device = std::make_shared<const accel::EmbreeDevice>();
  r.sim = std::make_unique<Simulation>(s, BuildBodyModels(s), accel::MakeEmbreeLocatorFactory(r.device));
  r.sim->Run();
  r.summary = Summarize(*r.sim);
  r.assessment = AssessRun(*r.sim, r.summary);
  return r;
}

struct Outcome {
  double intrusion = 0.0;  // [in] the pole's near side behind the box's rest front, where the run ended
  double crush = 0.0;      // [in] the box's deepest crush
  double delta_v = 0.0;    // [mph]
  bool inside = false;     // marked obstacle_inside
  bool voided = false;     // a warning voids the results
};

// the 3000 lb box (A 300 lb/in, B 100 lb/in^2, e 0) at 10 mph into the fixed 12 in round pole on its
// axis, 0.5 in apart, its front in `cell` in cells, friction `mu` on both; `post` meshes the box as
// one quad per side split 1:4 three times instead (nodes 8.25 in apart across the front) and puts a
// 6 in square post between its node columns in place of the pole; `carried_on` runs 3 s without the
// stop at separation; the rest are the contact options, the body order and the scene's heading
struct BoxRun {
  double cell = 2.0;
  double mu = 0.0;
  bool post = false;
  bool carried_on = false;
  std::string search = "velocity";
  int passes = 2;
  double step = 0.0005;  // [s]
  bool pole_first = false;
  double heading = 0.0;  // [deg] the box's, the pole placed ahead of it
  std::string label;
};

Outcome RunBoxIntoPole(const BoxRun& run) {
  const double cell = run.cell;
  const int nx = static_cast<int>(180 / cell), ny = static_cast<int>(66 / cell), nz = static_cast<int>(30 / cell);
  char box[1024], pole[1024], json[3072];
  std::snprintf(box, sizeof box, R"({"name": "box", "mesh": {"box": {"length": 180, "width": 66, "height": 30,
       "segments": [%d, %d, %d]}%s}, "weight": 3000, "restitution": 0, "friction": %g, "motion": "planar",
       "stiffness": {"default": {"A": 300, "B": 100, "conversion_height": 30}},
       "initial": {"position": [0, 0, 0], "heading": %g, "speed": 10}})",
                run.post ? 1 : nx, run.post ? 1 : ny, run.post ? 1 : nz, run.post ? R"(, "subdivisions": 3)" : "",
                run.mu, run.heading);
  const double ahead = run.post ? 93.5 : 96.5;  // [in] the obstacle's centre, 0.5 in before the front
  const double turn = run.heading * u::kDegree;
  std::snprintf(pole, sizeof pole, R"({"name": "pole", "mesh": %s, "rigid": true, "motion": "fixed", "friction": %g,
       "initial": {"position": [%.17g, %.17g, 0]}})",
                run.post ? R"({"box": {"length": 6, "width": 6, "height": 100, "segments": [6, 6, 100]}})"
                        : R"({"cylinder": {"radius": 6, "height": 100, "segments": 32}})",
                run.mu, ahead * std::cos(turn), ahead * std::sin(turn));
  std::snprintf(json, sizeof json, R"({"units": "US", "time": {"step": %g, "duration": %g, "stop_at_separation": %s},
    "contact": {"passes_per_step": %d, "search_direction": "%s"}, "bodies": [%s, %s]})",
                run.step, run.carried_on ? 3.0 : 0.6, run.carried_on ? "false" : "true", run.passes, run.search.c_str(),
                run.pole_first ? pole : box, run.pole_first ? box : pole);
  const AssessedRun ran = RunAndAssess(json, "box_into_pole.json");
  const Simulation& sim = *ran.sim;
  const Summary& summary = ran.summary;
  const RunAssessment& assessment = ran.assessment;
  const int ib = run.pole_first ? 1 : 0, ip = 1 - ib;
  Outcome o;
  // the pole's near side in the box's frame (planar: the box turns about z only)
  const RigidState& b = sim.engine().state(ib).rigid;
  const Vec3 centre = b.Rotation().transpose() * (sim.engine().state(ip).rigid.position - b.position);
  o.intrusion = (90 * u::kInch - (centre.x() - 3 * u::kInch * (run.post ? 1 : 2))) / u::kInch;
  o.crush = summary.bodies[ib].max_crush / u::kInch;
  o.delta_v = summary.bodies[ib].delta_v / u::kMph;
  for (const RunWarning& w : assessment.warnings) {
    o.inside = o.inside || w.code == "obstacle_inside";
    o.voided = o.voided || WarningVoidsResults(w.code);
  }
  std::printf("[measured] %g in cells, mu %g%s: pole %.2f in into the rest front, deepest crush %.2f in, "
              "delta-V %.2f mph, marked %d, voided %d\n",
              cell, run.mu, run.label.c_str(), o.intrusion, o.crush, o.delta_v, o.inside, o.voided);
  return o;
}

// the variants each case is held over: the searches, three passes, dt/2, the pole listed first and
// the scene turned 30 degrees
std::vector<BoxRun> Variants(BoxRun base) {
  std::vector<BoxRun> out = {base};
  auto add = [&](const std::string& label, const std::function<void(BoxRun*)>& change) {
    BoxRun v = base;
    change(&v);
    v.label = ", " + label;
    out.push_back(v);
  };
  add("local average normal", [](BoxRun* v) { v->search = "local_average_normal"; });
  add("polygon normal", [](BoxRun* v) { v->search = "poly_normal"; });
  add("3 passes", [](BoxRun* v) { v->passes = 3; });
  add("dt/2", [](BoxRun* v) { v->step /= 2; });
  add("pole listed first", [](BoxRun* v) { v->pole_first = true; });
  add("turned 30 deg", [](BoxRun* v) { v->heading = 30.0; });
  return out;
}

// spec §2 TOOFAR_MAXIMUM (6 in): a pole deeper than the box crushed by more than the search reaches
// is never met again
constexpr double kReach = 6.0;  // [in]

// Frictionless, the 2 in cells' nodes slid round the pole and it went 45 in into a box that crushed
// 11 in (the closed form crushes 12.71 in and stops the box), over every variant: marked, and, the
// pair still closing at over a quarter of its closing speed with the pole inside, passed through
// (voided). Before, `complete` without a warning (48 % of the closing speed left; passed_through
// alone needs 50 %).
TEST(ObstacleInside, PoleThatWentInBetweenTheNodesIsMarked) {
  for (const BoxRun& v : Variants({})) {
    const Outcome o = RunBoxIntoPole(v);
    ASSERT_GT(o.intrusion - o.crush, kReach) << v.label;  // the case: deeper than any crush, by more than the reach
    EXPECT_TRUE(o.inside) << v.label;
    EXPECT_TRUE(o.voided) << v.label;
  }
  // carried on without the stop, the pole leaves through the box's back (it did, unmarked, before the
  // check read every recorded state)
  BoxRun on;
  on.carried_on = true;
  on.label = ", carried on to 3 s";
  const Outcome o = RunBoxIntoPole(on);
  ASSERT_GT(o.intrusion, 180.0);  // [in] behind the rest front: past the 180 in box
  EXPECT_TRUE(o.inside);
  EXPECT_TRUE(o.voided);
}

// With friction the box crushes as deep as the pole came (a box stopped against a rigid pole closes
// by its own crush), at every cell size and over the variants, and between the node columns of a
// coarse front (the post's nodes push its faces): none is marked
TEST(ObstacleInside, PoleTheBoxCrushedAroundIsNotMarked) {
  std::vector<BoxRun> runs;
  BoxRun with_friction;
  with_friction.mu = 0.5;
  for (double cell : {1.5, 3.0, 6.0}) {
    with_friction.cell = cell;
    runs.push_back(with_friction);
  }
  with_friction.cell = 2.0;
  for (const BoxRun& v : Variants(with_friction)) runs.push_back(v);
  BoxRun post;
  post.cell = 8.25;
  post.post = true;
  post.label = " (post between node columns)";
  runs.push_back(post);
  for (const BoxRun& v : runs) {
    const Outcome o = RunBoxIntoPole(v);
    EXPECT_LT(o.intrusion - o.crush, kReach) << v.cell << v.label;
    EXPECT_FALSE(o.inside) << v.cell << v.label;
    EXPECT_FALSE(o.voided) << v.cell << v.label;
  }
}


// A deformable body through another's faces (fuzzing, 2026-11-27; before, unmarked): a 10 in cube of
// 200 lb (A 5000, B 2000 lb/in) at `speed` into a 200 x 80 x 60 in, 5000 lb box (A 300, B 100, 3 in
// cells), the scene turned `heading` degrees, run 2 s without the stop. The test's own measure: how
// far the cube's centre went past the box's back face (where it comes in), at any recorded state with
// the centre inside the box's rest shape, beyond the box's deepest crush within 10 in across that line
// (the cube's width: the crush the cube itself could have made). The bar is the search's reach, as for
// the pole above. At 90 mph turned 10 deg the cube goes through the box's faces, 172 in past the crush
// (80 mph did until friction was read against the slide it leaves, 69th session: the crater now holds
// the cube 3.8 in short of its crush at 70-80 mph, turned 0-30 deg, and lets it through at 90, 156-172
// in); at 20 mph it stops 10 in into the box and bounces back (e 0.10 of 0.1). (Before: at 80 mph
// unturned, the crater's nodes slid off the cube's faces and it drifted on inside the box after the
// pulse, at 0.2-0.5 mph, unmarked; with a first law of the turn within the step at 2.4 mph, 27 in past
// the crush by the end, marked; at 50-70 mph, or turned 30 deg, it was marked: Known limits)
struct CubeRun {
  double inside_beyond_crush = -INFINITY;  // [in]
  bool inside = false, voided = false;
};

CubeRun RunCubeIntoBox(double heading, double speed) {
  const double turn = heading * u::kDegree;
  char json[2048];
  std::snprintf(json, sizeof json, R"({"units": "US",
    "time": {"step": 0.0005, "duration": 2.0, "stop_at_separation": false},
    "bodies": [{"name": "cube", "mesh": {"box": {"length": 10, "width": 10, "height": 10, "segments": [3, 3, 3]}},
      "restitution": 0.1, "friction": 0.5, "weight": 200, "stiffness": {"default": {"A": 5000, "B": 2000}},
      "initial": {"position": [%.17g, %.17g, -30], "heading": %g, "speed": %g,
                  "place_at_contact": {"with": "box", "gap": 1}}},
     {"name": "box", "mesh": {"box": {"length": 200, "width": 80, "height": 60, "segments": [66, 26, 20]}},
      "restitution": 0.1, "friction": 0.5, "weight": 5000, "stiffness": {"default": {"A": 300, "B": 100}},
      "initial": {"position": [0, 0, -31], "heading": %g}}]})",
                -300 * std::cos(turn) - 10 * std::sin(turn), -300 * std::sin(turn) + 10 * std::cos(turn), heading,
                speed, heading);
  const AssessedRun ran = RunAndAssess(json, "cube_into_box.json");
  const Simulation& sim = *ran.sim;
  const RunAssessment& assessment = ran.assessment;
  CubeRun r;
  // the box's deepest crush by the end among its rest nodes within 10 in of a point across the line
  // from the box's back (where the cube comes in), its rest frame [in]
  const BodyModel& box_model = sim.engine().model(1);
  const BodyState& box_state = sim.engine().state(1);
  auto crush_near = [&](const Vec3& c) {
    double deepest = 0.0;
    for (std::size_t v = 0; v < box_model.mesh.vertices.size(); ++v) {
      const Vec3 rest = box_model.mesh.vertices[v] / u::kInch;
      if (std::abs(rest.y() - c.y()) < 10.0 && std::abs(rest.z() - c.z()) < 10.0)
        deepest = std::max(deepest, box_state.delta_max[v] / u::kInch);
    }
    return deepest;
  };
  for (const Sample& sample : sim.history()) {
    const RigidState& box = sample.bodies[1].rigid;
    const Vec3 c = box.Rotation().transpose() * (sample.bodies[0].rigid.position - box.position) / u::kInch;
    if (std::abs(c.y()) > 40.0 || std::abs(c.x()) > 100.0) continue;  // the centre outside the rest box
    // how far past the box's back (x = -100, where it came in) the centre went, beyond the crush there
    r.inside_beyond_crush = std::max(r.inside_beyond_crush, c.x() + 100.0 - crush_near(c));
  }
  for (const RunWarning& w : assessment.warnings) {
    r.inside = r.inside || w.code == "obstacle_inside";
    r.voided = r.voided || WarningVoidsResults(w.code);
  }
  std::printf("[measured] cube into box at %g mph turned %g deg: centre %.1f in past the box's back beyond the crush "
              "there, marked %d, voided %d\n", speed, heading, r.inside_beyond_crush, r.inside, r.voided);
  return r;
}

TEST(ObstacleInside, DeformableBodyThroughAnotherIsMarked) {
  const CubeRun through = RunCubeIntoBox(10.0, 90.0);
  ASSERT_GT(through.inside_beyond_crush, kReach);  // the case: through the faces, past the search's reach
  EXPECT_TRUE(through.inside);
  EXPECT_TRUE(through.voided);
  const CubeRun stopped = RunCubeIntoBox(0.0, 20.0);
  ASSERT_LT(stopped.inside_beyond_crush, kReach);
  EXPECT_FALSE(stopped.inside);
  EXPECT_FALSE(stopped.voided);
}

// the p406 (its vehicle file) at `mph` into the left side of the stationary milk truck, 12 in ahead of
// the truck's CG, placed 1 in apart: the p406's vertex deepest past the truck's rest left side where
// it lies (the first rest face a line across the truck from its left meets there: the cab is narrower
// than the box, the mirrors wider), where the run ended, against the truck's deepest crush anywhere
struct TruckRun {
  double past_side = 0.0;  // [in]
  double crush = 0.0;      // [in]
  bool inside = false;
};
TruckRun RunCarIntoTrucksSide(double mph) {
  char json[1024];
  std::snprintf(json, sizeof json, R"({"units": "US", "time": {"step": 0.0005, "duration": 1.0, "stop_at_separation": true},
      "bodies": [
        {"name": "p406", "vehicle": "vehicles/p406.json",
         "initial": {"position": [177.3, 12, -22], "heading": 180, "speed": %g, "place_at_contact": {"with": "truck", "gap": 1}}},
        {"name": "truck", "vehicle": "vehicles/milk_truck.json", "initial": {"position": [0, 0, -37], "heading": 90}}]})",
                mph);
  const AssessedRun run = RunAndAssess(json, std::string(DYMESH_DATA_DIR) + "/truck_side.json");
  const ContactEngine& engine = run.sim->engine();
  const TriMesh& truck = engine.model(1).mesh;
  const RigidState& car = engine.state(0).rigid;
  const RigidState& body = engine.state(1).rigid;
  TruckRun r;
  for (const Vec3& v : engine.state(0).vertices) {
    // in the truck's frame (x forward, y right, z down): a line along +y from far to its left
    const Vec3 q = body.Rotation().transpose() * (car.position + car.Rotation() * v - body.position);
    const Vec3 from(q.x(), -10.0, q.z());
    double side = INFINITY;
    for (const auto& t : truck.triangles) {
      double at = 0.0;
      if (SegmentCrossesTriangle(from, Vec3::UnitY(), 20.0, truck.vertices[t[0]], truck.vertices[t[1]],
                                 truck.vertices[t[2]], kSegmentSlack, &at))
        side = std::min(side, from.y() + at);
    }
    if (std::isfinite(side)) r.past_side = std::max(r.past_side, (q.y() - side) / u::kInch);
  }
  r.crush = run.summary.bodies[1].max_crush / u::kInch;
  for (const RunWarning& w : run.assessment.warnings) r.inside = r.inside || w.code == "obstacle_inside";
  std::printf("[measured] p406 into the milk truck's side at %g mph: %.1f in past its rest side, its crush %.1f in, "
              "marked %d\n", mph, r.past_side, r.crush, r.inside);
  return r;
}

// Found by a sweep of other meshes (2026-11-28): the p406 into the milk truck's side at 30 mph ended
// 38 in past the truck's rest side where the truck crushed 10 in, `complete`, no warning. The truck's
// mesh is closed but for a hole (8 open edges in 3,624 triangles), which kept it from being judged;
// judged now as a closed body. At 10 mph the car stops at the crushed side (within the reach)
TEST(ObstacleInside, ACarThroughTheMilkTrucksSideIsMarked) {
  const TruckRun through = RunCarIntoTrucksSide(30.0);
  ASSERT_GT(through.past_side - through.crush, kReach);  // the case: deeper than any crush, by more than the reach
  EXPECT_TRUE(through.inside);
  const TruckRun stopped = RunCarIntoTrucksSide(10.0);
  ASSERT_LT(stopped.past_side - stopped.crush, kReach);
  EXPECT_FALSE(stopped.inside);
}

}  // namespace
}  // namespace dymesh
