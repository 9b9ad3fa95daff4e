// A body's front corner meeting a rigid block's face that the corner node's mean normal turns away from
// (spec §2 Location: the surfaces face each other if any of the node's own faces meets the master).
// Before, the corner of a box whose side faces outweigh its front ones went into a block turned 45 deg
// unfound, and the box passed through the block (3.4-3.6 mph delta-V of 8 at dt and dt/2, in one cell
// per face or 2 x 3 x 1).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "run_to_end.h"
#include "test_scenarios.h"

namespace dymesh {
namespace {

namespace u = units;

constexpr double kSpeedMph = 8.0;

// a 144 x 52 x 30 in, 4890 lb box (8 x 8 x 3 cells: its side cells 18 in long, its front ones 6.5 in
// wide; A 476 lb/in, B 122 lb/in^2), frictionless, e = 0, at 8 mph along x into a fixed rigid block
// 126 x 48 x 27 in turned 45 deg, placed 1 in short of contact, the block's corner 6 in inside the box's
// right side: the box's right front corner meets the block's back face, turned 45 deg from its front
// and 135 deg from its side, away from the corner's mean normal
Scenario CornerScenario(const std::array<int, 3>& block_segments) {
  Scenario s = testing::UsScenario("(obstacle corner test)", 0.0005, 0.6);
  BodySpec box = testing::BoxVehicle("box", 144, 52, 30, {8, 8, 3}, 4890, 476, 122, 30, 0.0);
  box.initial.position = Vec3(-300, -7.58, 0) * u::kInch;
  box.place_at_contact = BodySpec::PlaceAtContact{1, 1.0 * u::kInch};
  box.initial.velocity = Vec3(kSpeedMph * u::kMph, 0, 0);
  BodySpec block;
  block.name = "block";
  block.mesh.box = true;
  block.mesh.box_size = Vec3(126, 48, 27) * u::kInch;
  block.mesh.box_segments = block_segments;
  block.rigid = true;
  block.motion = MotionModel::kFixed;
  block.initial.yaw = 45.0 * u::kDegree;
  s.bodies = {box, block};
  return s;
}

struct CornerRun {
  double delta_v = 0.0;  // [m/s] the box's
  double balance = 0.0;
  bool passed_through = false;
};

CornerRun RunCorner(const Scenario& s) {
  const Summary sum = testing::RunToEnd(s);
  const int box = s.bodies[0].rigid ? 1 : 0;
  CornerRun r{sum.bodies[box].delta_v, sum.energy_balance_error, false};
  for (const RunWarning& w : sum.warnings) r.passed_through = r.passed_through || w.code == "passed_through";
  return r;
}

// Known answer: the block's faces are flat, so how they are cut into triangles does not change the
// scene, and a rigid block does not let the box through. Each meshing's delta-V within 3 % of the
// finest's (16 x 6 x 3), the post tests' delta-V bar: what does change with the cutting is where the
// block's own nodes lie, and they push the box's faces where they cross them (spec §1 swapping), so
// the contact is discretised differently on the same scene; measured 1.8 % apart (before, 3.55 mph at
// one cell per face and 2 x 3 x 1, the box passing through). Energy balance within the 2 %
TEST(ObstacleCorner, BlockMeshingDoesNotChangeTheImpact) {
  const CornerRun reference = RunCorner(CornerScenario({16, 6, 3}));
  for (const std::array<int, 3>& cells : std::vector<std::array<int, 3>>{{1, 1, 1}, {2, 3, 1}, {8, 3, 1}, {16, 6, 3}}) {
    const CornerRun r = RunCorner(CornerScenario(cells));
    const std::string label = std::to_string(cells[0]) + " x " + std::to_string(cells[1]) + " x " +
                              std::to_string(cells[2]) + " block cells";
    EXPECT_FALSE(r.passed_through) << label;
    EXPECT_NEAR(r.delta_v, reference.delta_v, 0.03 * reference.delta_v) << label;
    EXPECT_NEAR(r.balance, 0.0, 0.02) << label;
    std::printf("[measured] box corner into a turned block, %s: delta-V %.3f mph (16 x 6 x 3: %.3f), balance %.4f %%\n",
                label.c_str(), r.delta_v / u::kMph, reference.delta_v / u::kMph, 100 * r.balance);
  }
}

// the same impact with the block in one cell per face across the searches, stop rules, pass counts,
// dt/2, the box meshed 1:4, body order and a turned frame: delta-V within 3 % of the finest block's at
// the default options (the bar above).
// Not the polygon-normal and local-average-normal searches, which keep the corner's mean normal (README
// known limits): with the first the box passes the block (3.94 mph delta-V of 8), with the second it
// stops 13 % short (6.89 mph). The polygon-normal search tries each face near the node along that face's
// own normal; taking any face the corner's own faces meet, it pushed the corner out through the block
TEST(ObstacleCorner, OneCellBlockForEverySearchStopRulePassCountStepOrderAndFrame) {
  const CornerRun reference = RunCorner(CornerScenario({16, 6, 3}));
  const std::vector<testing::ScenarioVariant> variants =
      testing::ContactVariantsWithMeshAndOrder("box mesh 1:4", "block first");
  for (const auto& [label, vary] : variants) {
    if (label == "polygon normal" || label == "local average normal") continue;
    Scenario s = CornerScenario({1, 1, 1});
    vary(&s);
    const CornerRun r = RunCorner(s);
    EXPECT_FALSE(r.passed_through) << label;
    EXPECT_NEAR(r.delta_v, reference.delta_v, 0.03 * reference.delta_v) << label;
    EXPECT_NEAR(r.balance, 0.0, 0.02) << label;
    std::printf("[measured] box corner into a one-cell turned block, %s: delta-V %.3f mph (%.3f)\n", label.c_str(),
                r.delta_v / u::kMph, reference.delta_v / u::kMph);
  }
}

}  // namespace
}  // namespace dymesh
