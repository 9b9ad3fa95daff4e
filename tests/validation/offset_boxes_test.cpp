// Two deformable boxes meeting front to front with a lateral offset: a box's side panel meshed as one
// long strip of triangles crushes like the same panel meshed finely along its length (spec §3's node
// area counts only the part of a face that reaches the master).
#include <gtest/gtest.h>

#include <cstdio>

#include "dymesh/analysis/summary.h"
#include "run_to_end.h"
#include "test_scenarios.h"

namespace dymesh {
namespace {

namespace u = dymesh::units;

// equal 180 x 66 x 30 in boxes (3000 lb, A 300 lb/in, B 100 lb/in^2), 15 mph each, frictionless,
// e = 0.1, the second box 31.3 in to the side (34.7 in of overlap); `length_segments` along x
Summary OffsetBoxes(int length_segments, SearchDirection search = SearchDirection::kVelocity) {
  Scenario s = testing::UsScenario("(offset boxes test)", 0.0005, 0.5);
  s.contact.search_direction = search;
  BodySpec a = testing::BoxVehicle("a", 180, 66, 30, {length_segments, 22, 10}, 3000, 300, 100, 30, 0.1);
  a.initial.velocity = Vec3(15 * u::kMph, 0, 0);
  BodySpec b = testing::BoxVehicle("b", 180, 66, 30, {length_segments, 22, 10}, 3000, 300, 100, 30, 0.1);
  b.initial.position = Vec3(180.5, 31.3, 0) * u::kInch;
  b.initial.yaw = 180 * u::kDegree;
  b.initial.velocity = Vec3(-15 * u::kMph, 0, 0);
  s.bodies = {a, b};
  return testing::RunToEnd(s);
}

// The mesh-convergence bar (2 %) on each box's delta-V and crush energy, and the ledger's
// balance (2 %). The deepest crush within 5 %: it is one node's, on a 3 in grid across the front;
// its peak (DeltaMaxTotal), which the meshes resolve. The permanent crush is printed, not held: the
// deepest node's peak less the spring it got back, all of e delta_max (spec §6) if it kept a face as
// the boxes parted, less if it lost it first, which one node's contact decides (at this start the
// fine boxes' deepest node springs its whole 10 %, 11.91 of 13.24 in, while 0.02 in to either side
// it keeps 13.3-13.6; the strip's springs 7-10 %)
// Held at these default options only: across other options the two meshings differ by 0.2-6 % in
// delta-V (README, Known limits).
// (When each corner node of the fronts took a third of its neighbouring 270 in^2 side triangles as
// its area, the strip-meshed boxes crushed 5.9 in instead of 13 in, at 29 g instead of 9 g, and their
// node laws booked 49 % more than the contact work.)
TEST(OffsetBoxes, LongSidePanelsCrushLikeFinelyMeshedOnes) {
  const Summary strip = OffsetBoxes(1), fine = OffsetBoxes(60);
  for (int k = 0; k < 2; ++k) {
    const BodySummary &s = strip.bodies[k], &f = fine.bodies[k];
    std::printf("[measured] offset boxes, %s: delta-V %.3f / %.3f mph, crush energy %.0f / %.0f J, deepest crush "
                "%.2f / %.2f in at its peak, %.2f / %.2f in permanent, yaw rate after %.1f / %.1f deg/s (side panels "
                "as one strip / 60 along)\n",
                s.name.c_str(), s.delta_v / u::kMph, f.delta_v / u::kMph, s.crush_energy, f.crush_energy,
                s.max_dynamic_crush / u::kInch, f.max_dynamic_crush / u::kInch, s.max_crush / u::kInch,
                f.max_crush / u::kInch, s.final_yaw_rate / u::kDegree, f.final_yaw_rate / u::kDegree);
    EXPECT_NEAR(s.delta_v, f.delta_v, 0.02 * f.delta_v) << s.name;
    EXPECT_NEAR(s.crush_energy, f.crush_energy, 0.02 * f.crush_energy) << s.name;
    EXPECT_NEAR(s.max_dynamic_crush, f.max_dynamic_crush, 0.05 * f.max_dynamic_crush) << s.name;
  }
  std::printf("[measured] offset boxes: node law / contact work %.3f (strip), %.3f (fine)\n",
              strip.law_energy / strip.crush_energy, fine.law_energy / fine.crush_energy);
  EXPECT_NEAR(strip.energy_balance_error, 0.0, 0.02);
  EXPECT_NEAR(fine.energy_balance_error, 0.0, 0.02);
}

// The local-average-normal search on the same boxes: a front corner node of the strip used to take
// nearly its side's normal (the side's 270 in^2 triangles outweighed the front's by area) and its ray
// ran along the other box's front: 3.1 mph exchanged against 15.7. Weighted by angle, its normal is
// the edge's bisector on either mesh. Delta-V and crush energy within the 2 %; the deepest crush
// is not held (strip 9.8 in against 11.5-12.5: README, Known limits).
TEST(OffsetBoxes, LocalAverageNormalSearchFindsTheFrontsOnStripPanels) {
  const Summary strip = OffsetBoxes(1, SearchDirection::kLocalAverageNormal);
  const Summary fine = OffsetBoxes(60, SearchDirection::kLocalAverageNormal);
  for (int k = 0; k < 2; ++k) {
    const BodySummary &s = strip.bodies[k], &f = fine.bodies[k];
    std::printf("[measured] offset boxes, local average normal, %s: delta-V %.3f / %.3f mph, crush energy %.0f / "
                "%.0f J (strip / 60 along)\n",
                s.name.c_str(), s.delta_v / u::kMph, f.delta_v / u::kMph, s.crush_energy, f.crush_energy);
    EXPECT_NEAR(s.delta_v, f.delta_v, 0.02 * f.delta_v) << s.name;
    EXPECT_NEAR(s.crush_energy, f.crush_energy, 0.02 * f.crush_energy) << s.name;
  }
  EXPECT_NEAR(strip.energy_balance_error, 0.0, 0.02);
  EXPECT_NEAR(fine.energy_balance_error, 0.0, 0.02);
}

}  // namespace
}  // namespace dymesh
