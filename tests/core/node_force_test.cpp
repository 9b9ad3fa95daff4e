#include "dymesh/core/node_force.h"

#include <gtest/gtest.h>

namespace dymesh {
namespace {

// a cubic law in plain numbers (unit-free): A=10, B=3, C=0.5, D=0.01, null band 0.5
Stiffness Cubic() {
  Stiffness k;
  k.A = 10.0;
  k.B = 3.0;
  k.C = 0.5;
  k.D = 0.01;
  return k;
}

TEST(NodeForce, NullBandGivesConstantTerm) {
  // spec §3: below delta_0 only A acts
  EXPECT_DOUBLE_EQ(LoadingPressure(Cubic(), 0.0, 0.5), 10.0);
  EXPECT_DOUBLE_EQ(LoadingPressure(Cubic(), 0.5, 0.5), 10.0);
}

TEST(NodeForce, CubicAboveNullBand) {
  // Eq. 1 at delta = 2.5: x = 2 -> 10 + 6 + 2 + 0.08
  EXPECT_DOUBLE_EQ(LoadingPressure(Cubic(), 2.5, 0.5), 18.08);
}

TEST(NodeForce, SaturationHoldsForce) {
  // Eq. 2: beyond SatCrush = 2.5 the force stays at its value there
  Stiffness k = Cubic();
  k.sat_crush = 2.5;
  EXPECT_DOUBLE_EQ(LoadingPressure(k, 2.5, 0.5), 18.08);
  EXPECT_DOUBLE_EQ(LoadingPressure(k, 7.0, 0.5), 18.08);
  EXPECT_LT(LoadingPressure(k, 2.0, 0.5), 18.08);
}

TEST(NodeForce, ZeroAtOrBelowRelaxedDeflection) {
  // Eq. 8: e = 0.2, delta_max = 10 -> no force at or below 8
  for (ReboundLaw law : {ReboundLaw::kScaled, ReboundLaw::kLiteral}) {
    EXPECT_EQ(ReboundPressure(Cubic(), 8.0, 10.0, 0.2, 0.5, law), 0.0);
    EXPECT_EQ(ReboundPressure(Cubic(), 5.0, 10.0, 0.2, 0.5, law), 0.0);
    EXPECT_GT(ReboundPressure(Cubic(), 8.5, 10.0, 0.2, 0.5, law), 0.0);
  }
  // e = 0: fully plastic, nothing comes back
  EXPECT_EQ(ReboundPressure(Cubic(), 9.99, 10.0, 0.0, 0.5, ReboundLaw::kScaled), 0.0);
}

TEST(NodeForce, LiteralReboundIsCubicAtReboundDeflection) {
  // spec §6 as written: the cubic at delta_r = delta - (1-e) delta_max = 9 - 8 = 1
  EXPECT_DOUBLE_EQ(ReboundPressure(Cubic(), 9.0, 10.0, 0.2, 0.5, ReboundLaw::kLiteral), 10 + 3 + 0.5 + 0.01);
}

TEST(NodeForce, ScaledReboundReturnsESquaredOfLoadingWork) {
  // trapezoid integrals of loading (0..delta_max) and rebound ((1-e) delta_max..delta_max)
  const Stiffness k = Cubic();
  const double dmax = 6.0, e = 0.3;
  const int n = 200000;
  double loading = 0.0, rebound = 0.0;
  for (int i = 0; i < n; ++i) {
    const double x0 = dmax * i / n, x1 = dmax * (i + 1) / n;
    loading += 0.5 * (LoadingPressure(k, x0, 0.5) + LoadingPressure(k, x1, 0.5)) * (x1 - x0);
    const double r0 = (1 - e) * dmax + e * x0, r1 = (1 - e) * dmax + e * x1;
    rebound += 0.5 * (ReboundPressure(k, r0, dmax, e, 0.5, ReboundLaw::kScaled) +
                      ReboundPressure(k, r1, dmax, e, 0.5, ReboundLaw::kScaled)) * (r1 - r0);
  }
  // the integrands are piecewise smooth: 2e5 panels put the quadrature error far below 1e-6
  EXPECT_NEAR(rebound / loading, e * e, 1e-6);
}

TEST(NodeForce, ScaledEqualsLiteralForPureLinearLaw) {
  Stiffness k;
  k.B = 4.0;
  EXPECT_DOUBLE_EQ(ReboundPressure(k, 9.0, 10.0, 0.2, 0.0, ReboundLaw::kScaled),
                   ReboundPressure(k, 9.0, 10.0, 0.2, 0.0, ReboundLaw::kLiteral));
}

TEST(NodeForce, UnloadSlopeCapsRebound) {
  // Ku line from the peak: g(10) = 10 + 3*9.5 + 0.5*9.5^2 + 0.01*9.5^3 ; at delta = 9.9 it is g(10) - Ku*0.1
  Stiffness k = Cubic();
  k.unload_slope = 1000.0;
  const double peak = LoadingPressure(k, 10.0, 0.5);
  EXPECT_DOUBLE_EQ(ReboundPressure(k, 9.99, 10.0, 0.5, 0.5, ReboundLaw::kScaled),
                   std::min(0.5 * LoadingPressure(k, (9.99 - 5.0) / 0.5, 0.5), peak - 10.0));
  EXPECT_EQ(ReboundPressure(k, 9.0, 10.0, 0.5, 0.5, ReboundLaw::kScaled), 0.0);  // line reached zero
}

TEST(UnloadStateMachine, FullCycle) {
  ContactOptions o;
  o.unload_begin = 0.1;
  o.unload_pot = 0.01;
  o.unload_stop = 0.001;
  const double e = 0.2;
  // loading below UNLOAD_BEGIN stays plastic, then START -> CAN at the peak
  UnloadState s = NextUnloadState(UnloadState::kCannotUnload, true, 0.05, 0.05, e, o);
  EXPECT_EQ(s, UnloadState::kCannotUnload);
  s = NextUnloadState(s, true, 1.0, 1.0, e, o);
  EXPECT_EQ(s, UnloadState::kStartUnload);
  s = NextUnloadState(s, true, 1.0, 1.0, e, o);
  EXPECT_EQ(s, UnloadState::kCanUnload);
  // a drop within UNLOAD_POT is still the peak; beyond it the node unloads
  EXPECT_EQ(NextUnloadState(s, true, 0.995, 1.0, e, o), UnloadState::kCanUnload);
  s = NextUnloadState(s, true, 0.95, 1.0, e, o);
  EXPECT_EQ(s, UnloadState::kNowUnloading);
  // reaching (1-e) delta_max (+ UNLOAD_STOP) finishes unloading
  s = NextUnloadState(s, true, 0.8005, 1.0, e, o);
  EXPECT_EQ(s, UnloadState::kFinishedUnloading);
  EXPECT_EQ(NodePressure(s, true, Cubic(), 0.8005, 1.0, e, o), 0.0);
  // pushed in again: back on the rebound branch, then on the loading branch past the old peak
  s = NextUnloadState(s, true, 0.9, 1.0, e, o);
  EXPECT_EQ(s, UnloadState::kNowUnloading);
  s = NextUnloadState(s, true, 1.2, 1.2, e, o);
  EXPECT_EQ(s, UnloadState::kCanUnload);
  // losing contact ends unloading
  EXPECT_EQ(NextUnloadState(UnloadState::kNowUnloading, false, 0.9, 1.0, e, o), UnloadState::kFinishedUnloading);
}

TEST(NodeLawWork, LoadingMatchesTheClosedFormIntegral) {
  // from 0 to 3.5 across the null band: A * 3.5 + B x^2/2 + C x^3/3 + D x^4/4 with x = 3
  const Stiffness k = Cubic();
  ContactOptions o;
  o.null_band = 0.5;
  const double x = 3.0, expected = 10 * 3.5 + 3 * x * x / 2 + 0.5 * x * x * x / 3 + 0.01 * x * x * x * x / 4;
  EXPECT_NEAR(NodeLawWork(k, 0.0, 3.5, 0.0, 0.2, o), expected, 1e-12 * expected);
}

TEST(NodeLawWork, UnloadAndReloadBelowThePeakCostNothing) {
  // spec §6: below the peak the node travels its rebound curve both ways, so a cycle stores and
  // returns the same energy; only the part past the old peak is on the loading curve
  const Stiffness k = Cubic();
  ContactOptions o;
  o.null_band = 0.5;
  const double peak = 4.0, e = 0.3;
  const double out = NodeLawWork(k, peak, 3.0, peak, e, o);  // unloading: energy given back
  const double back = NodeLawWork(k, 3.0, peak, peak, e, o);
  EXPECT_LT(out, 0.0);
  EXPECT_NEAR(out + back, 0.0, 1e-12);
  // reloading past the peak: the rebound curve up to it, the loading curve beyond
  EXPECT_NEAR(NodeLawWork(k, 3.0, 5.0, peak, e, o), back + NodeLawWork(k, peak, 5.0, peak, e, o), 1e-12);
  // the relaxed part (below (1 - e) peak) carries no force (Eq. 8)
  EXPECT_EQ(NodeLawWork(k, 2.0, 2.5, peak, e, o), 0.0);
}

}  // namespace
}  // namespace dymesh
