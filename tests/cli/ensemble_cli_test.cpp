// dymesh ensemble through the command: byte-identical outputs at 1 and 2 threads and across
// shards, resume after SIGKILL, replay equal to its record, clear errors for bad specs.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>
#include <utility>
#include <vector>

#include "../ensemble/box_spec.h"
#include "cli_fixture.h"
#include "coarse_boxes.h"
#include "process.h"
#include "xml_check.h"

namespace {

using dymesh::testing::ProcessResult;
using dymesh::testing::ReadFile;
namespace fs = std::filesystem;

class Ensemble : public dymesh::testing::CliFixture {
 protected:
  Ensemble() : CliFixture("dymesh_ensemble_test_") {}
  // the box spec with a loose 10 % stop tolerance: checkpoints at 8, 16, 32, 64 samples
  std::string WriteStopToleranceSpec() const {
    const std::string path = dymesh::testing::WriteBoxSpec(dir_, 64, "monte_carlo");
    std::string text = ReadFile(path);
    text.insert(text.rfind('}'), R"(, "stop_tolerance": {"relative": 0.1, "min_samples": 8})");
    std::ofstream(path) << text;
    return path;
  }
#ifdef DYMESH_MPIEXEC
  // `spec` under mpirun at each rank count: samples.jsonl, ensemble.json and report.html byte for
  // byte those in `reference`
  void ExpectSameBytesOnRanks(const std::string& spec, const std::vector<const char*>& ranks,
                              const fs::path& reference) const {
    // OpenMPI refuses root unless told; CI runs as root
    setenv("OMPI_ALLOW_RUN_AS_ROOT", "1", 1);
    setenv("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1", 1);
    for (const char* n : ranks) {
      const fs::path out = dir_ / (std::string("ranks") + n);
      const ProcessResult r = dymesh::testing::RunProcess(
          {DYMESH_MPIEXEC, "--oversubscribe", "-np", n, DYMESH_CLI, "ensemble", spec, "--quiet", "--out", out.string()},
          dir_ / "process", 300.0);
      ASSERT_EQ(r.exit_code, 0) << n << " ranks\n" << r.err;
      for (const char* name : {"samples.jsonl", "ensemble.json", "report.html"})
        EXPECT_EQ(ReadFile(out / name), ReadFile(reference / name)) << n << " ranks: " << name;
    }
  }
#endif
  // line `index` of a samples.jsonl
  static std::string Line(const fs::path& file, int index) {
    std::istringstream in(ReadFile(file));
    std::string line;
    for (int i = 0; i <= index; ++i) std::getline(in, line);
    return line;
  }
};

TEST_F(Ensemble, SameBytesAtOneAndTwoThreadsAndOrderedByIndex) {
  const std::string spec = dymesh::testing::WriteBoxSpec(dir_, 12);
  for (const char* threads : {"1", "2"}) {
    const ProcessResult r = Dymesh({"ensemble", spec, "--quiet", "--threads", threads, "--out", (dir_ / threads).string()});
    ASSERT_EQ(r.exit_code, 0) << r.err;
  }
  EXPECT_EQ(ReadFile(dir_ / "1" / "samples.jsonl"), ReadFile(dir_ / "2" / "samples.jsonl"));
  EXPECT_EQ(ReadFile(dir_ / "1" / "ensemble.json"), ReadFile(dir_ / "2" / "ensemble.json"));
  // the report: the same bytes too, well-formed XHTML, every figure present
  const std::string html = ReadFile(dir_ / "1" / "report.html");
  EXPECT_EQ(html, ReadFile(dir_ / "2" / "report.html"));
  EXPECT_EQ(dymesh::testing::XmlWellFormedError(html), "");
  for (const char* id : {"plot-histogram-box-delta-v", "plot-cdf-box-delta-v", "plot-convergence-box-delta-v",
                         "plot-tornado-box-delta-v", "plot-scatter-speed-box-delta-v", "plot-dv-pdof-box",
                         "table-statistics", "table-exceedance", "table-failed", "table-inputs"})
    EXPECT_NE(html.find(std::string("id=\"") + id + "\""), std::string::npos) << id;
  for (const char* banned : {"<script", "src=", "href="}) EXPECT_EQ(html.find(banned), std::string::npos) << banned;
  for (int i = 0; i < 12; ++i) EXPECT_EQ(nlohmann::json::parse(Line(dir_ / "1" / "samples.jsonl", i))["index"], i);
  const nlohmann::json stats = nlohmann::json::parse(ReadFile(dir_ / "1" / "ensemble.json"));
  EXPECT_EQ(stats["status_counts"]["complete"], 12);
  // box into a wall at 25..35 mph with e 0..0.2: delta-V between v and 1.2 v
  EXPECT_GT(stats["outputs"]["box.delta_v"]["min"].get<double>(), 25.0);
  EXPECT_LT(stats["outputs"]["box.delta_v"]["max"].get<double>(), 42.0);
  // the box's 66 x 30 in front meets the wall whole at every speed: its nodes' peak contact area is
  // the face's 1980 in^2, to the round-off of the summed triangle areas; the rigid wall's nodes carry none
  for (const char* q : {"min", "max"})
    EXPECT_NEAR(stats["outputs"]["box.peak_contact_area"][q].get<double>(), 66.0 * 30.0, 1e-9 * 1980.0) << q;
  const nlohmann::json first = nlohmann::json::parse(Line(dir_ / "1" / "samples.jsonl", 0));
  EXPECT_EQ(first["bodies"][1]["peak_contact_area"].get<double>(), 0.0);
  EXPECT_FALSE(fs::exists(dir_ / "1" / "samples.journal.jsonl"));
}

TEST_F(Ensemble, ThreeShardsMergedEqualOneRun) {
  const std::string spec = dymesh::testing::WriteBoxSpec(dir_, 10);
  ASSERT_EQ(Dymesh({"ensemble", spec, "--quiet", "--out", (dir_ / "whole").string()}).exit_code, 0);
  std::vector<std::string> merge = {"ensemble", "merge", spec, "--out", (dir_ / "merged").string()};
  for (int k = 1; k <= 3; ++k) {
    const std::string out = (dir_ / ("shard" + std::to_string(k))).string();
    ASSERT_EQ(Dymesh({"ensemble", spec, "--quiet", "--shard", std::to_string(k) + "/3", "--out", out}).exit_code, 0);
    merge.push_back(out);
  }
  const ProcessResult r = Dymesh(merge);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(ReadFile(dir_ / "merged" / "samples.jsonl"), ReadFile(dir_ / "whole" / "samples.jsonl"));
  EXPECT_EQ(ReadFile(dir_ / "merged" / "ensemble.json"), ReadFile(dir_ / "whole" / "ensemble.json"));
  // the third shard (samples 2, 5, 8) missing: refused, naming the first sample not run
  const ProcessResult missing = Dymesh({"ensemble", "merge", spec, "--out", (dir_ / "m2").string(), merge[5], merge[6]});
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_NE(missing.err.find("sample 2 is in no shard"), std::string::npos) << missing.err;
  // a shard folder that does not exist (a typo) is refused by name, not merged as an empty shard
  const std::string typo = (dir_ / "shard9").string();
  const ProcessResult absent = Dymesh({"ensemble", "merge", spec, "--out", (dir_ / "m3").string(), merge[5], merge[6], merge[7], typo});
  EXPECT_EQ(absent.exit_code, 2);
  EXPECT_NE(absent.err.find(typo + ": samples.jsonl: missing"), std::string::npos) << absent.err;
  // merged into one of its own shards (the path spelled another way): refused, the shard unchanged
  const std::string shard2 = ReadFile(fs::path(merge[6]) / "samples.jsonl");
  const std::string into_shard = (dir_ / "." / "shard2").string();
  const ProcessResult own = Dymesh({"ensemble", "merge", spec, "--out", into_shard, merge[5], merge[6], merge[7]});
  EXPECT_EQ(own.exit_code, 2);
  EXPECT_NE(own.err.find(into_shard + ": --out: is the shard folder " + merge[6] + ": merge into a new folder"),
            std::string::npos) << own.err;
  EXPECT_EQ(ReadFile(fs::path(merge[6]) / "samples.jsonl"), shard2);
  // a shard run into the whole ensemble's folder (or another shard's) is refused and changes nothing:
  // finishing there would have rewritten samples.jsonl with the shard's records only
  const std::string whole_samples = ReadFile(dir_ / "whole" / "samples.jsonl");
  const ProcessResult into_whole =
      Dymesh({"ensemble", spec, "--quiet", "--shard", "1/3", "--out", (dir_ / "whole").string()});
  EXPECT_EQ(into_whole.exit_code, 2);
  EXPECT_NE(into_whole.err.find("--shard: the folder holds sample 1, which is not in shard 1/3"), std::string::npos)
      << into_whole.err;
  EXPECT_EQ(ReadFile(dir_ / "whole" / "samples.jsonl"), whole_samples);
  EXPECT_EQ(Dymesh({"ensemble", spec, "--quiet", "--shard", "2/3", "--out", merge[5]}).exit_code, 2);
}

#ifdef DYMESH_MPIEXEC
TEST_F(Ensemble, OneTwoAndThreeMpiRanksGiveTheSameBytes) {
  const std::string spec = dymesh::testing::WriteBoxSpec(dir_, 11);
  ASSERT_EQ(Dymesh({"ensemble", spec, "--quiet", "--out", (dir_ / "plain").string()}).exit_code, 0);
  ExpectSameBytesOnRanks(spec, {"1", "2", "3"}, dir_ / "plain");
}

TEST_F(Ensemble, MpiRanksSayWhyTheyRefuseAsASerialRunDoes) {
  // found by a fuzz of the ensemble command, 2026-11-28: under mpirun a refused --out ended in Open
  // MPI's abort banner alone, exit 1; now the message and exit code of a serial run (2 here)
  setenv("OMPI_ALLOW_RUN_AS_ROOT", "1", 1);
  setenv("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1", 1);
  const std::string spec = dymesh::testing::WriteBoxSpec(dir_, 4);
  const fs::path file = dir_ / "not_a_folder";
  std::ofstream(file) << "x";
  const ProcessResult r = dymesh::testing::RunProcess(
      {DYMESH_MPIEXEC, "--oversubscribe", "-np", "2", DYMESH_CLI, "ensemble", spec, "--quiet", "--out", file.string()},
      dir_ / "process", 300.0);
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("error: " + file.string() + ": --out: exists and is not a folder"), std::string::npos) << r.err;
}

