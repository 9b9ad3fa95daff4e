// Two deformable boxes meeting front to front with a lateral offset: a box's side panel meshed as one
// long strip of triangles crushes like the same panel meshed finely along its length (spec §3's node
// area counts only the part of a face that reaches the master).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <memory>
#include <utility>

#include "dymesh/analysis/summary.h"
#include "dymesh/accel/embree_locator.h"
#include "dymesh/core/simulation.h"
#include "dymesh/io/body_models.h"
#include "test_scenarios.h"

namespace dymesh {
namespace {

namespace u = dymesh::units;

// what the offset boxes give: the summary, and each box's permanent crush at the middle of the
// overlap at mid-height (its front node nearest body-frame (90, 15.65, 0) in: the overlap runs from
// y = -1.7 to 33 in on either box) [in]
struct OffsetRun {
  Summary summary;
  std::array<double, 2> middle_crush{};
};

// equal 180 x 66 x 30 in boxes (3000 lb, A 300 lb/in, B 100 lb/in^2), 15 mph each, frictionless,
// restitution e, the second box 31.3 in to the side (34.7 in of overlap); {length, width, height}
// segments (22 x 10 across the front: 3 in cells)
OffsetRun OffsetBoxes(std::array<int, 3> segments, double e, SearchDirection search = SearchDirection::kVelocity) {
  Scenario s = testing::UsScenario("(offset boxes test)", 0.0005, 0.5);
  s.contact.search_direction = search;
  BodySpec a = testing::BoxVehicle("a", 180, 66, 30, segments, 3000, 300, 100, 30, e);
  a.initial.velocity = Vec3(15 * u::kMph, 0, 0);
  BodySpec b = testing::BoxVehicle("b", 180, 66, 30, segments, 3000, 300, 100, 30, e);
  b.initial.position = Vec3(180.5, 31.3, 0) * u::kInch;
  b.initial.yaw = 180 * u::kDegree;
  b.initial.velocity = Vec3(-15 * u::kMph, 0, 0);
  s.bodies = {a, b};
  auto device = std::make_shared<const accel::EmbreeDevice>();
  Simulation sim(s, BuildBodyModels(s), accel::MakeEmbreeLocatorFactory(device));
  sim.Run();
  OffsetRun run{Summarize(sim), {}};
  const Vec3 middle = Vec3(90, 15.65, 0) * u::kInch;
  for (int k = 0; k < 2; ++k) {
    const auto& rest = sim.engine().model(k).mesh.vertices;
    int nearest = 0;
    for (size_t v = 0; v < rest.size(); ++v)
      if ((rest[v] - middle).norm() < (rest[nearest] - middle).norm()) nearest = static_cast<int>(v);
    run.middle_crush[k] = -sim.engine().state(k).delta[nearest].x() / u::kInch;
  }
  return run;
}

// The mesh-convergence bar (2 %) on each box's delta-V, crush energy and yaw rate after, and
// the ledger's balance (2 %), between the side panels as one strip, 60 along (3 in cells) and 120
// along with 1.5 in cells across the front, without restitution; the crush in the middle of the
// overlap within 5 % (the bar this test held the deepest crush to): 10.05 / 10.06 / 10.26 in. With
// the crushed contact normal (the default until the 60th session) the middle crush is 12.45 / 12.62
// / 12.02 in and box a's yaw rate 26.3 / 24.8 / 24.7 deg/s (+6.5 %). With e = 0.1 delta-V is
// printed, not held: the pair's effective restitution along its impulse is 0.02-0.07 for the nodes'
// 0.1 (on an offset contact that slides and turns the fronts part node by node), the rebound not
// mesh-converged with either normal (delta-V strip / 3 / 1.5 in cells 15.19 / 15.22 / 15.86 mph,
// crushed normal 15.53 / 15.60 / 15.13; README, Known limits). The deepest crush (one node's peak,
// DeltaMaxTotal) is printed, not held: it lies on the contact's edges (the fronts' top and bottom
// rows meet edge on edge in one plane, and the overlap's sides), strip 12.8-13.9 in against 10.6-11.3
// on the finer meshes. Held at the default options only: with the other two searches, 3 passes or the
// stop after one, strip against 1.5 in cells, delta-V within 1.3 % and the yaw rate within 6 % (the
// polygon normal: 25.9 against 24.4 deg/s).
// (When each corner node of the fronts took a third of its neighbouring 270 in^2 side triangles as
// its area, the strip-meshed boxes crushed 5.9 in instead of 13 in, at 29 g instead of 9 g, and their
// node laws booked 49 % more than the contact work.)
TEST(OffsetBoxes, LongSidePanelsCrushLikeFinelyMeshedOnes) {
  const OffsetRun strip = OffsetBoxes({1, 22, 10}, 0.0), fine = OffsetBoxes({60, 22, 10}, 0.0),
                  finer = OffsetBoxes({120, 44, 20}, 0.0);
  for (const auto& [label, other] : {std::pair<const char*, const OffsetRun*>{"strip", &strip}, {"3 in", &fine}}) {
    for (int k = 0; k < 2; ++k) {
      const BodySummary &s = other->summary.bodies[k], &f = finer.summary.bodies[k];
      std::printf("[measured] offset boxes, e = 0, %s: delta-V %.3f / %.3f mph, crush energy %.0f / %.0f J, "
                  "middle crush %.2f / %.2f in, deepest %.2f / %.2f in at its peak, yaw rate after %.1f / %.1f deg/s "
                  "(%s / 1.5 in cells)\n",
                  s.name.c_str(), s.delta_v / u::kMph, f.delta_v / u::kMph, s.crush_energy, f.crush_energy,
                  other->middle_crush[k], finer.middle_crush[k], s.max_dynamic_crush / u::kInch,
                  f.max_dynamic_crush / u::kInch, s.final_yaw_rate / u::kDegree, f.final_yaw_rate / u::kDegree, label);
      EXPECT_NEAR(s.delta_v, f.delta_v, 0.02 * f.delta_v) << label << s.name;
      EXPECT_NEAR(s.crush_energy, f.crush_energy, 0.02 * f.crush_energy) << label << s.name;
      EXPECT_NEAR(s.final_yaw_rate, f.final_yaw_rate, 0.02 * std::abs(f.final_yaw_rate)) << label << s.name;
      EXPECT_NEAR(other->middle_crush[k], finer.middle_crush[k], 0.05 * finer.middle_crush[k]) << label << s.name;
    }
  }
  for (const OffsetRun* r : {&strip, &fine, &finer}) EXPECT_NEAR(r->summary.energy_balance_error, 0.0, 0.02);
  std::printf("[measured] offset boxes, e = 0: node law / contact work %.3f (strip), %.3f (3 in), %.3f (1.5 in)\n",
              strip.summary.law_energy / strip.summary.crush_energy, fine.summary.law_energy / fine.summary.crush_energy,
              finer.summary.law_energy / finer.summary.crush_energy);
  for (std::array<int, 3> segments : {std::array<int, 3>{1, 22, 10}, {60, 22, 10}, {120, 44, 20}}) {
    const Summary with_e = OffsetBoxes(segments, 0.1).summary;
    std::printf("[measured] offset boxes, e = 0.1, %d x %d x %d segments: delta-V %.3f mph, the pair's effective "
                "restitution %.3f\n", segments[0], segments[1], segments[2], with_e.bodies[0].delta_v / u::kMph,
                with_e.pairs.front().restitution());
  }
}

// The local-average-normal search on the same boxes: a front corner node of the strip used to take
// nearly its side's normal (the side's 270 in^2 triangles outweighed the front's by area) and its ray
// ran along the other box's front: 3.1 mph exchanged against 15.7. Weighted by angle, its normal is
// the edge's bisector on either mesh. Delta-V and crush energy within the 2 %; the deepest crush
// is not held (strip 9.8 in against 11.5-12.5: README, Known limits).
TEST(OffsetBoxes, LocalAverageNormalSearchFindsTheFrontsOnStripPanels) {
  const Summary strip = OffsetBoxes({1, 22, 10}, 0.1, SearchDirection::kLocalAverageNormal).summary;
  const Summary fine = OffsetBoxes({60, 22, 10}, 0.1, SearchDirection::kLocalAverageNormal).summary;
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
