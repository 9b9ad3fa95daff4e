// A deformable box whose front is one quad (its nodes at the corners, outside the contact) driven into
// a finely meshed box: a face crushes only at its corners, so where the narrow box meets it the coarse
// face cannot take its equal-pressure share (spec §5) and the share stays as overlap. The run reports
// that share as the body's untaken crush and marks it (crush_not_in_mesh); a finely meshed front takes
// it with its own nodes and is not marked.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "dymesh/analysis/summary.h"
#include "run_to_end.h"
#include "test_scenarios.h"

namespace dymesh {
namespace {

namespace u = dymesh::units;

const double kNullBandIn = ContactOptions{}.null_band / units::kInch;  // the default NULL_TEST [in]
constexpr double kA = 350.0, kB = 125.0;   // [lb/in], [lb/in^2] over the conversion height 30 in

// the 180 x 120 x 60 in box `wide` (front meshed `wide_segments`, B times `wide_b_factor`) at 20 mph
// into the 180 x 66 x 30 in box `narrow` at rest (11 x 11 x 10 in cells), fronts 1 in apart, mu 0
Scenario WideIntoNarrow(std::array<int, 3> wide_segments, double wide_b_factor) {
  Scenario s = testing::UsScenario("(untaken crush test)", 0.0005, 0.5);
  BodySpec wide = testing::BoxVehicle("wide", 180, 120, 60, wide_segments, 3000, kA, kB * wide_b_factor, 30, 0.1);
  wide.initial.position = Vec3(0, 0, -20) * u::kInch;
  wide.initial.velocity = Vec3(20 * u::kMph, 0, 0);
  BodySpec narrow = testing::BoxVehicle("narrow", 180, 66, 30, {16, 6, 3}, 3000, kA, kB, 30, 0.1);
  narrow.initial.position = Vec3(181, 0, -20) * u::kInch;
  narrow.initial.yaw = 180 * u::kDegree;
  s.bodies = {wide, narrow};
  return s;
}

const BodySummary& Named(const Summary& s, const std::string& name) {
  return *std::find_if(s.bodies.begin(), s.bodies.end(), [&](const BodySummary& b) { return b.name == name; });
}

bool Marked(const Summary& s, const std::string& name) {
  return std::any_of(s.warnings.begin(), s.warnings.end(), [&](const RunWarning& w) {
    return w.code == "crush_not_in_mesh" && w.message.find("\"" + name + "\"") != std::string::npos;
  });
}

// Known answer: at maximum engagement the closure has stopped, so the narrow box's front nodes and the
// wide box's face press at one pressure, the nodes at their crush c_n and the face at its share c_w
// (spec §5): A + f B (c_w - d0) = A + B (c_n - d0), d0 the null band, f the wide box's B factor:
//   c_w = d0 + (c_n - d0) / f.
// The wide box's own nodes never crush (its front's corners lie outside the 66 x 30 in contact).
// Within 2 %: the share is the narrow box's nodes' force-weighted mean at the loaded step where it
// peaks, c_n its deepest node's crush (measured: the two agree within 0.01 in in every variant)
void ExpectShareAtEqualPressure(double wide_b_factor, const std::string& label,
                                const std::function<void(Scenario*)>& vary) {
  Scenario s = WideIntoNarrow({1, 1, 1}, wide_b_factor);
  vary(&s);
  const Summary run = testing::RunToEnd(s);
  const BodySummary &wide = Named(run, "wide"), &narrow = Named(run, "narrow");
  const double c_n = narrow.max_dynamic_crush / u::kInch;
  const double expected = kNullBandIn + (c_n - kNullBandIn) / wide_b_factor;
  std::printf("[measured] one-quad front, B x%g, %s: untaken crush %.3f in (closed form %.3f from the narrow "
              "box's %.3f in), its own nodes' %.3f in\n",
              wide_b_factor, label.c_str(), wide.untaken_crush / u::kInch, expected, c_n,
              wide.max_dynamic_crush / u::kInch);
  EXPECT_NEAR(wide.untaken_crush / u::kInch, expected, 0.02 * expected) << label;
  EXPECT_EQ(wide.max_dynamic_crush, 0.0) << label;
  EXPECT_TRUE(Marked(run, "wide")) << label;
  EXPECT_FALSE(Marked(run, "narrow")) << label;
  EXPECT_NEAR(run.energy_balance_error, 0.0, 0.02) << label;  // the bar
}

TEST(UntakenCrush, OneQuadFrontKeepsItsEqualPressureShareAndIsMarked) {
  std::vector<testing::ScenarioVariant> variants = testing::ContactVariants();
  variants.insert(variants.begin(), {"default", [](Scenario*) {}});
  variants.push_back({"narrow mesh 1:4", [](Scenario* s) { s->bodies[1].mesh.subdivisions += 1; }});
  variants.push_back({"narrow first", [](Scenario* s) { std::swap(s->bodies[0], s->bodies[1]); }});
  for (double factor : {1.0, 2.0})
    for (const auto& [label, vary] : variants) ExpectShareAtEqualPressure(factor, label, vary);
}

// The same wide box with its front meshed in 10 in cells takes its share with its own nodes: both boxes
// crush about alike (equal laws) and neither is marked. What the narrow box's nodes still find of the wide
// box's share is what its nodes take in the sibling pass, and the two meshes' different cells (10 and
// 11 in) leave between them (measured below its own crush)
TEST(UntakenCrush, FinelyMeshedFrontTakesItsShareAndIsNotMarked) {
  const Summary run = testing::RunToEnd(WideIntoNarrow({18, 12, 6}, 1.0));
  const BodySummary &wide = Named(run, "wide"), &narrow = Named(run, "narrow");
  std::printf("[measured] 10 in cells: crush %.3f / %.3f in (wide / narrow), untaken %.3f / %.3f in\n",
              wide.max_dynamic_crush / u::kInch, narrow.max_dynamic_crush / u::kInch,
              wide.untaken_crush / u::kInch, narrow.untaken_crush / u::kInch);
  EXPECT_NEAR(wide.max_dynamic_crush, narrow.max_dynamic_crush, 0.05 * narrow.max_dynamic_crush);
  EXPECT_LT(wide.untaken_crush, wide.max_dynamic_crush);
  EXPECT_FALSE(Marked(run, "wide"));
  EXPECT_FALSE(Marked(run, "narrow"));
  EXPECT_NEAR(run.energy_balance_error, 0.0, 0.02);  // the bar
}

}  // namespace
}  // namespace dymesh