TEST_F(Ensemble, StopToleranceAcrossMpiRanksEndsWhereThreadsDo) {
  // the master judges each checkpoint once all its records are in: the same samples and bytes as a
  // threaded run, at 2 and 3 ranks
  const std::string path = WriteStopToleranceSpec();
  ASSERT_EQ(Dymesh({"ensemble", path, "--quiet", "--out", (dir_ / "threads").string()}).exit_code, 0);
  const std::string lines = ReadFile(dir_ / "threads" / "samples.jsonl");
  ASSERT_LT(std::count(lines.begin(), lines.end(), '\n'), 64);
  ExpectSameBytesOnRanks(path, {"2", "3"}, dir_ / "threads");
}
#endif

TEST_F(Ensemble, SamplesOverTheTimeLimitAreRecordedAndRunAgainOnResume) {
  // a limit no sample can meet: every sample is a timed_out record (counted, excluded, the ensemble
  // goes on; with none in the statistics it exits 3 and says so); the same command without the limit
  // then runs them again, to a fresh run's bytes
  const std::string spec = dymesh::testing::WriteBoxSpec(dir_, 4);
  ASSERT_EQ(Dymesh({"ensemble", spec, "--quiet", "--out", (dir_ / "fresh").string()}).exit_code, 0);
  const fs::path out = dir_ / "limited";
  const ProcessResult limited = Dymesh({"ensemble", spec, "--quiet", "--sample-time-limit", "1e-6", "--out", out.string()});
  ASSERT_EQ(limited.exit_code, 3) << limited.err;
  EXPECT_NE(limited.out.find("4 excluded from the statistics (4 not complete, 0 voided by a warning)"),
            std::string::npos) << limited.out;
  EXPECT_NE(limited.err.find("no sample reached the statistics"), std::string::npos) << limited.err;
  const std::string first = Line(out / "samples.jsonl", 0);
  EXPECT_NE(first.find("\"status\":\"timed_out\""), std::string::npos) << first;
  EXPECT_NE(first.find("ran over the sample time limit of 1e-06 s (wall clock)"), std::string::npos) << first;
  EXPECT_NE(ReadFile(out / "report.html").find("timed_out"), std::string::npos);
  const ProcessResult again = Dymesh({"ensemble", spec, "--quiet", "--out", out.string()});
  ASSERT_EQ(again.exit_code, 0) << again.err;
  EXPECT_NE(again.out.find("4 run now, 0 resumed, 0 excluded"), std::string::npos) << again.out;
  EXPECT_EQ(ReadFile(out / "samples.jsonl"), ReadFile(dir_ / "fresh" / "samples.jsonl"));
  EXPECT_EQ(ReadFile(out / "ensemble.json"), ReadFile(dir_ / "fresh" / "ensemble.json"));
  // a limit that is not a positive number of seconds is refused before any sample
  EXPECT_EQ(Dymesh({"ensemble", spec, "--sample-time-limit", "0", "--out", (dir_ / "zero").string()}).exit_code, 2);
}

