#include "dymesh/core/geometry.h"

#include <gtest/gtest.h>

#include <cmath>

namespace dymesh {
namespace {

constexpr double kPi = 3.14159265358979323846;

TEST(InsideTriangle, InteriorEdgeVertexAndOutside) {
  const Vec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0), n(0, 0, 1);
  EXPECT_TRUE(InsideTriangleCrossProduct(Vec3(0.2, 0.2, 0), a, b, c, n));
  // points on an edge and on a vertex count as inside
  EXPECT_TRUE(InsideTriangleCrossProduct(Vec3(0.5, 0.0, 0), a, b, c, n));
  EXPECT_TRUE(InsideTriangleCrossProduct(Vec3(0.5, 0.5, 0), a, b, c, n));
  EXPECT_TRUE(InsideTriangleCrossProduct(Vec3(1.0, 0.0, 0), a, b, c, n));
  // just outside each edge
  EXPECT_FALSE(InsideTriangleCrossProduct(Vec3(0.5, -1e-6, 0), a, b, c, n));
  EXPECT_FALSE(InsideTriangleCrossProduct(Vec3(-1e-6, 0.5, 0), a, b, c, n));
  EXPECT_FALSE(InsideTriangleCrossProduct(Vec3(0.5 + 1e-6, 0.5, 0), a, b, c, n));
  // the test is on the plane projection: the height above the plane does not matter
  EXPECT_TRUE(InsideTriangleCrossProduct(Vec3(0.2, 0.2, 5.0), a, b, c, n));
}

TEST(RayPlane, DistanceAndParallel) {
  double t = 0;
  ASSERT_TRUE(RayPlaneDistance(Vec3(0, 0, -2), Vec3(0, 0, 1), Vec3(3, 4, 0), Vec3(0, 0, 1), &t));
  EXPECT_DOUBLE_EQ(t, 2.0);
  EXPECT_FALSE(RayPlaneDistance(Vec3(0, 0, -2), Vec3(1, 0, 0), Vec3(0, 0, 0), Vec3(0, 0, 1), &t));
}

TEST(Dcm, KnownRotations) {
  // yaw +90 deg: body x (forward) points along earth y (east), body y (right) along earth -x
  const Mat3 yaw = BodyToEarth(0, 0, kPi / 2);
  EXPECT_TRUE((yaw * Vec3(1, 0, 0)).isApprox(Vec3(0, 1, 0), 1e-15));
  EXPECT_TRUE((yaw * Vec3(0, 1, 0)).isApprox(Vec3(-1, 0, 0), 1e-15));
  // pitch +90 deg (nose up, z down): body x points along earth -z (up)
  EXPECT_TRUE((BodyToEarth(0, kPi / 2, 0) * Vec3(1, 0, 0)).isApprox(Vec3(0, 0, -1), 1e-15));
  // roll +90 deg (right side down): body y points along earth +z (down)
  EXPECT_TRUE((BodyToEarth(kPi / 2, 0, 0) * Vec3(0, 1, 0)).isApprox(Vec3(0, 0, 1), 1e-15));
  // the product is a proper rotation and equals Rz * Ry * Rx
  const double r = 0.3, p = -0.2, y = 1.1;
  const Mat3 m = BodyToEarth(r, p, y);
  EXPECT_NEAR(m.determinant(), 1.0, 1e-14);
  EXPECT_TRUE((m.transpose() * m).isApprox(Mat3::Identity(), 1e-14));
  const Mat3 expected = (Eigen::AngleAxisd(y, Vec3::UnitZ()) * Eigen::AngleAxisd(p, Vec3::UnitY()) *
                         Eigen::AngleAxisd(r, Vec3::UnitX())).toRotationMatrix();
  EXPECT_TRUE(m.isApprox(expected, 1e-14));
}

TEST(Dcm, EulerRatesOfPureYaw) {
  // level body turning about its z axis: only yaw changes, at the body rate
  const Vec3 rates = EulerRates(0.0, 0.0, Vec3(0, 0, 0.7));
  EXPECT_DOUBLE_EQ(rates.z(), 0.7);
  EXPECT_DOUBLE_EQ(rates.x(), 0.0);
  EXPECT_DOUBLE_EQ(rates.y(), 0.0);
}

TEST(ClosestPointOnTriangle, FaceEdgesAndCorners) {
  // the right triangle (0,0,0), (1,0,0), (0,1,0): each Voronoi region's closest point by hand
  const Vec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
  const struct {
    Vec3 p, closest;
  } cases[] = {
      {{0.2, 0.2, 1.0}, {0.2, 0.2, 0.0}},    // above the face: its foot
      {{-1.0, -1.0, 0.5}, a},                // beyond corner a
      {{2.0, -0.5, 0.0}, b},                 // beyond corner b
      {{-0.5, 3.0, 0.0}, c},                 // beyond corner c
      {{0.5, -1.0, 3.0}, {0.5, 0.0, 0.0}},   // beside edge ab
      {{1.0, 1.0, 0.0}, {0.5, 0.5, 0.0}},    // beside edge bc
      {{-1.0, 0.5, 2.0}, {0.0, 0.5, 0.0}},   // beside edge ca
  };
  for (const auto& k : cases) EXPECT_LT((ClosestPointOnTriangle(k.p, a, b, c) - k.closest).norm(), 1e-15) << k.p.transpose();
}

}  // namespace
}  // namespace dymesh
