// The demo report in headless Chromium: parses as XHTML (well-formed), logs nothing to the
// console, and every plot renders with a size and drawn shapes. Chromium comes from Debian's
// `chromium` package (scripts/setup.sh installs it).
#include <gtest/gtest.h>

#include <array>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "cli_fixture.h"
#include "process.h"

namespace dymesh {
namespace {

namespace fs = std::filesystem;
using testing::ProcessResult;

// measures every svg.plot after layout and writes "id width height shapes-with-area" lines into
// the page (only in the test's copy: the report itself has no script); `shapes` selects what counts
// as drawn
std::string RenderCheck(const std::string& shapes) {
  return R"(<script>
(function () {
  var lines = [];
  document.querySelectorAll('svg.plot').forEach(function (svg) {
    var box = svg.getBoundingClientRect(), drawn = 0;
    svg.querySelectorAll(')" + shapes + R"(').forEach(function (e) {
      var b = e.getBBox();
      if (b.width > 0 || b.height > 0) drawn++;
    });
    lines.push(svg.id + ' ' + Math.round(box.width) + ' ' + Math.round(box.height) + ' ' + drawn);
  });
  var pre = document.createElement('pre');
  pre.id = 'render-check';
  pre.textContent = lines.join('\n');
  document.body.appendChild(pre);
  console.log('render-check done');
})();
</script>)";
}

// a report made by the dymesh command, and Chromium to look at it
class ReportInBrowser : public testing::CliFixture {
 protected:
  ReportInBrowser() : CliFixture("dymesh_browser_test_") {}
  void SetUp() override {
    CliFixture::SetUp();
    chromium_ = testing::FindOnPath("chromium");
    if (chromium_.empty()) chromium_ = testing::FindOnPath("chromium-browser");
    ASSERT_FALSE(chromium_.empty()) << "chromium not found on PATH: scripts/setup.sh installs Debian's chromium";
  }

  // runs a scenario of data/scenarios into dir_/out; returns report.html's path
  fs::path MakeReport(const std::string& scenario) {
    const ProcessResult r = testing::RunProcess(
        {DYMESH_CLI, "run", std::string(DYMESH_DATA_DIR) + "/scenarios/" + scenario, "--quiet", "--out", (dir_ / "out").string()},
        dir_ / "dymesh");
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return dir_ / "out" / "report.html";
  }

  // Chromium headless on a local file with a fresh profile; extra arguments before the URL
  ProcessResult Chromium(const fs::path& page, const std::vector<std::string>& extra) {
    const fs::path profile = dir_ / ("profile" + std::to_string(++runs_));
    fs::create_directories(profile);
    std::vector<std::string> argv = {chromium_, "--headless", "--no-sandbox", "--disable-gpu", "--disable-quic",
                                     "--no-first-run", "--disable-background-networking", "--disable-component-update",
                                     "--disable-sync", "--hide-scrollbars", "--user-data-dir=" + profile.string(),
                                     "--enable-logging=stderr", "--v=0"};
    argv.insert(argv.end(), extra.begin(), extra.end());
    argv.push_back("file://" + fs::absolute(page).string());
    return testing::RunProcess(argv, dir_ / ("chromium" + std::to_string(runs_)), 90.0);
  }

  // console messages Chromium logged ("[...:INFO:CONSOLE...] "text", source: ...")
  static std::vector<std::string> ConsoleMessages(const std::string& log) {
    std::vector<std::string> messages;
    const std::regex line(R"re(:CONSOLE[^\]]*\] "(.*)", source:)re");
    for (std::sregex_iterator it(log.begin(), log.end(), line), end; it != end; ++it) messages.push_back((*it)[1]);
    return messages;
  }

