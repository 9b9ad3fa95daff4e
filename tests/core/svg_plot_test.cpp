// SVG plots: ticks, decimation, escaping, well-formed output, plan-view scale and mirroring.
#include "dymesh/report/svg_plot.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "xml_check.h"

namespace dymesh {
namespace {

int Count(const std::string& text, const std::string& what) {
  int n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

TEST(NiceTicks, RoundStepsCoveringTheRange) {
  EXPECT_EQ(NiceTicks(0, 100, 5), (std::vector<double>{0, 20, 40, 60, 80, 100}));
  EXPECT_EQ(NiceTicks(-37, 12, 5), (std::vector<double>{-30, -20, -10, 0, 10}));
  const std::vector<double> small = NiceTicks(0.0, 0.13, 6);
  ASSERT_GE(small.size(), 3u);
  for (std::size_t k = 1; k < small.size(); ++k) EXPECT_NEAR(small[k] - small[k - 1], 0.02, 1e-12);
  EXPECT_EQ(NiceTicks(5, 5, 5).size(), 1u);  // empty range: no loop, one tick
  // a range lost in its values' round-off (an ensemble output equal in every sample to the last
  // digits: 1980 in^2 of contact area) has no step to count in: one tick, no endless loop
  EXPECT_EQ(NiceTicks(1980.0, 1980.0 + 1e-12, 6).size(), 1u);
}

TEST(DecimateMinMax, KeepsPeaksEndsAndOrder) {
  std::vector<double> x, y;
  for (int i = 0; i < 100000; ++i) {
    x.push_back(i * 1e-5);
    y.push_back(std::sin(i * 1e-3));
  }
  y[54321] = 40.0;   // a one-sample spike
  y[77777] = -40.0;
  std::vector<double> dx, dy;
  DecimateMinMax(x, y, 1000, &dx, &dy);
  EXPECT_LE(dx.size(), 1002u);
  EXPECT_EQ(dx.front(), x.front());
  EXPECT_EQ(dx.back(), x.back());
  EXPECT_EQ(*std::max_element(dy.begin(), dy.end()), 40.0);
  EXPECT_EQ(*std::min_element(dy.begin(), dy.end()), -40.0);
  EXPECT_TRUE(std::is_sorted(dx.begin(), dx.end()));
  // short series unchanged
  DecimateMinMax({0, 1, 2}, {3, 4, 5}, 1000, &dx, &dy);
  EXPECT_EQ(dy, (std::vector<double>{3, 4, 5}));
}

TEST(SvgText, EscapesAndFormats) {
  EXPECT_EQ(XmlEscape("a < b & \"c\" > d"), "a &lt; b &amp; &quot;c&quot; &gt; d");
  EXPECT_EQ(FormatFixed(-0.0001, 2), "0.00");
  EXPECT_EQ(FormatFixed(-1.25, 1), "-1.2");
  EXPECT_EQ(FormatFixed(3.14159, 3), "3.142");
}

// a scenario name, an ensemble input or a CRASH3 name with a control character made report.html
// malformed XML (found by fuzzing, 2026-11-26): XML allows none but tab, newline and CR
TEST(SvgText, ControlCharactersXmlDoesNotAllowAreShownEscaped) {
  EXPECT_EQ(XmlEscape(std::string("sp\x01" "eed\x1b[31m c\x07 ") + '\0'), "sp\\x01eed\\x1B[31m c\\x07 \\x00");
  EXPECT_EQ(XmlEscape("tab\there\nline\r"), "tab\there\nline\r");
}

TEST(RenderLinePlot, WellFormedWithEverySeriesAndMarker) {
  LinePlot p;
  p.id = "plot-test";
  p.title = "pulse <a & b>";
  p.x_label = "time [s]";
  p.y_label = "acceleration [g]";
  p.series.push_back({"x", {0, 0.1, 0.2}, {0, -20, 0}, "#1f5fbf"});
  p.series.push_back({"resultant", {0, 0.1, 0.2}, {0, 20, 0}, "#222222", true});
  p.markers.push_back({0.1, 20, "peak 20.0 g"});
  p.band = PlotBand{0.02, 0.15, "contact"};
  const std::string svg = RenderLinePlot(p);
  EXPECT_EQ(testing::XmlWellFormedError(svg), "") << svg;
  EXPECT_NE(svg.find("id=\"plot-test\""), std::string::npos);
  EXPECT_NE(svg.find("pulse &lt;a &amp; b&gt;"), std::string::npos);
  EXPECT_EQ(Count(svg, "<polyline"), 2);
  EXPECT_NE(svg.find("stroke-dasharray"), std::string::npos);
  EXPECT_NE(svg.find("peak 20.0 g"), std::string::npos);
  EXPECT_NE(svg.find("class=\"band\""), std::string::npos);
  // ticks cover the data: -20 and 20 are labelled
  EXPECT_NE(svg.find(">-20</text>"), std::string::npos);
  EXPECT_NE(svg.find(">20</text>"), std::string::npos);
}

TEST(RenderLinePlot, EmptyAndNonFiniteDataStillDraw) {
  LinePlot p;
  p.id = "plot-empty";
  p.series.push_back({"nothing", {}, {}});
  p.series.push_back({"nan", {0, 1}, {std::nan(""), 1.0}});
  const std::string svg = RenderLinePlot(p);
  EXPECT_EQ(testing::XmlWellFormedError(svg), "");
  EXPECT_EQ(svg.find("nan,"), std::string::npos);
  // values equal to their round-off draw on a unit span around them
  LinePlot flat;
  flat.id = "plot-flat";
  flat.series.push_back({"flat", {1980.0, 1980.0 + 1e-12}, {1980.0, 1980.0 + 1e-12}});
  EXPECT_EQ(testing::XmlWellFormedError(RenderLinePlot(flat)), "");
}

TEST(PlanView, OneScaleForBothAxesAndMirror) {
  PlanView view(0, 10, 0, 5, 600, 1000, false, "t", 24);
  EXPECT_NEAR(view.Px(10) - view.Px(0), (600 - 48), 1e-9);  // the width limits
  EXPECT_NEAR(view.Py(5) - view.Py(0), 0.5 * (600 - 48), 1e-9);
  EXPECT_LE(view.height(), 1000);
  PlanView mirrored(0, 10, 0, 5, 600, 1000, true, "t", 24);
  EXPECT_NEAR(mirrored.Px(0), view.Px(10), 1e-9);
  EXPECT_NEAR(mirrored.Px(10), view.Px(0), 1e-9);
  // the height limits a tall box
  PlanView tall(0, 1, 0, 10, 600, 300, false, "", 10);
  EXPECT_LE(tall.height(), 300);
  EXPECT_NEAR(tall.Py(10) - tall.Py(0), 280.0, 1e-9);
  tall.Polygon({{0, 0}, {1, 0}, {1, 10}}, "fill=\"red\"");
  tall.ScaleBar(1.0, "m");
  const std::string svg = tall.Render("plan");
  EXPECT_EQ(testing::XmlWellFormedError(svg), "") << svg;
  EXPECT_NE(svg.find("<polygon"), std::string::npos);
  EXPECT_NE(svg.find(" m</text>"), std::string::npos);
}

TEST(CrushColourBar, WellFormed) {
  const std::string svg = RenderCrushColourBar("bar", 20.8, "in", 600);
  EXPECT_EQ(testing::XmlWellFormedError(svg), "");
  EXPECT_NE(svg.find("20.8 in"), std::string::npos);
}

}  // namespace
}  // namespace dymesh