TEST_F(Ensemble, SamplesWhoseBodiesPassedThroughAreVoidedAndLeftOutOfTheStatistics) {
  // the coarse boxes head-on: in line they crush and part (delta-V ~33 mph each); 20 in apart
  // laterally they pass through each other (the trust test's case, run warning passed_through, status
  // complete). The Latin hypercube gives the two offsets 4 samples each.
  const std::string scenario = Write("boxes.json", dymesh::testing::CoarseBoxesHeadOn(0.0).dump());
  const std::string spec = Write("spec.json", R"({"scenario": ")" + scenario + R"(", "design": "latin_hypercube",
    "samples": 8, "seed": 3, "inputs": [{"name": "offset", "path": "bodies[1].initial.position[1]",
    "distribution": {"discrete": {"values": [0, 20]}}}]})");
  const ProcessResult r = Dymesh({"ensemble", spec, "--quiet", "--out", (dir_ / "out").string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("8 run now, 0 resumed, 4 excluded from the statistics (0 not complete, 4 voided by a warning)"),
            std::string::npos) << r.out;
  // every offset sample is recorded complete with the warning; the in-line ones are clean
  for (int i = 0; i < 8; ++i) {
    const nlohmann::json s = nlohmann::json::parse(Line(dir_ / "out" / "samples.jsonl", i));
    EXPECT_EQ(s["status"], "complete") << i;
    const bool offset = s["inputs"]["offset"].get<double>() == 20.0;
    EXPECT_EQ(s["warnings"].dump(), offset ? "[\"passed_through\"]" : "[]") << i;
  }
  // the statistics hold the in-line samples only: delta-V near 33 mph, not the ~2 mph of a pass-through
  const nlohmann::json stats = nlohmann::json::parse(ReadFile(dir_ / "out" / "ensemble.json"));
  EXPECT_EQ(stats["status_counts"]["complete"], 8);
  EXPECT_EQ(stats["voided_by_warning"]["passed_through"], 4);
  EXPECT_EQ(stats["in_statistics"], 4);
  EXPECT_EQ(stats["outputs"]["a.delta_v"]["n"], 4);
  EXPECT_GT(stats["outputs"]["a.delta_v"]["min"].get<double>(), 25.0);
  // the report lists them with why
  const std::string html = ReadFile(dir_ / "out" / "report.html");
  EXPECT_NE(html.find("4 in the statistics, 4 not"), std::string::npos);
  EXPECT_NE(html.find("<td>complete</td><td>[&quot;passed_through&quot;]</td>"), std::string::npos);
}

TEST_F(Ensemble, SamplesWithWarningsThatLeaveResultsStandAreKeptAndCounted) {
  // the box into the wall at a 0.5 ms step and at 4 ms (under 50 steps per contact period: warned
  // time_step_coarse, which does not void: delta-V 34.4 against 33.0 mph); the Latin hypercube gives
  // each step 3 of the 6 samples. All 6 enter the statistics; the coarse ones are counted by code and
  // listed in the report
  const std::string scenario = std::string(DYMESH_DATA_DIR) + "/scenarios/validation/box_barrier_30mph.json";
  const std::string spec = Write("spec.json", R"({"scenario": ")" + scenario + R"(", "design": "latin_hypercube",
    "samples": 6, "seed": 5, "inputs": [{"name": "step", "path": "time.step",
    "distribution": {"discrete": {"values": [0.0005, 0.004]}}}]})");
  const ProcessResult r = Dymesh({"ensemble", spec, "--quiet", "--out", (dir_ / "out").string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("6 run now, 0 resumed, 0 excluded from the statistics (0 not complete, 0 voided by a warning), "
                       "3 kept with warnings"),
            std::string::npos) << r.out;
  std::vector<int> coarse;
  for (int i = 0; i < 6; ++i) {
    const nlohmann::json s = nlohmann::json::parse(Line(dir_ / "out" / "samples.jsonl", i));
    const bool is_coarse = s["inputs"]["step"].get<double>() == 0.004;
    EXPECT_EQ(s["warnings"].dump(), is_coarse ? "[\"time_step_coarse\"]" : "[]") << i;
    if (is_coarse) coarse.push_back(i);
  }
  ASSERT_EQ(coarse.size(), 3u);
  const nlohmann::json stats = nlohmann::json::parse(ReadFile(dir_ / "out" / "ensemble.json"));
  EXPECT_EQ(stats["in_statistics"], 6);
  EXPECT_EQ(stats["voided_by_warning"].dump(), "{}");
  EXPECT_EQ(stats["kept_with_warning"].dump(), "{\"time_step_coarse\":3}");
  // the report's table of kept samples with warnings holds exactly the coarse ones
  const std::string html = ReadFile(dir_ / "out" / "report.html");
  const std::size_t table = html.find("id=\"table-warned\"");
  ASSERT_NE(table, std::string::npos);
  const std::string rows = html.substr(table, html.find("</table>", table) - table);
  for (int i = 0; i < 6; ++i) {
    const bool listed = rows.find("<tr><td>" + std::to_string(i) + "</td><td>time_step_coarse</td></tr>") != std::string::npos;
    EXPECT_EQ(listed, std::find(coarse.begin(), coarse.end(), i) != coarse.end()) << i;
  }
}

