#include "dymesh/core/crush_sharing.h"

#include <gtest/gtest.h>

#include <cmath>
#include <tuple>

#include "dymesh/core/node_force.h"

namespace dymesh {
namespace {

// plain numbers (unit-free); null band 0.5 as in the spec's inches
constexpr double kNullBand = 0.5;

Stiffness Law(double a, double b, double c = 0.0, double d = 0.0) {
  Stiffness k;
  k.A = a;
  k.B = b;
  k.C = c;
  k.D = d;
  return k;
}

// the pressures on the two sides after the split
double SlavePressure(const Stiffness& k, double deflection, double x) { return LoadingPressure(k, deflection + x, kNullBand); }
double MasterPressure(const Stiffness& k, double deflection, double depth, double x) {
  return LoadingPressure(k, deflection + depth - x, kNullBand);
}

TEST(CrushShare, Theta) {
  // spec §5: equal bodies split evenly; the softer slave takes the larger share
  EXPECT_DOUBLE_EQ(CrushShare(10, 3, 10, 3, 2.0), 0.5);
  const double theta = CrushShare(10, 3, 5, 1, 2.0);  // F_m = 16, F_s = 7
  EXPECT_DOUBLE_EQ(theta, 16.0 / 23.0);
  EXPECT_GT(theta, 0.5);
  // Newton's third law at the shared crush for linear laws: F_s(theta d) == F_m((1-theta) d) when A = 0
  const double d = 3.0, t = CrushShare(0, 6, 0, 2, d);
  EXPECT_DOUBLE_EQ(2 * t * d, 6 * (1 - t) * d);
}

TEST(EqualPressureShare, LinearLawsInSeries) {
  // closed form for A + B (delta - d0) on both sides, both past the null band:
  //   A_s + B_s (ds + x - d0) = A_m + B_m (dm + depth - x - d0)
  //   x = (A_m - A_s + B_m (dm + depth - d0) - B_s (ds - d0)) / (B_s + B_m)
  const Stiffness s = Law(300, 100), m = Law(300, 200);
  const double ds = 4.0, dm = 2.0, depth = 0.3;
  const double expected = (0.0 + 200 * (dm + depth - kNullBand) - 100 * (ds - kNullBand)) / 300.0;
  const double x = EqualPressureShare(s, ds, m, dm, depth, 0.5, kNullBand);
  EXPECT_NEAR(x, expected, 1e-12);
  EXPECT_NEAR(SlavePressure(s, ds, x), MasterPressure(m, dm, depth, x), 1e-9);
}

TEST(EqualPressureShare, CubicLawsAndOrderOfBodies) {
  // cubic laws: the pressures agree to round-off, and swapping the roles gives the complement
  // (at x = 0: 11.63 vs 16.09; at x = depth: 15.66 vs 12.53, so the split is inside)
  const Stiffness s = Law(10, 3, 0.5, 0.01), m = Law(8, 1, 0.2, 0.05);
  const double ds = 1.0, dm = 3.0, depth = 1.0;
  const double x = EqualPressureShare(s, ds, m, dm, depth, 0.3, kNullBand);
  EXPECT_GT(x, 0.0);
  EXPECT_LT(x, depth);
  EXPECT_NEAR(SlavePressure(s, ds, x), MasterPressure(m, dm, depth, x), 1e-10);
  const double y = EqualPressureShare(m, dm, s, ds, depth, 0.7, kNullBand);
  EXPECT_NEAR(x + y, depth, 1e-12);
}

TEST(EqualPressureShare, StifferSideTakesNone) {
  // a slave already harder than the master can become at the full depth: the master takes it all
  EXPECT_EQ(EqualPressureShare(Law(500, 100), 5.0, Law(100, 10), 0.0, 0.2, 0.5, kNullBand), 0.0);
  // and the reverse: the slave takes it all
  EXPECT_EQ(EqualPressureShare(Law(100, 10), 0.0, Law(500, 100), 5.0, 0.2, 0.5, kNullBand), 0.2);
}

TEST(EqualPressureShare, FlatLawsKeepTheta) {
  // equal A inside the null band: every split equalises, theta's is kept (Eq. 7)
  EXPECT_DOUBLE_EQ(EqualPressureShare(Law(300, 100), 0.0, Law(300, 200), 0.0, 0.2, 0.25, kNullBand), 0.05);
  // unequal A inside the null band: the softer (lower A) side crushes until its pressure reaches the other's
  const double x = EqualPressureShare(Law(300, 100), 0.4, Law(600, 100), 0.0, 0.5, 0.5, kNullBand);
  EXPECT_DOUBLE_EQ(x, 0.5);
}

TEST(EqualPressureShare, SaturatedSideTakesTheRest) {
  // the master saturated at 1.0 (held at 300 + 200 * 0.5 = 400): the slave crushes to 400 and stops
  Stiffness m = Law(300, 200);
  m.sat_crush = 1.0;
  const Stiffness s = Law(300, 100);
  const double x = EqualPressureShare(s, 0.5, m, 2.0, 3.0, 0.5, kNullBand);
  EXPECT_NEAR(SlavePressure(s, 0.5, x), 400.0, 1e-9);
  EXPECT_NEAR(x, 1.0, 1e-12);
}

TEST(SlavePartOfClosure, HardeningLayersGiveWayInverselyToTheirSlopes) {
  // series springs past the null band: dx_s / d(depth) = B_m / (B_s + B_m), whatever the crush so far
  EXPECT_NEAR(SlavePartOfClosure(Law(300, 100), 4.0, Law(300, 200), 2.0, 0.3, 0.5, kNullBand), 2.0 / 3.0, 1e-12);
  // the derivative of the equal-pressure share, by a finite difference of it (cubic laws, C and D terms)
  const Stiffness s = Law(10, 3, 0.5, 0.01), m = Law(8, 1, 0.2, 0.05);
  const double ds = 1.0, dm = 3.0, depth = 1.0, h = 1e-6;
  const double above = EqualPressureShare(s, ds, m, dm, depth + h, 0.3, kNullBand);
  const double below = EqualPressureShare(s, ds, m, dm, depth - h, 0.3, kNullBand);
  const double part = SlavePartOfClosure(s, ds, m, dm, depth, 0.3, kNullBand);
  EXPECT_NEAR(part, (above - below) / (2 * h), 1e-6);
  // the roles swapped: the parts are complements
  EXPECT_NEAR(part + SlavePartOfClosure(m, dm, s, ds, depth, 0.7, kNullBand), 1.0, 1e-9);
}

TEST(SlavePartOfClosure, FlatLayerGivesWayAloneOnlyAtItsPlateau) {
  // the slave in its null band (A 300) against a master pressing 300 + 200 (1.0 - 0.5) = 400 > 300:
  // the share puts the slave through its band first, so it takes the whole further closure
  EXPECT_EQ(SlavePartOfClosure(Law(300, 100), 0.0, Law(300, 200), 1.0, 0.2, 0.5, kNullBand), 1.0);
  // an uncrushed hard slave (A 600) against a soft master at 300 + 100 (1.0 - 0.5) = 350 < 600: the
  // slave holds, the master gives way
  EXPECT_EQ(SlavePartOfClosure(Law(600, 100), 0.0, Law(300, 100), 1.0, 0.1, 0.5, kNullBand), 0.0);
  // both in their bands at one pressure: theta's split
  EXPECT_EQ(SlavePartOfClosure(Law(300, 100), 0.0, Law(300, 200), 0.0, 0.2, 0.25, kNullBand), 0.25);
  // a saturated master (held at 400) against a hardening slave at 400: the master gives way alone
  Stiffness sat = Law(300, 200);
  sat.sat_crush = 1.0;
  EXPECT_EQ(SlavePartOfClosure(Law(300, 100), 1.5, sat, 2.0, 0.0, 0.5, kNullBand), 0.0);
}

TEST(HeldLayerPressure, FlatLayerPassesTheOtherSidesPressureOn) {
  // series layers carry one force: an uncrushed hard slave (A 600, in its null band) on a soft master
  // crushed to 1.0 (300 + 100 (1.0 - 0.5) = 350) holds and presses 350, not its own 600
  EXPECT_DOUBLE_EQ(HeldLayerPressure(Law(600, 100), 0.0, Law(300, 100), 1.0, kNullBand), 350.0);
  // a saturated slave (held at 300 + 200 * 0.5 = 400) on a master at 300 + 100 (1.3 - 0.5) = 380
  Stiffness sat = Law(300, 200);
  sat.sat_crush = 1.0;
  EXPECT_DOUBLE_EQ(HeldLayerPressure(sat, 2.0, Law(300, 100), 1.3, kNullBand), 380.0);
  // a hardening slave: the share equalised the pressures, no bound
  EXPECT_EQ(HeldLayerPressure(Law(300, 100), 1.0, Law(300, 100), 1.0, kNullBand), INFINITY);
}

TEST(ShareAtEqualPressure, OneSolveGivesTheShareItsPartAndItsBound) {
  // the three answers RestoreNode uses, from one equal-pressure solve: a hard slave in its band on a
  // softer master (it holds: push 0, part 0, pressing with the master's pressure), and two hardening laws
  for (const auto& [s, ds, m, dm, depth] : {std::tuple{Law(600, 100), 0.0, Law(300, 100), 1.0, 0.3},
                                            std::tuple{Law(10, 3, 0.5, 0.01), 1.0, Law(8, 1, 0.2, 0.05), 3.0, 1.0}}) {
    const double theta = LayerTheta(s, ds, m, dm, depth);
    const double push = EqualPressureShare(s, ds, m, dm, depth, theta, kNullBand);
    const LayerShare share = ShareAtEqualPressure(s, ds, m, dm, depth, kNullBand);
    EXPECT_EQ(share.slave_push, push);
    EXPECT_EQ(share.slave_part, SlavePartOfClosure(s, ds, m, dm, depth, theta, kNullBand));
    EXPECT_EQ(share.max_pressure, HeldLayerPressure(s, ds + push, m, dm + depth - push, kNullBand));
  }
  const LayerShare held = ShareAtEqualPressure(Law(600, 100), 0.0, Law(300, 100), 1.0, 0.3, kNullBand);
  EXPECT_EQ(held.slave_push, 0.0);
  EXPECT_EQ(held.slave_part, 0.0);
  EXPECT_DOUBLE_EQ(held.max_pressure, 300 + 100 * (1.3 - 0.5));
}

TEST(EqualPressureShare, NoDepthNoShare) {
  EXPECT_EQ(EqualPressureShare(Law(1, 1), 0.0, Law(1, 1), 0.0, 0.0, 0.5, kNullBand), 0.0);
}

}  // namespace
}  // namespace dymesh
