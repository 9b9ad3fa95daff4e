// The HTML report without a browser: well-formed (XHTML-safe), self-contained, every plot present,
// the interrupted banner, units of the scenario. (tests/cli/report_browser_test.cpp renders it.)
#include "dymesh/io/body_models.h"
#include "dymesh/report/report.h"

#include <gtest/gtest.h>

#include "dymesh/accel/embree_locator.h"
#include "test_scenarios.h"
#include "xml_check.h"

namespace dymesh {
namespace {

// a run of the box barrier scenario (stopped after `steps` steps when given)
struct FinishedRun {
  std::shared_ptr<const accel::EmbreeDevice> device = std::make_shared<const accel::EmbreeDevice>();
  Simulation sim;
  Summary summary;
  explicit FinishedRun(const Scenario& s, int steps = 1 << 30)
      : sim(s, BuildBodyModels(s), accel::MakeEmbreeLocatorFactory(device)) {
    sim.Run([&](double) { return sim.steps() < steps; });
    summary = Summarize(sim);
  }
};

bool Has(const std::string& html, const std::string& what) { return html.find(what) != std::string::npos; }

TEST(Report, SelfContainedWellFormedWithEveryPlot) {
  const FinishedRun run(testing::BarrierScenario(30.0, 0.1, 0.0005));
  const std::string html = ReportHtml(run.sim, run.summary);
  EXPECT_EQ(testing::XmlWellFormedError(html), "");
  // every figure of the moving, deformable box; none for the fixed, rigid wall
  for (const char* id : {"plot-acceleration-box", "plot-delta-v", "plot-force", "plot-moment", "plot-energy",
                         "plot-contact-area", "plot-trajectories", "plot-crush-top-box", "plot-crush-side-box", "plot-crush-profile-box",
                         "table-summary", "table-overall", "table-crush-box", "crush-scale-box"})
    EXPECT_TRUE(Has(html, std::string("id=\"") + id + "\"")) << id;
  EXPECT_FALSE(Has(html, "plot-acceleration-wall"));
  EXPECT_FALSE(Has(html, "plot-crush-top-wall"));
  // nothing loaded from elsewhere: no script, no links, no imports; http only in XML namespaces
  for (const char* banned : {"<script", "src=", "href=", "@import", "<link", "<iframe"}) EXPECT_FALSE(Has(html, banned)) << banned;
  const std::string ns = "xmlns=\"http://www.w3.org/";
  for (std::size_t at = html.find("http"); at != std::string::npos; at = html.find("http", at + 1))
    EXPECT_EQ(html.compare(at - 7, ns.size(), ns), 0) << html.substr(at - 20, 60);
  for (std::size_t at = html.find("url("); at != std::string::npos; at = html.find("url(", at + 1))
    EXPECT_EQ(html[at + 4], '#') << html.substr(at, 30);
  // US units and the delta-V / PDOF annotation
  EXPECT_TRUE(Has(html, "delta-V [mph]"));
  EXPECT_TRUE(Has(html, "PDOF 0 deg (12 o'clock)"));
  EXPECT_FALSE(Has(html, "<b>status: interrupted</b>"));
}

TEST(Report, InterruptedRunSaysSoInSi) {
  Scenario s = testing::BarrierScenario(30.0, 0.1, 0.0005);
  s.units = UnitSystem::kSI;
  const FinishedRun run(s, 40);
  ASSERT_EQ(run.summary.status, dymesh::RunStatus::kInterrupted);
  const std::string html = ReportHtml(run.sim, run.summary);
  EXPECT_EQ(testing::XmlWellFormedError(html), "");
  EXPECT_TRUE(Has(html, "<b>status: interrupted</b>"));
  EXPECT_TRUE(Has(html, "<b>status: interrupted</b> at t = 0.0200 s"));
  EXPECT_TRUE(Has(html, "delta-V [m/s]"));
  EXPECT_FALSE(Has(html, "mph"));
}

TEST(Report, NamesAreEscaped) {
  Scenario s = testing::BarrierScenario(30.0, 0.1, 0.0005);
  s.name = "A <b>&amp; test</b>";
  s.bodies[0].name = "car <1>";
  const FinishedRun run(s, 5);
  const std::string html = ReportHtml(run.sim, run.summary);
  EXPECT_EQ(testing::XmlWellFormedError(html), "");
  EXPECT_TRUE(Has(html, "A &lt;b&gt;&amp;amp; test&lt;/b&gt;"));
  EXPECT_TRUE(Has(html, "id=\"plot-acceleration-car--1-\""));
}

}  // namespace
}  // namespace dymesh
