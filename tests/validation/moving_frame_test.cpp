// A frame moving at constant velocity (a Galilean change of frame): every body given the same extra
// velocity is the same collision, seen by an observer who moves. Contact search, pushback, crush
// sharing, friction (its slide and its stick) and the ledger all read relative motion, so the
// collision's results must not depend on the common velocity.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "dymesh/analysis/summary.h"
#include "dymesh/io/scenario_json.h"
#include "run_to_end.h"
#include "test_scenarios.h"

namespace dymesh {
namespace {

namespace u = units;

// every body moves with the frame's velocity [mph] added (all bodies planar: none is fixed)
Scenario Boosted(Scenario s, double vx_mph, double vy_mph) {
  for (BodySpec& b : s.bodies) b.initial.velocity += Vec3(vx_mph, vy_mph, 0.0) * u::kMph;
  return s;
}

// two deformable boxes of different grids, 3000 lb at 30 mph into 4000 lb at rest, 20 in to the
// side (the impact turns both), with friction and restitution
Scenario EccentricBoxes() {
  Scenario s = testing::UsScenario("(moving frame test)", 0.0005, 0.5);
  BodySpec a = testing::BoxVehicle("a", 180, 66, 30, {18, 22, 10}, 3000, 300, 100, 30, 0.15);
  BodySpec b = testing::BoxVehicle("b", 180, 66, 30, {15, 20, 9}, 4000, 300, 100, 30, 0.15);
  a.friction = b.friction = 0.3;
  a.initial.velocity = Vec3(30.0 * u::kMph, 0, 0);
  b.initial.position = Vec3(181, 20, 0) * u::kInch;
  s.bodies = {a, b};
  return s;
}

// the same box into a rigid 8000 lb block that moves in the plane (the rigid contact: the block is
// always the master, and its own nodes push the box's faces)
Scenario BoxIntoRigidBlock() {
  Scenario s = testing::UsScenario("(moving frame test)", 0.0005, 0.5);
  BodySpec a = testing::BoxVehicle("a", 180, 66, 30, {18, 22, 10}, 3000, 300, 100, 30, 0.15);
  a.friction = 0.5;
  a.initial.velocity = Vec3(30.0 * u::kMph, 0, 0);
  BodySpec block;
  block.name = "block";
  block.mesh.box = true;
  block.mesh.box_size = Vec3(60, 120, 40) * u::kInch;
  block.mesh.box_segments = {2, 4, 2};
  block.mass = 8000 * u::kPoundMass;
  block.rigid = true;
  block.friction = 0.5;
  block.restitution = 0.15;
  block.initial.position = Vec3(120.5, 20, 0) * u::kInch;
  s.bodies = {a, block};
  return s;
}

// Known answer: the base frame's results. The frame enters the engine only through the bodies'
// absolute positions and velocities, whose round-off (1e-15 of them) is all that may differ; where the
// grids of two flat fronts line up, a node on the other box's face edge meets one face or its
// neighbour by round-off, and that choice grows through the nodes' crush and stick: each body's
// delta-V vector, yaw rate and deepest crush, the pair's crush and friction work and the end of the
// contact within 1e-6 of their size (measured 1e-14 on the rigid block and the car demo, up to
// 1.2e-9 of the largest yaw rate on the boxes; a friction slide read with a tenth of one body's
// velocity left out, a frame dependence, moves them 1e-2 to 0.24). Each body's part of the crush work
// within 1e-4: the face a node meets at such a tie gives its layer split (spec §5) its corners'
// crushes, not its force (measured 1.0e-5 on the boxes, 2e-15 on the car demo)
void ExpectSameCollision(const std::string& label, const Scenario& base) {
  const Summary s0 = testing::RunToEnd(base);
  double largest_yaw = 0.0, total_crush = 0.0;
  for (const BodySummary& b : s0.bodies) largest_yaw = std::max(largest_yaw, std::abs(b.final_yaw_rate));
  for (const BodySummary& b : s0.bodies) total_crush += b.crush_energy;
  ASSERT_GT(largest_yaw, 0.05) << label << ": the collision turns the bodies (the yaw rate is tested)";
  for (const Vec3& frame : {Vec3(17, 9, 0), Vec3(-40, 25, 0)}) {
    const Summary s1 = testing::RunToEnd(Boosted(base, frame.x(), frame.y()));
    char at[200];
    std::snprintf(at, sizeof at, "%s, frame moving at (%g, %g) mph", label.c_str(), frame.x(), frame.y());
    for (std::size_t i = 0; i < s0.bodies.size(); ++i) {
      const BodySummary &b0 = s0.bodies[i], &b1 = s1.bodies[i];
      EXPECT_LE((b1.delta_v_earth - b0.delta_v_earth).norm(), 1e-6 * b0.delta_v_earth.norm())
          << at << ", " << b0.name;
      EXPECT_NEAR(b1.final_yaw_rate, b0.final_yaw_rate, 1e-6 * largest_yaw) << at << ", " << b0.name;
      EXPECT_NEAR(b1.max_crush, b0.max_crush, 1e-6 * b0.max_crush) << at << ", " << b0.name;
      EXPECT_NEAR(b1.crush_energy, b0.crush_energy, 1e-4 * total_crush) << at << ", " << b0.name;
    }
    EXPECT_NEAR(s1.crush_energy, s0.crush_energy, 1e-6 * s0.crush_energy) << at;
    EXPECT_NEAR(s1.friction_energy, s0.friction_energy, 1e-6 * s0.crush_energy) << at;
    EXPECT_NEAR(s1.contact_end, s0.contact_end, 1e-6 * s0.contact_end) << at;
    EXPECT_NEAR(s1.energy_balance_error, 0.0, 1e-9) << at;
    std::printf("[measured] %s: delta-V %.12f mph (base %.12f), yaw rate %.9f deg/s (base %.9f)\n", at,
                s1.bodies[0].delta_v_earth.norm() / u::kMph, s0.bodies[0].delta_v_earth.norm() / u::kMph,
                s1.bodies[0].final_yaw_rate / u::kDegree, s0.bodies[0].final_yaw_rate / u::kDegree);
  }
}

TEST(MovingFrame, EccentricDeformableBoxesAreTheSameCollision) {
  ExpectSameCollision("eccentric boxes", EccentricBoxes());
}

TEST(MovingFrame, BoxIntoAMovingRigidBlockIsTheSameCollision) {
  ExpectSameCollision("box into rigid block", BoxIntoRigidBlock());
}

TEST(MovingFrame, CarToCarSideDemoIsTheSameCollision) {
  ExpectSameCollision("car-to-car side demo",
                      LoadScenario(std::string(DYMESH_DATA_DIR) + "/scenarios/car_to_car_side.json"));
}

}  // namespace
}  // namespace dymesh