TEST_F(Ensemble, KilledRunResumesToTheSameBytes) {
  const std::string spec = dymesh::testing::WriteBoxSpec(dir_, 40);
  ASSERT_EQ(Dymesh({"ensemble", spec, "--quiet", "--out", (dir_ / "whole").string()}).exit_code, 0);
  // a run killed (SIGKILL) once a few records are in its journal
  const fs::path out = dir_ / "killed";
  fs::create_directories(dir_ / "p");
  const auto p = dymesh::testing::StartProcess({DYMESH_CLI, "ensemble", spec, "--threads", "1", "--out", out.string()},
                                               dir_ / "p" / "out", dir_ / "p" / "err");
  const fs::path journal = out / "samples.journal.jsonl";
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (std::chrono::steady_clock::now() < deadline) {
    const std::string text = ReadFile(journal);
    if (std::count(text.begin(), text.end(), '\n') >= 5) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  kill(p.pid, SIGKILL);
  dymesh::testing::WaitProcess(p, 30.0);
  ASSERT_FALSE(fs::exists(out / "samples.jsonl")) << "the run finished before it was killed";
  const ProcessResult resumed = Dymesh({"ensemble", spec, "--quiet", "--out", out.string()});
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  EXPECT_NE(resumed.out.find(" resumed"), std::string::npos);
  EXPECT_EQ(resumed.out.find(" 0 resumed"), std::string::npos) << resumed.out;
  EXPECT_EQ(ReadFile(out / "samples.jsonl"), ReadFile(dir_ / "whole" / "samples.jsonl"));
  EXPECT_EQ(ReadFile(out / "ensemble.json"), ReadFile(dir_ / "whole" / "ensemble.json"));
}

TEST_F(Ensemble, ReplayGivesTheRecordAndTheFullOutputs) {
  // the box arrives spinning, so it leaves with a yaw rate the record must carry
  const std::string spec = dymesh::testing::WriteBoxSpec(dir_, 8, "latin_hypercube", R"(,
      {"name": "spin", "path": "bodies[0].initial.yaw_rate", "distribution": {"uniform": {"low": 20, "high": 40}}})");
  ASSERT_EQ(Dymesh({"ensemble", spec, "--quiet", "--out", (dir_ / "all").string()}).exit_code, 0);
  const ProcessResult r = Dymesh({"ensemble", "replay", spec, "--index", "5", "--out", (dir_ / "five").string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(ReadFile(dir_ / "five" / "record.json"), Line(dir_ / "all" / "samples.jsonl", 5) + "\n");
  for (const char* name : {"summary.json", "report.html", "history.csv", "box_deformed.ply"})
    EXPECT_TRUE(fs::exists(dir_ / "five" / name)) << name;
  // the yaw rate it leaves with: the record's, the single run's and the statistics' output agree
  const nlohmann::json record = nlohmann::json::parse(ReadFile(dir_ / "five" / "record.json"));
  const nlohmann::json summary = nlohmann::json::parse(ReadFile(dir_ / "five" / "summary.json"));
  const double yaw_rate = record["bodies"][0]["final_yaw_rate_deg_s"].get<double>();
  EXPECT_EQ(yaw_rate, summary["bodies"][0]["final_yaw_rate_deg_s"].get<double>());
  EXPECT_GT(std::abs(yaw_rate), 1.0);
  const nlohmann::json stats = nlohmann::json::parse(ReadFile(dir_ / "all" / "ensemble.json"));
  EXPECT_EQ(stats["outputs"]["box.final_yaw_rate_deg_s"]["n"].get<int>(), 8);
  const ProcessResult bad = Dymesh({"ensemble", "replay", spec, "--index", "8", "--out", (dir_ / "x").string()});
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("--index: expected a sample index in 0..7, got 8"), std::string::npos) << bad.err;
}

TEST_F(Ensemble, SamplesOfAGravityBodyCarryItsSupportWork) {
  // the box into the wall rising at 3 mph as a `gravity` body: each record carries its weight and ground
  // support's work, overall and per body, as the sample's own run writes it to summary.json
  std::string scenario = ReadFile(std::string(DYMESH_DATA_DIR) + "/scenarios/validation/box_barrier_30mph.json");
  const std::string initial = R"("heading": 0, "speed": 30)";
  ASSERT_NE(scenario.find(initial), std::string::npos);
  scenario.replace(scenario.find(initial), initial.size(), R"("heading": 0, "velocity": [30, 0, -3])");
  scenario.replace(scenario.find(R"("weight": 3000,)"), 15, R"("weight": 3000, "motion": "gravity",)");
  const std::string spec = Write("spec.json", R"({"scenario": ")" + Write("rising.json", scenario) +
                                                  R"(", "design": "latin_hypercube", "samples": 3, "seed": 5,
    "inputs": [{"name": "restitution", "path": "bodies[0].restitution",
                "distribution": {"uniform": {"low": 0.0, "high": 0.2}}, "bounds": [0, 1]}]})");
  ASSERT_EQ(Dymesh({"ensemble", spec, "--quiet", "--out", (dir_ / "all").string()}).exit_code, 0);
  const ProcessResult r = Dymesh({"ensemble", "replay", spec, "--index", "1", "--out", (dir_ / "one").string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json record = nlohmann::json::parse(Line(dir_ / "all" / "samples.jsonl", 1));
  const nlohmann::json summary = nlohmann::json::parse(ReadFile(dir_ / "one" / "summary.json"));
  const double work = record["support_work"].get<double>();
  EXPECT_EQ(work, summary["overall"]["support_work"].get<double>());
  EXPECT_EQ(record["bodies"][0]["support_work"].get<double>(), summary["bodies"][0]["support_work"].get<double>());
  // the wall's faces are vertical and frictionless (the box's friction is the default 0): the contact does
  // no vertical work, so the support's is the change of the vertical kinetic energy, -m (vz0^2 - vz^2) / 2,
  // vz0 = 3 mph = 52.8 in/s up (the run stops at separation with the box still rising); m = 3000 / 386.09
  // lb s^2/in, ft lbf = 12 lbf in. Booked at each step's mean velocity, as the ledger is: 1e-6 relative
  const double vz = record["bodies"][0]["final_velocity"][2].get<double>() * 17.6;
  const double expected = -0.5 * (3000.0 / 386.08858) * (52.8 * 52.8 - vz * vz) / 12.0;
  EXPECT_LT(expected, -800.0);
  EXPECT_NEAR(work, expected, 1e-6 * std::abs(expected)) << record.dump();
  EXPECT_LT(std::abs(record["energy_balance_error"].get<double>()), 1e-9);
}

TEST_F(Ensemble, SaltelliDesignGivesSobolIndices) {
  // 16 rows of A and B, two inputs: 64 runs; delta-V of the box is mostly speed, some restitution
  const std::string spec = dymesh::testing::WriteBoxSpec(dir_, 16, "saltelli");
  const ProcessResult r = Dymesh({"ensemble", spec, "--quiet", "--out", (dir_ / "out").string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("64 samples"), std::string::npos) << r.out;
  const nlohmann::json sobol = nlohmann::json::parse(ReadFile(dir_ / "out" / "ensemble.json"))["outputs"]["box.delta_v"]["sobol"];
  EXPECT_EQ(sobol["speed"]["rows"], 16);
  EXPECT_GT(sobol["speed"]["total"].get<double>(), sobol["restitution"]["total"].get<double>());
  EXPECT_GT(sobol["speed"]["first"].get<double>(), 0.5);
  // the report draws them: one first-order and one total bar per input, labelled with ensemble.json's values
  const std::string html = ReadFile(dir_ / "out" / "report.html");
  EXPECT_EQ(dymesh::testing::XmlWellFormedError(html), "");
  const std::size_t begin = html.find("<svg class=\"plot\" id=\"plot-sobol-box-delta-v\"");
  ASSERT_NE(begin, std::string::npos);
  const std::string svg = html.substr(begin, html.find("</svg>", begin) - begin);
  std::size_t bars = 0;
  for (std::size_t at = svg.find("<rect"); at != std::string::npos; at = svg.find("<rect", at + 1)) ++bars;
  EXPECT_EQ(bars, 4u);
  for (const char* input : {"speed", "restitution"})
    for (const char* index : {"first", "total"}) {
      char label[32];
      std::snprintf(label, sizeof label, ">%.2f</text>", sobol[input][index].get<double>());
      EXPECT_NE(svg.find(label), std::string::npos) << input << " " << index << " " << label;
    }
}

TEST_F(Ensemble, OneAtATimeGivesTheSwings) {
  // the box into a wall: delta-V ~ (1 + e) v, so speed 25.5..34.5 mph swings it ~9.9 mph and
  // restitution 0.01..0.19 ~5.4 mph, around ~33 mph at the medians
  const std::string spec = dymesh::testing::WriteBoxSpec(dir_, 1, "one_at_a_time");
  ASSERT_EQ(Dymesh({"ensemble", spec, "--quiet", "--out", (dir_ / "out").string()}).exit_code, 0);
  const nlohmann::json oat = nlohmann::json::parse(ReadFile(dir_ / "out" / "ensemble.json"))["outputs"]["box.delta_v"]["one_at_a_time"];
  EXPECT_NEAR(oat["baseline"].get<double>(), 33.0, 0.05 * 33.0);
  EXPECT_NEAR(oat["inputs"]["speed"]["swing"].get<double>(), 9.9, 0.1 * 9.9);
  EXPECT_NEAR(oat["inputs"]["restitution"]["swing"].get<double>(), 5.4, 0.2 * 5.4);
  // the report names the design by its spec key
  EXPECT_NE(ReadFile(dir_ / "out" / "report.html").find("; design one_at_a_time, "), std::string::npos);
}

TEST_F(Ensemble, EvidenceGivesThePosteriorOfTheImpactSpeed) {
  // the box's delta-V measured as 36.3 +- 0.5 mph: delta-V ~ (1 + e) v with e ~ 0.1 puts the
  // posterior impact speed near 33 mph (prior uniform 25..35, mean 30)
  std::string path = dymesh::testing::WriteBoxSpec(dir_, 60);
  std::string text = ReadFile(path);
  text.insert(text.rfind('}'), R"(, "evidence": [{"observable": "box.delta_v", "value": 36.3, "sd": 0.5}])");
  std::ofstream(path) << text;
  const ProcessResult r = Dymesh({"ensemble", path, "--quiet", "--out", (dir_ / "out").string()});
  const nlohmann::json post = nlohmann::json::parse(ReadFile(dir_ / "out" / "ensemble.json"))["posterior"];
  const double effective = post["effective_sample_size"].get<double>();
  EXPECT_GT(effective, 3.0);
  EXPECT_LT(effective, 60.0);
  EXPECT_NEAR(post["inputs"]["speed"]["mean"].get<double>(), 33.0, 1.5);
  EXPECT_NEAR(post["outputs"]["box.delta_v"]["mean"].get<double>(), 36.3, 1.0);
  // fewer than 20 effective samples (P5 and P95 each need one beyond them): warned, in ensemble.json
  // and on stderr, exit 3 (a 0.5 mph band over a 10 mph prior keeps about 60 x 0.1 x 1.25 of the 60)
  const bool few = effective < 20.0;
  EXPECT_EQ(r.exit_code, few ? 3 : 0) << r.err;
  EXPECT_EQ(post.contains("warning"), few);
  EXPECT_EQ(r.err.find("effective sample size") != std::string::npos, few) << r.err;
  // the report shows the same posterior: its effective sample size, the warning when there is one, and
  // the posterior mean speed beside the prior's
  const std::string html = ReadFile(dir_ / "out" / "report.html");
  EXPECT_EQ(dymesh::testing::XmlWellFormedError(html), "");
  char ess[64], speed[128];
  std::snprintf(ess, sizeof ess, "effective sample size %.1f.", effective);
  std::snprintf(speed, sizeof speed, "<tr><td>speed</td><td>%.3f</td>", post["prior"]["inputs"]["speed"]["mean"].get<double>());
  EXPECT_NE(html.find(ess), std::string::npos) << ess;
  EXPECT_NE(html.find(speed), std::string::npos) << speed;
  char posterior_mean[32];
  std::snprintf(posterior_mean, sizeof posterior_mean, "<td>%.3f</td>", post["inputs"]["speed"]["mean"].get<double>());
  EXPECT_NE(html.find(posterior_mean, html.find(speed)), std::string::npos) << posterior_mean;
  EXPECT_EQ(html.find("id=\"posterior-warning\"") != std::string::npos, few);
  // the prior weighs every sample alike: 60 samples of a uniform 25..35 mph, mean 30 within 3 SE
  // (SE = 10 / sqrt(12 x 60) = 0.37 mph; Latin hypercube strata make it far tighter)
  EXPECT_NEAR(post["prior"]["inputs"]["speed"]["mean"].get<double>(), 30.0, 3 * 0.37);
  std::printf("[measured] posterior of 60 samples, delta-V 36.3 +- 0.5 mph: effective sample size %.1f\n", effective);
}

TEST_F(Ensemble, APosteriorOfTooFewEffectiveSamplesIsWarnedAndOneOfEnoughIsNot) {
  // a 0.05 mph band: a sample or two carry the posterior; a 5 mph band: most of the 24 samples do
  for (const auto& [sd, warned] : {std::pair{"0.05", true}, std::pair{"5", false}}) {
    std::string path = dymesh::testing::WriteBoxSpec(dir_, 24);
    std::string text = ReadFile(path);
    text.insert(text.rfind('}'), std::string(R"(, "evidence": [{"observable": "box.delta_v", "value": 36.3, "sd": )") + sd + "}]");
    std::ofstream(path) << text;
    const fs::path out = dir_ / (std::string("sd") + sd);
    const ProcessResult r = Dymesh({"ensemble", path, "--quiet", "--out", out.string()});
    const nlohmann::json post = nlohmann::json::parse(ReadFile(out / "ensemble.json"))["posterior"];
    EXPECT_EQ(r.exit_code, warned ? 3 : 0) << sd << r.err;
    EXPECT_EQ(post.contains("warning"), warned) << sd;
    EXPECT_EQ(post["effective_sample_size"].get<double>() < 20.0, warned) << sd;
    EXPECT_EQ(r.err.find("warning: the evidence leaves an effective sample size of") != std::string::npos, warned) << r.err;
  }
}

TEST_F(Ensemble, StopToleranceEndsAtASettledCheckpointTheSameAtAnyThreadCount) {
  // checkpoints at 8, 16, 32, 64 samples; a loose 10 % tolerance settles before 64
  const std::string path = WriteStopToleranceSpec();
  for (const char* threads : {"1", "2"})
    ASSERT_EQ(Dymesh({"ensemble", path, "--quiet", "--threads", threads, "--out", (dir_ / threads).string()}).exit_code, 0);
  const nlohmann::json stats = nlohmann::json::parse(ReadFile(dir_ / "1" / "ensemble.json"));
  ASSERT_TRUE(stats.contains("converged_at_samples")) << stats.dump();
  const int n = stats["converged_at_samples"].get<int>();
  EXPECT_TRUE(n == 16 || n == 32) << n;
  const std::string lines = ReadFile(dir_ / "1" / "samples.jsonl");
  EXPECT_EQ(std::count(lines.begin(), lines.end(), '\n'), n);
  EXPECT_EQ(lines, ReadFile(dir_ / "2" / "samples.jsonl"));
  EXPECT_EQ(ReadFile(dir_ / "1" / "ensemble.json"), ReadFile(dir_ / "2" / "ensemble.json"));
}

TEST_F(Ensemble, BenchReportsSamplesPerSecondAndMemory) {
  // figures present and positive (speeds are measured in the benchmarks, not asserted here)
  const std::string spec = dymesh::testing::WriteBoxSpec(dir_, 8);
  const ProcessResult r = Dymesh({"bench", "--ensemble", spec, "--samples", "2", "--threads", "2", "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_GT(j["samples_per_second"]["threads_1"].get<double>(), 0.0);
  EXPECT_GT(j["samples_per_second"]["threads_n"].get<double>(), 0.0);
  EXPECT_GT(j["bytes_per_concurrent_sample"].get<double>(), 10000.0);
  const ProcessResult neither = Dymesh({"bench"});
  EXPECT_EQ(neither.exit_code, 2);
  EXPECT_NE(neither.err.find("give both mesh files, or --ensemble SPEC"), std::string::npos) << neither.err;
  // an ensemble and meshes together, or a sample count for meshes: refused, not one silently ignored
  const ProcessResult both = Dymesh({"bench", "--ensemble", spec, "--master", spec});
  EXPECT_EQ(both.exit_code, 2);
  EXPECT_NE(both.err.find("--master excludes --ensemble"), std::string::npos) << both.err;
  const ProcessResult samples = Dymesh({"bench", "--master", spec, "--slave", spec, "--samples", "3"});
  EXPECT_EQ(samples.exit_code, 2);
  EXPECT_NE(samples.err.find("--samples requires --ensemble"), std::string::npos) << samples.err;
}

TEST_F(Ensemble, BadSpecsAreRefusedBeforeAnySample) {
  struct Case {
    std::string extra, message;
  };
  const std::string kBoxScenario = DYMESH_DATA_DIR "/scenarios/validation/box_barrier_30mph.json";
  const Case cases[] = {
      {R"(, {"name": "x", "path": "vehicles[3].mass", "distribution": {"fixed": 1}})",
       "inputs[2].path: \"vehicles[3].mass\" does not lead into the scenario"},
      {R"(, {"name": "x", "path": "bodies[0].friction", "distribution": {"normal": {"mean": 0.3, "sd": -1}}})",
       "inputs[2].distribution.normal: expected a standard deviation (or band95) > 0"},
      {R"(, {"name": "x", "path": "bodies[0].friction", "distribution": {"uniform": {"low": 2, "high": 3}}, "bounds": [0, 1]})",
       "inputs[2].bounds: the bounds [0.000000, 1.000000] exclude the distribution's support"},
      {R"(, {"name": "x", "path": "bodies[0].friction", "distribution": {"gamma": {"k": 2}}})",
       "inputs[2].distribution: unknown distribution \"gamma\""},
      // found by fuzzing (2026-11-24): each used to start the ensemble, crash or end in a raw library message
      {R"(, {"name": "x", "path": "bodies[0].friction", "distribution": {"discrete": {"values": [0.1, 0.2, 0.3], "weights": [1, 1]}}})",
       "inputs[2].distribution.discrete.weights: expected an array of 3 weights, one per value"},
      {R"(, {"name": "x", "path": "bodies[0].friction", "distribution": {"uniform": {"low": -1e308, "high": 1e308}}})",
       "inputs[2].distribution.uniform: these parameters give draws that are not finite numbers"},
      {R"(, {"name": "x", "path": "bodies[0].friction", "distribution": {"truncated_normal": {"mean": 0, "sd": 0.01, "low": 0.5, "high": 0.6}}})",
       "inputs[2].distribution.truncated_normal: these parameters give draws that are not finite numbers"},
      {R"(, {"name": "x", "path": "bodies[0].name", "distribution": {"fixed": 1}})",
       "inputs[2].path: \"bodies[0].name\" leads to \"box\" in the scenario, not a number"},
      {R"(, {"name": "x", "path": "bodies[0]..friction", "distribution": {"fixed": 0.1}})",
       "inputs[2].path: expected a JSON path into the scenario such as bodies[0].initial.speed"},
      {R"(, {"name": "x", "path": "bodies[0].initial.position[1", "distribution": {"fixed": 0.1}})",
       "inputs[2].path: expected a JSON path into the scenario such as bodies[0].initial.speed"},
      {R"(, {"name": "x", "path": "bodies[0].friction", "distribution": {"fixed": 0.1}, "bound": [0, 1]})",
       "inputs[2].bound: unknown key; allowed keys: name, path, distribution, bounds, levels"},
      {R"(, {"name": "x", "path": "bodies[0].friction", "distribution": {"uniform": {"low": 0, "high": 1, "mode": 0.5}}})",
       "inputs[2].distribution.uniform.mode: unknown key; allowed keys: low, high"},
      {R"(, {"name": "x", "path": "bodies[0].restitution", "distribution": {"fixed": 0.1}})",
       "inputs[2].path: \"bodies[0].restitution\" is already set by inputs[1]"},
      {R"(, {"name": "x", "path": "bodies[0].friction", "distribution": {"uniform": {"low": 20, "high": 30}}})",
       "inputs at their medians: inputs[0] (\"speed\" = 30.0), inputs[1] (\"restitution\" = 0.1), inputs[2] (\"x\" = 25.0): "
       "the scenario refuses this sample: "},
      // what a run refuses before its first step (2026-11-25: every sample ran as failed_input, exit 3): a
      // position that overlaps the wall at every value, or at one extreme; a speed or a yaw rate on the fixed wall
      {R"(, {"name": "x", "path": "bodies[0].initial.position[0]", "distribution": {"uniform": {"low": 40, "high": 50}}})",
       "inputs at their medians: inputs[0] (\"speed\" = 30.0), inputs[1] (\"restitution\" = 0.1), inputs[2] (\"x\" = 45.0): "
       "the scenario refuses this sample: " + kBoxScenario + ": bodies[1].initial.position: \"box\" and \"wall\" overlap by 44.5 in"},
      {R"(, {"name": "x", "path": "bodies[0].initial.position[0]", "distribution": {"uniform": {"low": -40, "high": 20}}})",
       "inputs[2] (\"x\" = 19.9999"},
      {R"(, {"name": "x", "path": "bodies[1].initial.speed", "distribution": {"uniform": {"low": 0.5, "high": 1}}})",
       "inputs at their medians: inputs[0] (\"speed\" = 30.0), inputs[1] (\"restitution\" = 0.1), inputs[2] (\"x\" = 0.75): "
       "the scenario refuses this sample: " + kBoxScenario + ": bodies[1].initial: a body with motion \"fixed\" does not move"},
      {R"(, {"name": "x", "path": "bodies[1].initial.yaw_rate", "distribution": {"uniform": {"low": 3, "high": 5}}})",
       "inputs at their medians: inputs[0] (\"speed\" = 30.0), inputs[1] (\"restitution\" = 0.1), inputs[2] (\"x\" = 4.0): "
       "the scenario refuses this sample: " + kBoxScenario + ": bodies[1].initial: a body with motion \"fixed\" does not move"},
      // read as strictly as a scenario (2026-11-25): a duplicate key kept only its last value, a number out
      // of range and malformed JSON gave the JSON library's own message
      {R"(, {"name": "x", "name": "y", "path": "bodies[0].friction", "distribution": {"fixed": 0.1}})",
       "inputs[2].name: duplicate key \"name\""},
      {R"(, {"name": "x", "path": "bodies[0].friction", "distribution": {"fixed": 1e999}})",
       "inputs[2].distribution.fixed: expected a finite number, got 1e999"},
      {R"(, {"name": "x", "path": "bodies[0].friction", "distribution": {"fixed": 0.1})",
       "(json): malformed JSON at byte "},
  };
  for (const Case& c : cases) {
    const std::string spec = dymesh::testing::WriteBoxSpec(dir_, 5, "latin_hypercube", c.extra);
    const ProcessResult r = Dymesh({"ensemble", spec, "--out", (dir_ / "out").string()});
    EXPECT_EQ(r.exit_code, 2) << c.extra;
    EXPECT_NE(r.err.find("spec.json: " + c.message), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir_ / "out" / "samples.journal.jsonl"));
  }
  const ProcessResult missing = Dymesh({"ensemble", (dir_ / "none.json").string(), "--out", (dir_ / "out").string()});
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_NE(missing.err.find("file not found"), std::string::npos) << missing.err;
}

// a single run and an ensemble share report.html: neither writes into the other's folder (each used
// to replace the other's report and leave the rest; found by fuzzing, 2026-11-24)
TEST_F(Ensemble, RunAndEnsembleKeepToTheirOwnFolders) {
  const std::string spec = dymesh::testing::WriteBoxSpec(dir_, 2);
  ASSERT_EQ(Dymesh({"ensemble", spec, "--quiet", "--out", (dir_ / "ens").string()}).exit_code, 0);
  const std::string scenario = std::string(DYMESH_DATA_DIR) + "/scenarios/validation/box_barrier_30mph.json";
  const std::string ensemble_report = ReadFile(dir_ / "ens" / "report.html");
  const ProcessResult run = Dymesh({"run", scenario, "--quiet", "--out", (dir_ / "ens").string()});
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("ens: --out: holds an ensemble's results"), std::string::npos) << run.err;
  EXPECT_EQ(ReadFile(dir_ / "ens" / "report.html"), ensemble_report);
  ASSERT_EQ(Dymesh({"run", scenario, "--quiet", "--out", (dir_ / "single").string()}).exit_code, 0);
  const ProcessResult ensemble = Dymesh({"ensemble", spec, "--quiet", "--out", (dir_ / "single").string()});
  EXPECT_EQ(ensemble.exit_code, 2);
  EXPECT_NE(ensemble.err.find("single: --out: holds a single run's results"), std::string::npos) << ensemble.err;
  EXPECT_FALSE(fs::exists(dir_ / "single" / "samples.jsonl"));
}

// keys beside the inputs, each with a defect fuzzing found (2026-11-24): a segfault (a correlation
// row left empty), raw library messages (thresholds not an array, a matrix row that is a number), an
// output no sample has, and --samples beyond a table's rows (read past the table)
TEST_F(Ensemble, BadSpecKeysAndSampleCountsAreRefusedBeforeAnySample) {
  struct Case {
    const char* key;
    const char* value;
    std::string message;
  };
  const Case cases[] = {
      {"correlation", R"({"inputs": ["speed", "restitution"], "rank_matrix": [[1, 0.5], []]})",
       "correlation.rank_matrix[1]: expected a row of 2 numbers"},
      {"correlation", R"({"inputs": ["speed", "restitution"], "rank_matrix": [[1, 0.5], 0]})",
       "correlation.rank_matrix[1]: expected a row of 2 numbers"},
      {"correlation", R"({"inputs": ["speed", "speed"], "rank_matrix": [[1, 0.5], [0.5, 1]]})",
       "correlation.inputs[1]: input \"speed\" is named twice"},
      {"thresholds", R"("x")", "thresholds: expected an array of thresholds, got \"x\""},
      {"thresholds", R"([{"output": "nobody.delta_v", "above": 3}])", "thresholds[0].output: expected BODY.QUANTITY"},
      {"evidence", R"([{"observable": "box.c7", "value": 3, "sd": 1}])", "evidence[0].observable: expected BODY.QUANTITY"},
  };
  for (const Case& c : cases) {
    const std::string spec = dymesh::testing::WriteBoxSpec(dir_, 5);
    nlohmann::json j = nlohmann::json::parse(ReadFile(spec));
    j[c.key] = nlohmann::json::parse(c.value);
    std::ofstream(spec) << j.dump();
    const ProcessResult r = Dymesh({"ensemble", spec, "--out", (dir_ / "out").string()});
    EXPECT_EQ(r.exit_code, 2) << c.key << " " << c.value;
    EXPECT_NE(r.err.find("spec.json: " + c.message), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir_ / "out" / "samples.journal.jsonl"));
  }
  // a table of two rows asked for three samples
  const std::string spec = dymesh::testing::WriteBoxSpec(dir_, 5, "table");
  nlohmann::json j = nlohmann::json::parse(ReadFile(spec));
  j["table"] = {{30, 0.1}, {32, 0.1}};
  std::ofstream(spec) << j.dump();
  const ProcessResult r = Dymesh({"ensemble", spec, "--samples", "3", "--out", (dir_ / "out").string()});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("spec.json: --samples: this design has 2 samples; expected at most that, got 3"), std::string::npos) << r.err;
}

// keys the spec's design does not read, and a normal given in both forms (fuzzing, 2026-11-25: each was
// accepted and ignored)
TEST_F(Ensemble, SpecKeysThatWouldBeIgnoredAreRefused) {
  struct Case {
    const char* design;
    const char* pointer;
    const char* value;
    std::string message;
  };
  const Case cases[] = {
      {"grid", "/samples", "5", "samples: the design \"grid\" sets its own run count"},
      {"one_at_a_time", "/samples", "5", "samples: the design \"one_at_a_time\" sets its own run count"},
      {"table", "/samples", "2", "samples: the design \"table\" sets its own run count"},
      {"latin_hypercube", "/table", "[[30, 0.1]]", "table: is read only by the design \"table\"; this spec's design is \"latin_hypercube\""},
      {"monte_carlo", "/inputs/0/levels", "4", "inputs[0].levels: is read only by the design \"grid\""},
      {"latin_hypercube", "/inputs/0/distribution", R"({"normal": {"mean": 30, "sd": 1, "value": 31, "band95": 4}})",
       "inputs[0].distribution.normal: give mean and sd, or value and band95, not both"},
      {"latin_hypercube", "/inputs/0/distribution", R"({"truncated_normal": {"value": 30, "band95": 4, "sd": 1, "low": 20, "high": 40}})",
       "inputs[0].distribution.truncated_normal: give mean and sd, or value and band95, not both"},
  };
  for (const Case& c : cases) {
    const std::string spec = dymesh::testing::WriteBoxSpec(dir_, 5, c.design);
    nlohmann::json j = nlohmann::json::parse(ReadFile(spec));
    if (std::string(c.design) == "table") j["table"] = {{30, 0.1}, {32, 0.1}};
    j[nlohmann::json::json_pointer(c.pointer)] = nlohmann::json::parse(c.value);
    std::ofstream(spec) << j.dump();
    const ProcessResult r = Dymesh({"ensemble", spec, "--out", (dir_ / "out").string()});
    EXPECT_EQ(r.exit_code, 2) << c.pointer << " " << c.value;
    EXPECT_NE(r.err.find("spec.json: " + c.message), std::string::npos) << r.err;
  }
}

// CRASH3 presets that fuzzing found accepted (2026-11-24): on the rigid wall (stiffness never used), the
// same surface twice, and a surface an input also sets (one overwrote the other in every sample)
TEST_F(Ensemble, Crash3PresetsWithNoOrTwoSourcesAreRefused) {
  const std::string preset = R"({"name": "k", "body": 0, "surface": "front", "width": 66, "weight": 3000,
    "b0": {"fixed": 5}, "b1": {"fixed": 1.5}})";
  const std::string on_wall = R"({"name": "w", "body": 1, "surface": "front", "width": 66, "weight": 3000,
    "b0": {"fixed": 5}, "b1": {"fixed": 1.5}})";
  const std::string again = R"({"name": "k2", "body": 0, "surface": "front", "width": 66, "weight": 3000,
    "b0": {"fixed": 5}, "b1": {"fixed": 1.5}})";
  const std::pair<std::string, std::string> cases[] = {
      {"[" + on_wall + "]", "crash3[0].body: body 1 (\"wall\") is rigid: it takes no crush"},
      {"[" + preset + ", " + again + "]", "crash3[1].surface: bodies[0] front is already set by crash3[0]"},
  };
  for (const auto& [crash3, message] : cases) {
    const std::string spec = dymesh::testing::WriteBoxSpec(dir_, 5);
    nlohmann::json j = nlohmann::json::parse(ReadFile(spec));
    j["crash3"] = nlohmann::json::parse(crash3);
    std::ofstream(spec) << j.dump();
    const ProcessResult r = Dymesh({"ensemble", spec, "--out", (dir_ / "out").string()});
    EXPECT_EQ(r.exit_code, 2) << crash3;
    EXPECT_NE(r.err.find("spec.json: " + message), std::string::npos) << r.err;
  }
  // the box with its own front stiffness, which an input varies while a preset sets it
  nlohmann::json scenario = nlohmann::json::parse(ReadFile(DYMESH_DATA_DIR "/scenarios/validation/box_barrier_30mph.json"));
  scenario["bodies"][0]["stiffness"]["front"] = {{"A", 300}, {"B", 100}, {"conversion_height", 30}};
  const std::string spec = Write("front.json", R"({"scenario": ")" + Write("front_scenario.json", scenario.dump()) +
      R"(", "samples": 3, "inputs": [{"name": "a", "path": "bodies[0].stiffness.front.A",
      "distribution": {"uniform": {"low": 250, "high": 350}}}], "crash3": [)" + preset + "]}");
  const ProcessResult r = Dymesh({"ensemble", spec, "--out", (dir_ / "out").string()});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("front.json: crash3[0].surface: bodies[0] front is also set by inputs[0] "
                       "(\"bodies[0].stiffness.front.A\"): give its stiffness one source"), std::string::npos) << r.err;
}

}  // namespace
