// Two deformable boxes of unequal stiffness in line: crush shared at equal pressure (spec §5's
// purpose, SMAC's rule), against the closed form, in either body order and with 2, 3 or 4 passes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

#include "dymesh/io/body_models.h"
#include "dymesh/accel/embree_locator.h"
#include "dymesh/analysis/summary.h"
#include "dymesh/core/simulation.h"
#include "test_scenarios.h"

namespace dymesh {
namespace {

namespace u = dymesh::units;

constexpr double kNullBandIn = 0.5;  // the default NULL_TEST [in]
constexpr double kHeightIn = 30.0;   // conversion height of both boxes [in]

struct Law2D {
  double a, b;  // [lb/in], [lb/in^2]
  // force per unit width of spec §3 (Eq. 1 per width) at crush c [in]
  double ForcePerWidth(double c) const { return c <= kNullBandIn ? a : a + b * (c - kNullBandIn); }
  // its work per unit width [lb in / in] from no crush to the crush where it carries f >= a: the null
  // band at a, then the line, integral of f dC = (f^2 - a^2) / (2 b)
  double WorkPerWidth(double f) const { return a * kNullBandIn + (f * f - a * a) / (2 * b); }
};

constexpr double kWidthIn = 66.0;  // the boxes' fronts, loaded whole

// The two layers in series carry one force per width f at every moment (equal pressure), so each
// side's crush work is its own law's work up to the common peak force: W_s(f) and W_h(f) above. The
// peak force is the one at which they sum to the contact work per width (e = 0: the boxes end at
// their common velocity, no rebound); found by bisection. Returns the soft side's part W_s / (W_s + W_h)
double ExpectedSoftShare(Law2D soft, Law2D hard, double work_per_width) {
  double lo = std::max(soft.a, hard.a), hi = 1e6;
  for (int i = 0; i < 200; ++i) {
    const double f = 0.5 * (lo + hi);
    (soft.WorkPerWidth(f) + hard.WorkPerWidth(f) < work_per_width ? lo : hi) = f;
  }
  const double f = 0.5 * (lo + hi);
  return soft.WorkPerWidth(f) / (soft.WorkPerWidth(f) + hard.WorkPerWidth(f));
}

// soft and hard boxes head-on at 15 mph each, fronts 1 in apart; `soft_first` picks the body order
Scenario InLine(Law2D soft, Law2D hard, bool soft_first, int passes) {
  Scenario s;
  s.file = "(unequal stiffness test)";
  s.units = UnitSystem::kUS;
  s.time_step = 0.0005;
  s.duration = 0.4;
  s.contact.passes_per_step = passes;
  BodySpec a = testing::BoxVehicle("soft", 180, 66, 30, {1, 22, 10}, 3000, soft.a, soft.b, kHeightIn, 0.0);
  a.initial.velocity = Vec3(15 * u::kMph, 0, 0);
  BodySpec b = testing::BoxVehicle("hard", 180, 66, 30, {1, 22, 10}, 3000, hard.a, hard.b, kHeightIn, 0.0);
  b.initial.position = Vec3(181, 0, 0) * u::kInch;
  b.initial.yaw = 3.14159265358979323846;
  b.initial.velocity = Vec3(-15 * u::kMph, 0, 0);
  s.bodies = soft_first ? std::vector<BodySpec>{a, b} : std::vector<BodySpec>{b, a};
  return s;
}

struct Crush {
  double soft, hard;                // [in] largest dynamic crush of each
  double soft_work, hard_work;      // [in lb] each side's crush energy (the ledger's, split)
};

Crush Run(const Scenario& scenario, bool law_accounts_for_work) {
  auto device = std::make_shared<const accel::EmbreeDevice>();
  Simulation sim(scenario, BuildBodyModels(scenario), accel::MakeEmbreeLocatorFactory(device));
  sim.Run();
  const Summary s = Summarize(sim);
  Crush c{};
  for (const BodySummary& b : s.bodies) {
    (b.name == "soft" ? c.soft : c.hard) = b.max_dynamic_crush / u::kInch;
    (b.name == "soft" ? c.soft_work : c.hard_work) = b.crush_energy / (u::kPoundForce * u::kInch);
  }
  EXPECT_NEAR(s.energy_balance_error, 0.0, 0.02);
  // flat fronts meet flat fronts: the node laws account for the contact work (2 %) at any pass count.
  // Where the sides differ in A, 5 % (measured 0.96-1.04 over 2-4 passes): the harder side's uncrushed
  // nodes report their own A while the softer side crushes at less, 4 % more contact work than
  // node-law work with 2 passes (a known limit in the README); and a second pass pair used to count
  // only the nodes the first pair's interpolation gap happened to miss (7 % over with 3 passes, 17 %
  // with 4)
  const double bar = law_accounts_for_work ? 0.02 : 0.05;
  EXPECT_NEAR(s.law_energy, s.crush_energy, bar * s.crush_energy);
  std::printf("[measured] node law / contact work %.4f\n", s.law_energy / s.crush_energy);
  return c;
}

// equal pressure at maximum engagement: a_s + b_s (C_s - d0) = a_h + b_h (C_h - d0), both past d0
void ExpectEqualPressure(Law2D soft, Law2D hard, const char* label) {
  const bool equal_a = soft.a == hard.a;
  for (int passes : {2, 3, 4}) {
    for (bool soft_first : {true, false}) {
      const Crush c = Run(InLine(soft, hard, soft_first, passes), equal_a);
      const double f_soft = soft.ForcePerWidth(c.soft), f_hard = hard.ForcePerWidth(c.hard);
      // 5 %: the bar for Newton's third law per unit width (measured under 0.5 %)
      EXPECT_NEAR(f_soft, f_hard, 0.05 * f_hard) << label << " passes " << passes << " soft first " << soft_first;
      // the closed-form crush of the soft side given the hard side's: C_s = d0 + (f_h - a_s) / b_s
      const double expected_soft = kNullBandIn + (f_hard - soft.a) / soft.b;
      EXPECT_NEAR(c.soft, expected_soft, 0.10 * expected_soft) << label;
      // each side's part of the crush energy, against the layers' closed form at the measured total;
      // 2 %, the energy bar (measured 0.1 %). Held where A is equal: where it differs the
      // harder side's uncrushed nodes press with their own A while the softer side crushes alone at
      // less (the contact work 4 % over the node laws, a known limit in the README), and that work is
      // booked to the softer side, which alone gives way then (measured +1.8 to +2.2 % over the form)
      const double total = c.soft_work + c.hard_work;
      const double expected_share = ExpectedSoftShare(soft, hard, total / kWidthIn);
      if (equal_a) {
        EXPECT_NEAR(c.soft_work / total, expected_share, 0.02 * expected_share) << label;
      }
      std::printf("[measured] %s, passes %d, soft first %d: crush %.3f / %.3f in, force per width %.1f / %.1f lb/in, "
                  "soft side's crush energy %.4f of %.0f in lb (closed form %.4f)\n",
                  label, passes, soft_first, c.soft, c.hard, f_soft, f_hard, c.soft_work / total, total, expected_share);
    }
  }
}

TEST(UnequalStiffness, DoubleBSharesAtEqualPressure) {
  // equal A, B doubled: (C_s - d0) / (C_h - d0) = 2
  ExpectEqualPressure({300, 100}, {300, 200}, "B 100 vs 200");
}

TEST(UnequalStiffness, DoubleAsharesAtEqualPressure) {
  // equal B, A doubled: C_s - C_h = (a_h - a_s) / B = 3 in
  ExpectEqualPressure({300, 100}, {600, 100}, "A 300 vs 600");
}

}  // namespace
}  // namespace dymesh
