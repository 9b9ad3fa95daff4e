// Plan outlines: convex hull and a mesh's outline at a pose.
#include "dymesh/core/outline.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace dymesh {
namespace {

TEST(ConvexHull, DropsInnerCollinearAndRepeatedPoints) {
  const std::vector<Vec2> hull = ConvexHull({{0, 0}, {2, 0}, {1, 0}, {2, 2}, {0, 2}, {1, 1}, {0, 0}, {0, 1}});
  ASSERT_EQ(hull.size(), 4u);
  // counter-clockwise from the lowest-left point
  EXPECT_EQ(hull[0], Vec2(0, 0));
  EXPECT_EQ(hull[1], Vec2(2, 0));
  EXPECT_EQ(hull[2], Vec2(2, 2));
  EXPECT_EQ(hull[3], Vec2(0, 2));
  EXPECT_EQ(ConvexHull({{1, 1}, {1, 1}}).size(), 1u);
}

TEST(PlanOutline, BoxTurnedNinetyDegrees) {
  // a 4 x 2 x 1 box at (10, 5) heading 90 deg: 2 long in x, 4 long in y
  const TriMesh box = MakeBox(4.0, 2.0, 1.0, 2, 2, 2);
  RigidState pose;
  pose.position = Vec3(10, 5, -1);
  pose.yaw = 0.5 * 3.14159265358979323846;
  const std::vector<Vec2> outline = PlanOutline(box.vertices, pose);
  ASSERT_EQ(outline.size(), 4u);
  double x0 = 1e9, x1 = -1e9, y0 = 1e9, y1 = -1e9;
  for (const Vec2& p : outline) x0 = std::min(x0, p.x()), x1 = std::max(x1, p.x()), y0 = std::min(y0, p.y()), y1 = std::max(y1, p.y());
  EXPECT_NEAR(x0, 9.0, 1e-12);
  EXPECT_NEAR(x1, 11.0, 1e-12);
  EXPECT_NEAR(y0, 3.0, 1e-12);
  EXPECT_NEAR(y1, 7.0, 1e-12);
}

}  // namespace
}  // namespace dymesh
