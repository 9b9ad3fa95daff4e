#include "dymesh/core/stiffness.h"

#include <gtest/gtest.h>

#include "dymesh/core/units.h"

namespace dymesh {
namespace {

TEST(Stiffness, TwoDToThreeDConversion) {
  // spec §4 Eq. 3 in US units: A = 300 lb/in, B = 100 lb/in^2, H = 30 in -> 10 lb/in^2, 3.333 lb/in^3
  const Stiffness k = StiffnessFrom2D(300.0, 100.0, 30.0);
  EXPECT_DOUBLE_EQ(k.A, 10.0);
  EXPECT_DOUBLE_EQ(k.B, 100.0 / 30.0);
  EXPECT_EQ(k.C, 0.0);
  EXPECT_EQ(k.D, 0.0);
  // the same in SI: per-width N/m over m gives N/m^2, equal to 10 lb/in^2 converted
  const Stiffness si = StiffnessFrom2D(300.0 * units::PoundPerInchPow(1), 100.0 * units::PoundPerInchPow(2),
                                       30.0 * units::kInch);
  EXPECT_NEAR(si.A, 10.0 * units::PoundPerInchPow(2), 1e-9 * si.A);
  EXPECT_NEAR(si.B, (100.0 / 30.0) * units::PoundPerInchPow(3), 1e-9 * si.B);
}

TEST(Stiffness, SurfaceFromNormal) {
  EXPECT_EQ(ClassifySurface(Vec3(1, 0.2, 0)), BodySurface::kFront);
  EXPECT_EQ(ClassifySurface(Vec3(-1, 0.2, 0)), BodySurface::kBack);
  EXPECT_EQ(ClassifySurface(Vec3(0.1, 1, 0)), BodySurface::kRight);
  EXPECT_EQ(ClassifySurface(Vec3(0.1, -1, 0)), BodySurface::kLeft);
  EXPECT_EQ(ClassifySurface(Vec3(0, 0, -1)), BodySurface::kTop);  // SAE z down
  EXPECT_EQ(ClassifySurface(Vec3(0, 0, 1)), BodySurface::kBottom);
}

}  // namespace
}  // namespace dymesh
