// Output files of a run: every file once, atomically, summary last; stopping between files; the
// PLY meshes' crush and colours; history.csv's header; the crush profile of a known answer.
#include "dymesh/report/output_files.h"
#include "dymesh/io/body_models.h"
#include "dymesh/analysis/summary.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "dymesh/accel/embree_locator.h"
#include "test_scenarios.h"

namespace dymesh {
namespace {

namespace fs = std::filesystem;

// one box-into-barrier run (e = 0, the closed-form case of the README), shared by the tests
class BarrierRun : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    device_ = std::make_shared<const accel::EmbreeDevice>();
    sim_ = std::make_unique<Simulation>(testing::BarrierScenario(30.0, 0.0, 0.0005), BuildBodyModels(testing::BarrierScenario(30.0, 0.0, 0.0005)), accel::MakeEmbreeLocatorFactory(device_));
    sim_->Run();
    summary_ = std::make_unique<Summary>(Summarize(*sim_));
  }
  static void TearDownTestSuite() {
    summary_.reset();
    sim_.reset();
    device_.reset();
  }
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("dymesh_results_test_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  static std::string Read(const fs::path& path) {
    std::ifstream in(path);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
  }

  static inline std::shared_ptr<const accel::EmbreeDevice> device_;
  static inline std::unique_ptr<Simulation> sim_;
  static inline std::unique_ptr<Summary> summary_;
  fs::path dir_;
};

TEST_F(BarrierRun, WritesEveryFileOnceSummaryLast) {
  const WrittenOutputs w = WriteOutputs(*sim_, *summary_, dir_.string());
  // four meshes per body, history, report, summary
  ASSERT_EQ(w.written.size(), 11u);
  EXPECT_TRUE(w.not_written.empty());
  EXPECT_EQ(fs::path(w.written.back()).filename(), "summary.json");
  for (const char* name : {"box_deformed.ply", "box_undeformed.ply", "box_deformed.obj", "wall_undeformed.obj",
                                  "history.csv", "report.html"})
    EXPECT_TRUE(fs::exists(dir_ / name)) << name;
  // no temporary file left behind
  for (const auto& entry : fs::directory_iterator(dir_)) EXPECT_NE(entry.path().extension(), ".tmp") << entry.path();
  EXPECT_EQ(nlohmann::json::parse(Read(dir_ / "summary.json"))["overall"]["status"], "complete");
}

TEST_F(BarrierRun, StopSkipsTheRestAndNoStaleSummaryRemains) {
  // an earlier run's summary must not vouch for a half-replaced folder
  fs::create_directories(dir_);
  std::ofstream(dir_ / "summary.json") << "{\"old\": true}";
  int asked = 0;
  const WrittenOutputs w = WriteOutputs(*sim_, *summary_, dir_.string(), [&] { return ++asked > 3; });
  EXPECT_EQ(w.written.size(), 3u);
  ASSERT_EQ(w.not_written.size(), 8u);
  EXPECT_EQ(fs::path(w.not_written.back()).filename(), "summary.json");
  EXPECT_FALSE(fs::exists(dir_ / "summary.json"));
  EXPECT_FALSE(fs::exists(dir_ / "report.html"));
}

TEST_F(BarrierRun, PlyCarriesCrushAndColourPerVertex) {
  WriteOutputs(*sim_, *summary_, dir_.string());
  std::ifstream in(dir_ / "box_deformed.ply");
  // header: vertex count, the crush property, colours, faces
  std::string line, header;
  while (std::getline(in, line) && line != "end_header") header += line + "\n";
  const BodyModel& model = sim_->engine().model(0);
  EXPECT_NE(header.find("element vertex " + std::to_string(model.mesh.vertices.size())), std::string::npos) << header;
  EXPECT_NE(header.find("property float crush\nproperty uchar red\nproperty uchar green\nproperty uchar blue\n"), std::string::npos);
  EXPECT_NE(header.find("element face " + std::to_string(model.mesh.triangles.size())), std::string::npos);
  // vertices: the largest crush is the summary's (in inches) and gets the end of the colour ramp; none is grey
  double largest = 0.0;
  int grey = 0;
  for (std::size_t v = 0; v < model.mesh.vertices.size(); ++v) {
    double x, y, z, crush;
    int r, g, b;
    ASSERT_TRUE(in >> x >> y >> z >> crush >> r >> g >> b);
    if (crush > largest) {
      largest = crush;
      EXPECT_EQ((std::array<int, 3>{r, g, b}), (std::array<int, 3>{120, 0, 10}));
    }
    if (crush == 0.0) {
      EXPECT_EQ((std::array<int, 3>{r, g, b}), (std::array<int, 3>{208, 208, 208}));
      ++grey;
    }
  }
  EXPECT_NEAR(largest, summary_->bodies[0].max_crush / units::kInch, 1e-6);
  EXPECT_GT(grey, 0);
  int n = 0, a, b, c;
  ASSERT_TRUE(in >> n >> a >> b >> c);
  EXPECT_EQ(n, 3);
}

TEST_F(BarrierRun, HistoryHeaderNamesEveryColumnAndUnit) {
  WriteOutputs(*sim_, *summary_, dir_.string());
  std::ifstream in(dir_ / "history.csv");
  std::string header, first;
  std::getline(in, header);
  std::getline(in, first);
  // time plus 17 quantities per body, each "name[unit]"
  std::vector<std::string> columns;
  std::stringstream ss(header);
  for (std::string c; std::getline(ss, c, ',');) columns.push_back(c);
  ASSERT_EQ(columns.size(), 1u + 17u * 2u);
  const std::regex named(R"(^[A-Za-z0-9_.]+\[[^\]]+\]$)");
  for (const std::string& c : columns) EXPECT_TRUE(std::regex_match(c, named)) << c;
  EXPECT_EQ(columns[16], "box.kinetic_energy[ft*lbf]");
  EXPECT_EQ(columns[17], "box.contact_area[in^2]");
  // kinetic energy at t = 0: 3000 lb at 30 mph
  std::vector<double> values;
  std::stringstream fs_(first);
  for (std::string c; std::getline(fs_, c, ',');) values.push_back(std::stod(c));
  EXPECT_NEAR(values[16], 0.5 * 3000 * units::kPoundMass * std::pow(30 * units::kMph, 2) / (units::kPoundForce * units::kFoot), 1e-3);
}

TEST_F(BarrierRun, CrushProfileMatchesTheClosedFormCrush) {
  // uniform full-width frontal crush: C1..C6 all near the closed-form 15.78 in, over the 66 in front
  const CrushProfile& p = summary_->bodies[0].crush_profile;
  EXPECT_EQ(p.face, CrushFace::kFront);
  EXPECT_NEAR(p.width / units::kInch, 66.0, 1e-6);
  EXPECT_NEAR(p.centre, 0.0, 1e-9);
  for (int k = 0; k < 6; ++k) EXPECT_NEAR(p.crush[k] / units::kInch, 15.782, 0.03 * 15.782) << "C" << k + 1;
  EXPECT_EQ(summary_->bodies[1].crush_profile.face, CrushFace::kNone);  // the rigid wall
}

}  // namespace
}  // namespace dymesh
