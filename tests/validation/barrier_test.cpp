// Rigid-barrier validation against the closed-form crush of the spec's force law.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "dymesh/analysis/summary.h"
#include "run_to_end.h"
#include "test_scenarios.h"

namespace dymesh {
namespace {

namespace u = dymesh::units;

// closed form: kinetic energy = work of the law over the width W,
//   E/W = A C + B (C - d0)^2 / 2   (A per width below and above the null band d0, B on the excess)
// so (B/2) x^2 + A x + (A d0 - E/W) = 0 with x = C - d0.
double ClosedFormCrushIn(double weight_lb, double speed_mph, double width_in, double a, double b, double d0) {
  const double g_in = u::kStandardGravity / u::kInch;             // [in/s^2]
  const double v = speed_mph * u::kMph / u::kInch;                 // [in/s]
  const double energy_per_width = 0.5 * (weight_lb / g_in) * v * v / width_in;  // [lbf in / in]
  const double x = (-a + std::sqrt(a * a - 2.0 * b * (a * d0 - energy_per_width))) / b;
  return x + d0;
}

Summary RunBarrier(double restitution, double time_step) {
  return testing::RunToEnd(testing::BarrierScenario(30.0, restitution, time_step));
}

TEST(Barrier, MaximumCrushMatchesClosedForm) {
  // 3000 lb, 30 mph, W = 66 in, A = 300 lb/in, B = 100 lb/in^2, null band 0.5 in: C = 15.78 in
  const double expected = ClosedFormCrushIn(3000, 30, 66, 300, 100, 0.5);
  EXPECT_NEAR(expected, 15.78, 0.01);
  const Summary s = RunBarrier(0.0, 0.0005);
  const double crush_in = s.bodies[0].max_dynamic_crush / u::kInch;
  // 3 %: the tolerance; discretisation (0.5 ms steps at 13 m/s, 0.26 in per step) is below 1 %
  EXPECT_NEAR(crush_in, expected, 0.03 * expected);
  // e = 0: all of it is permanent, the car stops dead (rebound only from the last step's impulse)
  EXPECT_NEAR(s.bodies[0].max_crush / u::kInch, expected, 0.03 * expected);
  EXPECT_LT(std::abs(s.separation_speed), 0.05 * s.closing_speed);
  // crush energy accounts for the kinetic energy lost
  EXPECT_NEAR(s.energy_balance_error, 0.0, 0.01);
  // the whole 66 x 30 in front carries the load (a third of every front triangle per corner, spec §3;
  // 1e-9: round-off of the summed triangle areas); the rigid wall has no nodes of its own in contact
  const double face = 66.0 * 30.0 * u::kInch * u::kInch;
  EXPECT_NEAR(s.bodies[0].peak_contact_area, face, 1e-9 * face);
  EXPECT_EQ(s.bodies[1].peak_contact_area, 0.0);
  std::printf("[measured] barrier e=0: crush %.3f in (closed form %.3f), energy balance %.4f %%\n", crush_in,
              expected, 100 * s.energy_balance_error);
}

TEST(Barrier, ReboundSpeedIsRestitutionTimesImpactSpeed) {
  // e = 0.2 at 0.1 ms steps: the explicit step adds at most F_peak dt / m = 0.04 m/s (1.5 % of e v)
  const double e = 0.2;
  const Summary s = RunBarrier(e, 0.0001);
  const double v = 30.0 * u::kMph;
  EXPECT_NEAR(s.closing_speed, v, 1e-9 * v);
  EXPECT_NEAR(s.separation_speed, e * v, 0.03 * e * v);
  // the crush energy is the loading work less what the rebound gave back
  EXPECT_NEAR(s.energy_balance_error, 0.0, 0.01);
  std::printf("[measured] barrier e=0.2: rebound %.4f m/s = %.4f v, energy balance %.4f %%\n", s.separation_speed,
              s.separation_speed / v, 100 * s.energy_balance_error);
}

}  // namespace
}  // namespace dymesh
