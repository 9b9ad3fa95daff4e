// An eccentric impact into a rigid frictionless wall against the impulse-momentum closed form, for
// every search direction and stop rule, at dt/2 and in a rotated frame.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <utility>

#include "dymesh/analysis/summary.h"
#include "run_to_end.h"
#include "test_scenarios.h"

namespace dymesh {
namespace {

namespace u = dymesh::units;

// a 180 x 20 x 30 in, 3000 lb box whose CG sits kArm to the left of its face centre (the front face is
// entirely to the CG's right), at 10 mph straight into a wide rigid wall; mu = 0, e = 0
constexpr double kArm = 23.0;       // [in] lateral offset of the face centre from the CG
constexpr double kSpeedMph = 10.0;

Mat3 Rz(double angle) { return BodyToEarth(0.0, 0.0, angle); }

Scenario EccentricScenario(SearchDirection direction, StopRule stop, double time_step, double frame_angle) {
  Scenario s;
  s.file = "(eccentric wall test)";
  s.units = UnitSystem::kUS;
  s.time_step = time_step;
  s.duration = 0.4;
  s.contact.search_direction = direction;
  s.contact.stop_rule = stop;
  BodySpec box = testing::BoxVehicle("box", 180, 20, 30, {1, 8, 10}, 3000, 300, 100, 30, 0.0);
  box.cg = Vec3(0, -kArm, 0) * u::kInch;
  const double m = box.mass, arm = kArm * u::kInch;
  const double izz = m * (std::pow(180 * u::kInch, 2) + std::pow(20 * u::kInch, 2)) / 12 + m * arm * arm;
  box.inertia_diagonal = Vec3(izz / 10, izz, izz);
  box.initial.velocity = Vec3(kSpeedMph * u::kMph, 0, 0);
  // the wall's face 0.5 in ahead of the box front, wide enough that no edge is ever reached
  BodySpec wall = testing::RigidWall(90.5);
  // a frame change: every pose and velocity turned about the vertical
  for (BodySpec* b : {&box, &wall}) testing::TurnAboutVertical(frame_angle, b);
  s.bodies = {box, wall};
  return s;
}

// closed form of a frictionless impact with restitution e at a point offset `arm` from the CG, normal
// to the velocity: the normal impulse P sends the contact point back at e times its closing speed,
//   v - P/m - arm^2 P / I = -e v  ->  P = (1 + e) v / (1/m + arm^2 / I);  delta-V = P/m, yaw rate = arm P / I
// while the CG leaves at P/m - v, a restitution of (P/m - v) / v at the CG
struct ClosedForm {
  double delta_v, yaw_rate, cg_restitution;  // [m/s], [rad/s], [-]
};
ClosedForm ImpulseMomentum(const BodySpec& box, double e) {
  const double v = kSpeedMph * u::kMph, arm = kArm * u::kInch, m = box.mass, izz = (*box.inertia_diagonal).z();
  const double impulse = (1 + e) * v / (1 / m + arm * arm / izz);
  return {impulse / m, arm * impulse / izz, (impulse / m - v) / v};
}

void ExpectClosedForm(SearchDirection direction, StopRule stop, double time_step, double frame_angle,
                      const char* label) {
  const Scenario scenario = EccentricScenario(direction, stop, time_step, frame_angle);
  const Summary s = testing::RunToEnd(scenario);
  const ClosedForm expected = ImpulseMomentum(scenario.bodies[0], 0.0);
  // delta-V in the wall's frame: normal (x) and tangential (y)
  const Vec3 dv = Rz(frame_angle).transpose() * s.bodies[0].delta_v_earth;
  const double yaw_rate = s.bodies[0].final_yaw_rate;
  // 10 %: the closed form takes the load at the face centre; the measured arm moves outward as the
  // box yaws (about 3 degrees during the pulse) and the crush deepens on the far side
  EXPECT_NEAR(-dv.x(), expected.delta_v, 0.10 * expected.delta_v) << label;
  EXPECT_NEAR(yaw_rate, expected.yaw_rate, 0.10 * expected.yaw_rate) << label;
  // no friction, no tangential impulse: the lateral delta-V is round-off (1 % is the bar)
  EXPECT_LT(std::abs(dv.y()), 0.01 * dv.norm()) << label;
  // the energy ledger accounts for the kinetic energy lost (2 %), and so does the node law on a
  // rigid wall (the wall cannot absorb any)
  EXPECT_NEAR(s.energy_balance_error, 0.0, 0.02) << label;
  EXPECT_NEAR(s.law_energy, s.crush_energy, 0.02 * s.crush_energy) << label;
  // the pair's account of the turn: no friction, so no friction yaw and an impulse ratio within the
  // lateral bar above; the box's yaw rate change is its whole turn (it started without one and
  // nothing else loads it), to round-off
  const PairSummary& pair = s.pairs.at(0);
  EXPECT_LT(pair.impulse_ratio, 0.01) << label;
  EXPECT_EQ(pair.friction_yaw_rate_change[0], 0.0) << label;
  EXPECT_NEAR(pair.yaw_rate_change[0], yaw_rate, 1e-9 * std::abs(yaw_rate)) << label;
  std::printf("[measured] eccentric wall %s: delta-V %.4f m/s (closed form %.4f), yaw rate %.4f rad/s (%.4f), "
              "lateral %.2e m/s, law/ledger %.4f\n",
              label, -dv.x(), expected.delta_v, yaw_rate, expected.yaw_rate, dv.y(), s.law_energy / s.crush_energy);
}

// every search method with its scenario name; the velocity search (the default) first
const struct {
  SearchDirection direction;
  const char* label;
} kSearches[] = {{SearchDirection::kVelocity, "velocity"},
                 {SearchDirection::kLocalAverageNormal, "local_average_normal"},
                 {SearchDirection::kPolyNormal, "poly_normal"},
                 {SearchDirection::kSpecified, "specified"}};

TEST(EccentricWall, EverySearchDirectionMatchesImpulseMomentum) {
  for (const auto& c : kSearches) ExpectClosedForm(c.direction, StopRule::kBestOfAll, 0.0005, 0.0, c.label);
}

TEST(EccentricWall, EveryStopRuleMatchesImpulseMomentum) {
  ExpectClosedForm(SearchDirection::kVelocity, StopRule::kAfterOne, 0.0005, 0.0, "after_one");
  ExpectClosedForm(SearchDirection::kVelocity, StopRule::kBestOfTwo, 0.0005, 0.0, "best_of_two");
}

// With restitution e the contact point leaves at e times its closing speed and the CG at
// (P/m - v) / v of it (0.119 here against e = 0.3: the CG-based restitution is not the coefficient).
// `scenario` has the box first; listed the wall first, the pair's speeds belong to the wall against
// the box: same ratios
constexpr double kRestitution = 0.3;

void ExpectPointRestitution(Scenario scenario, bool wall_first, const std::string& label) {
  const double e = kRestitution, v = kSpeedMph * u::kMph;
  scenario.bodies[0].restitution = e;
  const ClosedForm expected = ImpulseMomentum(scenario.bodies[0], e);
  if (wall_first) std::swap(scenario.bodies[0], scenario.bodies[1]);
  const Summary s = testing::RunToEnd(scenario);
  ASSERT_EQ(s.pairs.size(), 1u) << label;
  const PairSummary& p = s.pairs[0];
  const double delta_v = s.bodies[wall_first ? 1 : 0].delta_v;
  std::printf("[measured] eccentric wall e %.2f, %s%s: point restitution %.4f, CG %.4f (closed form %.4f), "
              "delta-V %.4f m/s (%.4f), balance %.2e\n", e, label.c_str(), wall_first ? ", wall first" : "",
              p.point_restitution(), p.restitution(), expected.cg_restitution, delta_v, expected.delta_v,
              s.energy_balance_error);
  // at rest before the contact, the contact point closes at the CG's speed (round-off)
  EXPECT_NEAR(p.point_closing_speed, v, 1e-9 * v) << label;
  // 10 %, the bar of the plastic case above and for the same reason: the load's arm moves as the
  // box yaws during the pulse, so the point the closed form takes is not exactly the one loaded
  EXPECT_NEAR(p.point_restitution(), e, 0.1 * e) << label;
  EXPECT_NEAR(delta_v, expected.delta_v, 0.1 * expected.delta_v) << label;
  // the CG's ratio is far from e, as the closed form says
  EXPECT_LT(p.restitution(), 0.5 * e) << label;
  // the energy ledger balances (2 %, the plastic case's bar)
  EXPECT_NEAR(s.energy_balance_error, 0.0, 0.02) << label;
}

// Every search but the velocity one (it loses this rebound: README, Known limits), in two frames and
// with either body listed first
TEST(EccentricWall, RestitutionIsMetAtTheImpactPointNotAtTheCg) {
  for (const auto& search : kSearches) {
    for (double frame : {0.0, 37.0 * u::kDegree})
      for (bool wall_first : {false, true})
        ExpectPointRestitution(EccentricScenario(search.direction, StopRule::kBestOfAll, 0.0005, frame), wall_first,
                               std::string(search.label) + (frame != 0.0 ? ", frame +37 deg" : ""));
  }
}

// The same bars at dt/2, with the box meshed 1:4, with three passes per step and with each stop rule
// (the local-normal search)
TEST(EccentricWall, RestitutionHoldsAtHalfStepFinerMeshPassCountAndStopRule) {
  const SearchDirection lan = SearchDirection::kLocalAverageNormal;
  ExpectPointRestitution(EccentricScenario(lan, StopRule::kBestOfAll, 0.00025, 0.0), false, "dt/2");
  Scenario finer = EccentricScenario(lan, StopRule::kBestOfAll, 0.0005, 0.0);
  finer.bodies[0].mesh.subdivisions += 1;
  ExpectPointRestitution(finer, false, "box mesh 1:4");
  Scenario three = EccentricScenario(lan, StopRule::kBestOfAll, 0.0005, 0.0);
  three.contact.passes_per_step = 3;
  ExpectPointRestitution(three, false, "3 passes");
  ExpectPointRestitution(EccentricScenario(lan, StopRule::kAfterOne, 0.0005, 0.0), false, "after_one");
  ExpectPointRestitution(EccentricScenario(lan, StopRule::kBestOfTwo, 0.0005, 0.0), false, "best_of_two");
}

TEST(EccentricWall, HalfTimeStepAndRotatedFrame) {
  ExpectClosedForm(SearchDirection::kVelocity, StopRule::kBestOfAll, 0.00025, 0.0, "dt/2");
  ExpectClosedForm(SearchDirection::kVelocity, StopRule::kBestOfAll, 0.0005, 37.0 * u::kDegree, "frame +37 deg");
  ExpectClosedForm(SearchDirection::kLocalAverageNormal, StopRule::kBestOfAll, 0.0005, -10.0 * u::kDegree,
                   "local normal, frame -10 deg");
}

}  // namespace
}  // namespace dymesh