  std::string chromium_;
  int runs_ = 0;
};

// the figures of the demo (p406 into a fixed rigid barrier)
const std::vector<std::string> kDemoPlots = {"plot-acceleration-p406", "plot-delta-v", "plot-force", "plot-moment",
                                             "plot-contact-area", "plot-energy", "plot-trajectories", "plot-crush-top-p406",
                                             "plot-crush-side-p406", "plot-crush-profile-p406"};

TEST_F(ReportInBrowser, DemoReportParsesAsXhtmlWithoutConsoleMessages) {
  const fs::path report = MakeReport("barrier_frontal.json");
  // the same bytes loaded as XHTML: Chromium's XML parser refuses anything not well formed
  const fs::path xhtml = dir_ / "report.xhtml";
  fs::copy_file(report, xhtml);
  const ProcessResult r = Chromium(xhtml, {"--dump-dom"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out.find("parsererror"), std::string::npos) << r.out.substr(0, 2000);
  for (const std::string& id : kDemoPlots) EXPECT_NE(r.out.find("id=\"" + id + "\""), std::string::npos) << id;
  EXPECT_NE(r.out.find("id=\"table-summary\""), std::string::npos);
  EXPECT_TRUE(ConsoleMessages(r.err).empty()) << r.err;
}

TEST_F(ReportInBrowser, EveryPlotRendersWithSizeAndShapes) {
  for (const std::string scenario : {"barrier_frontal.json", "car_to_car_side.json"}) {
    SCOPED_TRACE(scenario);
    fs::remove_all(dir_ / "out");
    std::string html = testing::ReadFile(MakeReport(scenario));
    const std::size_t body_end = html.rfind("</body>");
    ASSERT_NE(body_end, std::string::npos);
    html.insert(body_end, RenderCheck("polyline, polygon"));
    const fs::path page = dir_ / "check.html";
    std::ofstream(page) << html;
    const ProcessResult r = Chromium(page, {"--dump-dom"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    // only the check's own message: the report itself logs nothing
    EXPECT_EQ(ConsoleMessages(r.err), std::vector<std::string>{"render-check done"}) << r.err;
    // "id width height drawn" per plot
    const std::size_t start = r.out.find("<pre id=\"render-check\">");
    ASSERT_NE(start, std::string::npos) << r.out.substr(0, 2000);
    std::stringstream lines(r.out.substr(start + 23, r.out.find("</pre>", start) - start - 23));
    std::map<std::string, std::array<int, 3>> plots;
    std::string id;
    for (std::array<int, 3> v; lines >> id >> v[0] >> v[1] >> v[2];) plots[id] = v;
    std::vector<std::string> expected = {"plot-delta-v", "plot-force", "plot-moment", "plot-contact-area", "plot-energy",
                                         "plot-trajectories"};
    const std::vector<std::string> bodies = scenario == "barrier_frontal.json" ? std::vector<std::string>{"p406"}
                                                                                : std::vector<std::string>{"p406", "car1_stock"};
    for (const std::string& b : bodies)
      for (const char* kind : {"plot-acceleration-", "plot-crush-top-", "plot-crush-side-", "plot-crush-profile-"})
        expected.push_back(kind + b);
    for (const std::string& e : expected) {
      ASSERT_TRUE(plots.count(e)) << e << " missing";
      EXPECT_GT(plots[e][0], 300) << e;
      EXPECT_GT(plots[e][1], 150) << e;
      EXPECT_GT(plots[e][2], 0) << e << ": nothing drawn";
    }
  }
}

TEST_F(ReportInBrowser, EnsembleReportRendersEveryPlot) {
  // a small ensemble of the box into a wall: speed and restitution uncertain
  fs::create_directories(dir_ / "ens");
  std::ofstream(dir_ / "ens" / "spec.json") << R"({"scenario": ")" << DYMESH_DATA_DIR << R"(/scenarios/validation/box_barrier_30mph.json",
    "samples": 12, "seed": 3, "inputs": [
      {"name": "speed", "path": "bodies[0].initial.speed", "distribution": {"uniform": {"low": 25, "high": 35}}},
      {"name": "restitution", "path": "bodies[0].restitution", "distribution": {"uniform": {"low": 0, "high": 0.2}}}]})";
  const ProcessResult run = testing::RunProcess(
      {DYMESH_CLI, "ensemble", (dir_ / "ens" / "spec.json").string(), "--quiet", "--out", (dir_ / "ens" / "out").string()},
      dir_ / "dymesh");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  std::string html = testing::ReadFile(dir_ / "ens" / "out" / "report.html");
  html.insert(html.rfind("</body>"), RenderCheck("polyline, polygon, circle, rect[height=\"16\"]"));  // dots and tornado bars too
  const fs::path page = dir_ / "ensemble.html";
  std::ofstream(page) << html;
  const ProcessResult r = Chromium(page, {"--dump-dom"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(ConsoleMessages(r.err), std::vector<std::string>{"render-check done"}) << r.err;
  const std::size_t start = r.out.find("<pre id=\"render-check\">");
  ASSERT_NE(start, std::string::npos);
  std::stringstream lines(r.out.substr(start + 23, r.out.find("</pre>", start) - start - 23));
  std::map<std::string, std::array<int, 3>> plots;
  std::string id;
  for (std::array<int, 3> v; lines >> id >> v[0] >> v[1] >> v[2];) plots[id] = v;
  for (const char* e : {"plot-histogram-box-delta-v", "plot-cdf-box-delta-v", "plot-convergence-box-delta-v",
                        "plot-tornado-box-delta-v", "plot-scatter-speed-box-delta-v", "plot-scatter-restitution-box-delta-v",
                        "plot-dv-pdof-box", "plot-histogram-box-max-crush"}) {
    ASSERT_TRUE(plots.count(e)) << e << " missing";
    EXPECT_GT(plots[e][0], 300) << e;
    EXPECT_GT(plots[e][1], 80) << e;
    EXPECT_GT(plots[e][2], 0) << e << ": nothing drawn";
  }
}

TEST_F(ReportInBrowser, ScreenshotIsAPicture) {
  const fs::path report = MakeReport("barrier_frontal.json");
  const fs::path png = dir_ / "report.png";
  const ProcessResult r = Chromium(report, {"--window-size=1280,1600", "--screenshot=" + png.string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string bytes = testing::ReadFile(png);
  ASSERT_GT(bytes.size(), 20000u) << "screenshot too small to hold the plots";
  EXPECT_EQ(bytes.substr(1, 3), "PNG");
}

}  // namespace
}  // namespace dymesh
