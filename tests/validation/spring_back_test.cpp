// A node that loses the face it was pressed on springs back (spec §6) at most to the master's nearest
// surface while the bodies still close on it, and by its whole elastic part once they part. A host
// drives a deformable box 3 in into a rigid wall, then moves the wall sideways in one step so that no
// face lies ahead of the box's front nodes: the wall's side face is left 0.2 in beside the front's
// edge column. The box keeps closing (or, in the second case, backs away).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "box_at_wall.h"

namespace dymesh {
namespace {

constexpr double kSpeed = 600.0;      // [in/s] the box's approach, in and (parting) out
constexpr double kGapIn = 0.2;        // the wall's side face beside the front's edge column [in]
constexpr double kRestitution = 0.5;  // elastic part of a 3 in crush: e delta_max = 1.5 in

// one way of setting up the same physical case
struct Variant {
  const char* name;
  double dt = 0.0005;
  testing::Arrangement arrangement{};
};

// after the step the wall moves away sideways: the front nodes' largest deflection error against the
// closed form [in], and the load left on the box [lbf]
struct AfterTheWallLeaves {
  double worst_in = 0.0;
  double load_lbf = 0.0;
};

AfterTheWallLeaves Measure(const Variant& setup, bool closing) {
  testing::BoxAtWall host(testing::BarrierScenario(0.0, kRestitution, setup.dt), setup.arrangement);
  // in from 0.3 in short to 3 in, at the plan's speed
  const double advance = kSpeed * setup.dt;
  const int steps = static_cast<int>(std::lround(3.3 / advance));
  for (int k = 1; k <= steps; ++k) host.Drive(-0.3 + advance * k, kSpeed, setup.dt);
  for (int v : host.front()) EXPECT_NEAR(host.Deflection(v), 3.0, 1e-9) << setup.name;
  // the wall (40 x 400 in) jumps sideways: its -y side face ends 0.2 in beyond the front's +y edge (y = 33 in)
  host.PlaceWall(testing::kWallFaceIn + 20.0, 200.0 + 33.0 + kGapIn);
  const StepResult last = host.Drive(closing ? 3.0 + advance : 3.0 - advance, closing ? kSpeed : -kSpeed, setup.dt);
  // closing: a front node at rest y is 33.2 - y in from the wall's side face (its nearest surface: the
  // node is inside the wall's x range), so it springs min(that, 1.5 in); parting: 1.5 in
  const double elastic = kRestitution * 3.0;
  AfterTheWallLeaves out;
  for (int v : host.front()) {
    const double spring = closing ? std::min(33.0 + kGapIn - host.RestY(v), elastic) : elastic;
    out.worst_in = std::max(out.worst_in, std::abs(host.Deflection(v) - (3.0 - spring)));
  }
  // no node is on a wall face any more (the side face is 0.2 in beside the nearest): no load at all
  out.load_lbf = last.loads[0].force_earth.norm() / units::kPoundForce;
  return out;
}

TEST(SpringBack, NoFurtherThanTheSurfaceWhileClosingFreelyOnceParting) {
  // Not the local average normal: the front's edge column looks halfway between the front and the
  // side, and its ray back meets the wall's side face 0.2 in beside it within the search backoff, so
  // those nodes still count as on a face (368 lbf closing; parting, 1.2 in short of their spring:
  // README → Known limits). The polygon normal searches along each face's own normal: the edge column finds the
  // wall's side face 0.2 in away (outside); its spring, back along its crush, runs along that face, so
  // it does not meet it (it counted as touching until 2026-11-24: about 22,700 lbf on the box). The
  // spring is bounded once per step (it used to spring again with every pass: 0.4 in with two
  // passes, 0.8 in with four)
  std::vector<Variant> setups = {{"dt/2", 0.00025}, {"polygon normal, 4 passes", 0.0005, {4, SearchDirection::kPolyNormal}}};
  for (const auto& a : testing::ArrangementVariants())
    if (a.arrangement.search != SearchDirection::kLocalAverageNormal) setups.push_back({a.name, 0.0005, a.arrangement});
  for (const Variant& setup : setups) {
    const AfterTheWallLeaves closing = Measure(setup, true), parting = Measure(setup, false);
    std::printf("[measured] spring-back, %s: closing worst error %.2e in, parting %.2e in; load %.3g, %.3g lbf\n",
                setup.name, closing.worst_in, parting.worst_in, closing.load_lbf, parting.load_lbf);
    // 1e-9 in: metres converted and a point-to-face distance, far below the 0.2 in being checked
    EXPECT_LT(closing.worst_in, 1e-9) << setup.name;
    EXPECT_LT(parting.worst_in, 1e-9) << setup.name;
    // no node touches: exactly no load
    EXPECT_EQ(parting.load_lbf, 0.0) << setup.name;
    EXPECT_EQ(closing.load_lbf, 0.0) << setup.name;
  }
}

}  // namespace
}  // namespace dymesh
