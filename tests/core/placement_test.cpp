// Gaps and overlaps at t = 0 against the geometry of turned boxes, and placement at contact.
#include <gtest/gtest.h>

#include <cmath>

#include "dymesh/io/body_models.h"
#include "dymesh/core/placement.h"
#include "dymesh/core/simulation.h"
#include "test_scenarios.h"

namespace dymesh {
namespace {

namespace u = units;

// the spec §4 box turned by `heading_deg`, CG at the origin, moving +x at 30 mph, wall face at x = face_in
Scenario TurnedBoxBeforeWall(double heading_deg, double face_in) {
  Scenario s = testing::BarrierScenario(30.0, 0.1, 0.0005);
  s.bodies[0].initial.yaw = heading_deg * u::kDegree;
  s.bodies[1] = testing::RigidWall(face_in);
  return s;
}

// x of the box's foremost corner when turned by the heading: 90 cos + 33 sin [in]
double ForemostCornerIn(double heading_deg) {
  const double h = heading_deg * u::kDegree;
  return 90.0 * std::cos(h) + 33.0 * std::abs(std::sin(h));
}

TEST(Placement, GapOfATurnedBoxIsItsForemostCornerToTheWall) {
  for (double heading : {0.0, 10.0, -25.0, 40.0}) {
    const Scenario s = TurnedBoxBeforeWall(heading, 100.0);
    const auto p = MeasurePlacements(s, BuildBodyModels(s));
    ASSERT_EQ(p.size(), 1u);
    EXPECT_TRUE(p[0].meet);
    EXPECT_NEAR(p[0].direction.x(), 1.0, 1e-15);
    // exact geometry: the corner vertex reaches the wall face; 1e-9 in of round-off
    EXPECT_NEAR(p[0].gap / u::kInch, 100.0 - ForemostCornerIn(heading), 1e-9) << heading;
  }
}

TEST(Placement, OverlapDepthIsHowFarTheDeepestVertexIsInside) {
  // the corner 7 in past the wall face: an overlap of 7 in, refused, or allowed with a warning
  Scenario s = TurnedBoxBeforeWall(20.0, ForemostCornerIn(20.0) - 7.0);
  const auto models = BuildBodyModels(s);
  EXPECT_NEAR(MeasurePlacements(s, models)[0].gap / u::kInch, -7.0, 1e-9);
  Scenario refused = s;
  EXPECT_THROW(PlaceBodies(&refused, models), InputError);
  s.allow_initial_overlap = true;
  PlaceBodies(&s, models);
  ASSERT_EQ(s.warnings.size(), 1u);
  EXPECT_EQ(s.warnings[0].code, "initial_overlap");
}

// a one-cell box (180 x 66 x 30 in, its CG at the origin, moving +x) and a one-cell rigid wall 40 in
// thick whose near face is at x = face_in: with the wall through the box's middle no vertex of either
// lies inside the other
Scenario OneCellBoxAndWall(double face_in) {
  Scenario s = testing::BarrierScenario(30.0, 0.1, 0.0005);
  const BodySpec moving = s.bodies[0];
  s.bodies[0] = testing::BoxVehicle("box", 180, 66, 30, {1, 1, 1}, 3000, 300, 100, 30, 0.1);
  s.bodies[0].initial = moving.initial;
  s.bodies[1] = testing::RigidWall(face_in);
  s.bodies[1].mesh.box_segments = {1, 1, 1};
  return s;
}

TEST(Placement, SurfacesThatCrossWithNoVertexInsideOverlap) {
  // found by a fuzz of the library (2026-11-28): the wall through the middle of the box read as a
  // gap of 70 in (the box's rear vertices to the wall's near face), `check` said ok and the run drove
  // the box through the wall. To come clear along the closing direction the box must move back until
  // its front face (x = 90 in) is behind the wall's near face (x = -20 in): 110 in. The diagonal of
  // the wall's near face passes through the box (between its sides y = -33 and +33 in); the middle of
  // that stretch, (-20, 0, 0), leaves the box through its front face 110 in back. The same with the
  // bodies listed either way (1e-9 in of round-off)
  Scenario s = OneCellBoxAndWall(-20.0);
  const auto models = BuildBodyModels(s);
  EXPECT_NEAR(MeasurePlacements(s, models)[0].gap / u::kInch, -110.0, 1e-9);
  Scenario swapped = s;
  std::swap(swapped.bodies[0], swapped.bodies[1]);
  EXPECT_NEAR(MeasurePlacements(swapped, BuildBodyModels(swapped))[0].gap / u::kInch, -110.0, 1e-9);
  // the scene turned 30 deg about the vertical (poses and velocity): the same overlap
  Scenario turned = s;
  const Mat3 r = Eigen::AngleAxisd(30.0 * u::kDegree, Vec3::UnitZ()).toRotationMatrix();
  for (BodySpec& b : turned.bodies) {
    b.initial.position = r * b.initial.position;
    b.initial.velocity = r * b.initial.velocity;
    b.initial.yaw += 30.0 * u::kDegree;
  }
  EXPECT_NEAR(MeasurePlacements(turned, models)[0].gap / u::kInch, -110.0, 1e-9);
  try {
    PlaceBodies(&s, models);
    ADD_FAILURE() << "the overlap was not refused";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("\"box\" and \"wall\" overlap by 110 in at t = 0"), std::string::npos) << e.what();
  }
  // flush (the box's front face on the wall's, its edges on the wall's plane or ending there): no
  // crossing, a gap of 0; and 1 in apart, 1 in
  for (double apart : {0.0, 1.0}) {
    const Scenario flush = OneCellBoxAndWall(90.0 + apart);
    EXPECT_NEAR(MeasurePlacements(flush, BuildBodyModels(flush))[0].gap / u::kInch, apart, 1e-9) << apart;
  }
}

TEST(Placement, BodiesPassingEachOtherDoNotMeet) {
  Scenario s = TurnedBoxBeforeWall(0.0, 100.0);
  s.bodies[0].initial.velocity = Vec3(0, 10, 0);  // along the wall
  s.bodies[0].initial.position = Vec3(0, -500, 0) * u::kInch;
  const auto p = MeasurePlacements(s, BuildBodyModels(s));
  EXPECT_FALSE(p[0].meet);
}

TEST(Placement, PlaceAtContactLeavesTheRequestedGapAlongTheRelativeVelocity) {
  // two boxes, the struck one moving too: placement is along the relative velocity
  Scenario s = TurnedBoxBeforeWall(15.0, 100.0);
  BodySpec other = testing::BoxVehicle("other", 180, 66, 30, {1, 22, 10}, 3000, 300, 100, 30, 0.1);
  other.initial.position = Vec3(400, -100, 0) * u::kInch;
  other.initial.yaw = 90.0 * u::kDegree;
  other.initial.velocity = Vec3(0, 5, 0);
  s.bodies[1] = other;
  s.bodies[0].place_at_contact = BodySpec::PlaceAtContact{1, 0.5 * u::kInch};
  const auto models = BuildBodyModels(s);
  const Vec3 start = s.bodies[0].initial.position;
  const auto p = PlaceBodies(&s, models);
  EXPECT_NEAR(p[0].gap / u::kInch, 0.5, 1e-9);
  const Vec3 moved = s.bodies[0].initial.position - start;
  const Vec3 relative = (s.bodies[0].initial.velocity - s.bodies[1].initial.velocity).normalized();
  EXPECT_NEAR(moved.normalized().dot(relative), 1.0, 1e-12);
}

// found by a sweep of other meshes (2026-11-28): a coarse car placed 1 in from the milk truck ended
// 5.2 in into it and the run was refused ("use place_at_contact"): an edge met an edge before any
// vertex met a face. Two one-cell boxes 40 in long and high: the moving one, 60 in wide, pitched 45 deg
// (its leading edge across the motion, level, 20 sqrt 2 in ahead of its CG, its ends beside the other
// box), the struck one, 40 in wide, yawed 45 deg (its corner edge toward the other, upright, 20 sqrt 2
// in behind its CG): the edges cross at their middles, so the boxes touch when their CGs are 40 sqrt 2
// in apart; the vertices alone touch 20 in later, where the corner edge's ends meet the pitched box's
// sloping faces. Placed 1 in apart: 40 sqrt 2 + 1 in between the CGs (round-off bar), and the run
// starts (the overlap check does not refuse it)
TEST(Placement, PlaceAtContactStopsWhereAnEdgeMeetsAnEdge) {
  Scenario s = testing::BarrierScenario(30.0, 0.1, 0.0005);
  const BodySpec moving = s.bodies[0];
  s.bodies[0] = testing::BoxVehicle("pitched", 40, 60, 40, {1, 1, 1}, 3000, 300, 100, 30, 0.1);
  s.bodies[0].initial = moving.initial;
  s.bodies[0].initial.pitch = 45.0 * u::kDegree;
  s.bodies[1] = testing::BoxVehicle("yawed", 40, 40, 40, {1, 1, 1}, 3000, 300, 100, 30, 0.1);
  s.bodies[1].initial = moving.initial;
  s.bodies[1].initial.velocity = Vec3::Zero();
  s.bodies[1].initial.position.x() = 300.0 * u::kInch;
  s.bodies[1].initial.yaw = 45.0 * u::kDegree;
  s.bodies[0].place_at_contact = BodySpec::PlaceAtContact{1, 1.0 * u::kInch};
  const auto models = BuildBodyModels(s);
  EXPECT_NO_THROW(PlaceBodies(&s, models));
  const double apart = (s.bodies[1].initial.position - s.bodies[0].initial.position).norm() / u::kInch;
  EXPECT_NEAR(apart, 40.0 * std::sqrt(2.0) + 1.0, 1e-9);
}

TEST(Cylinder, ClosedOutwardAndOfTheRightVolume) {
  const TriMesh c = MakeCylinder(0.15, 3.0, 32);
  const MeshStats s = ComputeStats(c);
  EXPECT_EQ(s.open_edges, 0);
  EXPECT_EQ(s.nonmanifold_edges, 0);
  EXPECT_EQ(CountDuplicateFaces(c), 0);
  // a 32-gon prism: (n/2) r^2 sin(2 pi / n) h, exactly
  const double expected = 16.0 * 0.15 * 0.15 * std::sin(2.0 * 3.14159265358979323846 / 32.0) * 3.0;
  EXPECT_NEAR(SignedVolume(c), expected, 1e-12);
  EXPECT_EQ(CylinderRows(0.15, 3.0, 32), static_cast<int>(std::lround(3.0 / (0.3 * std::sin(3.14159265358979323846 / 32)))));
}

TEST(DuplicateFaces, CountsRepeatsInAnyWindingAndNamesTheFirst) {
  TriMesh m = MakeBox(1, 1, 1, 1, 1, 1);
  EXPECT_EQ(CountDuplicateFaces(m), 0);
  const auto t = m.triangles[3];
  m.triangles.push_back({t[0], t[2], t[1]});  // reversed
  m.triangles.push_back(t);                   // same
  std::array<int, 2> first{};
  EXPECT_EQ(CountDuplicateFaces(m, &first), 2);
  EXPECT_EQ(first[1], 3);
  EXPECT_EQ(first[0], 12);
}

}  // namespace
}  // namespace dymesh
