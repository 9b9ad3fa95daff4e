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
struct Arrangement {
  const char* name;
  double dt = 0.0005;
  int passes = 2;
  SearchDirection search = SearchDirection::kVelocity;
  bool wall_first = false;
  double turn_deg = 0.0;
  int refine = 1;  // the box's grid segments multiplied (2: each face cell split 1:4)
};

struct Result {
  double worst_closing_in = 0.0;  // largest |deflection - closed form| after the wall left, box closing
  double worst_parting_in = 0.0;  // the same, box backing away
};

// the front nodes' deflections [in] after the step the wall moves away sideways, against the closed form
double WorstAfterTheWallLeaves(const Arrangement& setup, bool closing) {
  Scenario s = testing::BarrierScenario(0.0, kRestitution, setup.dt);
  s.contact.passes_per_step = setup.passes;
  s.contact.search_direction = setup.search;
  s.bodies[0].mesh.box_segments = {1, 22 * setup.refine, 10 * setup.refine};
  testing::BoxAtWall host(s, setup.turn_deg, setup.wall_first);
  // in from 0.3 in short to 3 in, at the plan's speed
  const double advance = kSpeed * setup.dt;
  const int steps = static_cast<int>(std::lround(3.3 / advance));
  for (int k = 1; k <= steps; ++k) host.Drive(-0.3 + advance * k, kSpeed, setup.dt);
  for (int v : host.front()) EXPECT_NEAR(host.Deflection(v), 3.0, 1e-9) << setup.name;
  // the wall (40 x 400 in) jumps sideways: its -y side face ends 0.2 in beyond the front's +y edge (y = 33 in)
  host.PlaceWall(testing::kWallFaceIn + 20.0, 200.0 + 33.0 + kGapIn);
  host.Drive(closing ? 3.0 + advance : 3.0 - advance, closing ? kSpeed : -kSpeed, setup.dt);
  // closing: a front node at rest y is 33.2 - y in from the wall's side face (its nearest surface: the
  // node is inside the wall's x range), so it springs min(that, 1.5 in); parting: 1.5 in
  const double elastic = kRestitution * 3.0;
  double worst = 0.0;
  for (int v : host.front()) {
    const double spring = closing ? std::min(33.0 + kGapIn - host.RestY(v), elastic) : elastic;
    worst = std::max(worst, std::abs(host.Deflection(v) - (3.0 - spring)));
  }
  return worst;
}

TEST(SpringBack, NoFurtherThanTheSurfaceWhileClosingFreelyOnceParting) {
  // Not the local average normal: this box's front edge nodes never meet the wall with it. Not the
  // polygon normal: it searches along each face's own normal, so the edge column finds the wall's
  // side face 0.2 in away (outside) and springs toward it along its crush, which that gap does not
  // close, once per pass (0.4 in with two passes). Both in README → Known limits
  const Arrangement setups[] = {
      {"default"},
      {"dt/2", 0.00025},
      {"1 pass", 0.0005, 1},
      {"4 passes", 0.0005, 4},
      {"specified", 0.0005, 2, SearchDirection::kSpecified},
      {"wall listed first", 0.0005, 2, SearchDirection::kVelocity, true},
      {"frame +30 deg", 0.0005, 2, SearchDirection::kVelocity, false, 30.0},
      {"box mesh 1:4", 0.0005, 2, SearchDirection::kVelocity, false, 0.0, 2},
  };
  for (const Arrangement& setup : setups) {
    const double closing = WorstAfterTheWallLeaves(setup, true), parting = WorstAfterTheWallLeaves(setup, false);
    std::printf("[measured] spring-back, %s: closing worst error %.2e in, parting %.2e in\n", setup.name, closing,
                parting);
    // 1e-9 in: metres converted and a point-to-face distance, far below the 0.2 in being checked
    EXPECT_LT(closing, 1e-9) << setup.name;
    EXPECT_LT(parting, 1e-9) << setup.name;
  }
}

}  // namespace
}  // namespace dymesh
