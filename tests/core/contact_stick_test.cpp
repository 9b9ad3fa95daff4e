#include "dymesh/core/contact_stick.h"

#include <gtest/gtest.h>

namespace dymesh {
namespace {

// exact arithmetic on these plain numbers: one multiply and a scale; 1e-15 is their round-off
constexpr double kRoundOff = 1e-15;

TEST(StickingCorrection, FrictionlessFacesOnlyPushAlongTheirNormal) {
  // mu = 0: nothing along the face, whatever the slide (the frictionless wall's law)
  EXPECT_EQ(StickingCorrection(Vec3(0.3, -0.2, 0.0), 0.1, 0.1, 0.0), Vec3::Zero());
  // no push (the node bottomed out at its maximum crush, or no depth): no friction to hold it
  EXPECT_EQ(StickingCorrection(Vec3(0.3, 0.0, 0.0), 0.0, 0.1, 0.5), Vec3::Zero());
  EXPECT_EQ(StickingCorrection(Vec3(0.3, 0.0, 0.0), 0.1, 0.0, 0.5), Vec3::Zero());
}

TEST(StickingCorrection, InsideTheConeTheNodeTakesItsShareOfTheSlipBack) {
  // rigid master: the node takes the whole push (push = depth) and so the whole slip, 0.02 < mu push
  const Vec3 slide(0.02, 0.0, 0.0);
  EXPECT_LT((StickingCorrection(slide, 0.1, 0.1, 0.5) + slide).norm(), kRoundOff);
  // two deformable sides: the slave pushes 30 % of the depth and takes 30 % of the slip back
  EXPECT_LT((StickingCorrection(slide, 0.03, 0.1, 0.5) + 0.3 * slide).norm(), kRoundOff);
}

TEST(StickingCorrection, BeyondTheConeFrictionHoldsMuTimesThePush) {
  // a slip of 1.0 against a push of 0.1 at mu 0.4: the correction is 0.04 long, against the slip
  const Vec3 slide(0.6, 0.8, 0.0);
  const Vec3 c = StickingCorrection(slide, 0.1, 0.1, 0.4);
  EXPECT_NEAR(c.norm(), 0.04, kRoundOff);
  EXPECT_NEAR(c.dot(slide) / slide.norm(), -0.04, kRoundOff);
}

}  // namespace
}  // namespace dymesh
