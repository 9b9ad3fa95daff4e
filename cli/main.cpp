// The dymesh command: runs a scenario and writes its outputs. Holds no physics.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <exception>
#include <iostream>

#include "bench_command.h"
#include "dymesh/accel/embree_locator.h"
#include "dymesh/core/results.h"
#include "dymesh/core/scenario.h"
#include "dymesh/core/simulation.h"
#include "dymesh/core/units.h"

namespace {

// one line per body: the figures a reconstructionist looks at first
void PrintSummary(const dymesh::Summary& s, dymesh::UnitSystem units) {
  const bool us = units == dymesh::UnitSystem::kUS;
  const double speed = us ? 1 / dymesh::units::kMph : 1.0, length = us ? 1 / dymesh::units::kInch : 1.0;
  const char* su = us ? "mph" : "m/s";
  const char* lu = us ? "in" : "m";
  for (const auto& b : s.bodies) {
    std::printf("  %-16s delta-V %7.2f %s  PDOF %6.1f deg (%2d o'clock)  peak %5.1f g  max crush %6.2f %s\n",
                b.name.c_str(), b.delta_v * speed, su, b.pdof_deg, b.pdof_clock,
                b.peak_accel / dymesh::units::kStandardGravity, b.max_crush * length, lu);
  }
  std::printf("  contact %.4f-%.4f s, %d steps; energy balance error %.3f%%\n", s.contact_start, s.contact_end,
              s.steps, 100.0 * s.energy_balance_error);
}

int Run(const std::string& scenario_path, const std::string& out_dir) {
  const dymesh::Scenario scenario = dymesh::LoadScenario(scenario_path);
  auto device = std::make_shared<const dymesh::EmbreeDevice>();
  dymesh::Simulation sim(scenario, dymesh::MakeEmbreeLocatorFactory(device));
  sim.Run();
  const dymesh::Summary summary = dymesh::Summarize(sim);
  const auto written = dymesh::WriteOutputs(sim, summary, out_dir);
  std::printf("%s: %s\n", scenario.file.c_str(), scenario.name.c_str());
  PrintSummary(summary, scenario.units);
  std::printf("outputs in %s:\n", out_dir.c_str());
  for (const auto& path : written) std::printf("  %s\n", path.c_str());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"dymesh: DyMESH mesh-based vehicle collision simulation"};
  app.require_subcommand(1);
  std::string scenario_path, out_dir = "out";
  CLI::App* run = app.add_subcommand("run", "simulate a scenario and write summary.json, history.csv and meshes");
  run->add_option("scenario", scenario_path, "scenario JSON file")->required();
  run->add_option("--out", out_dir, "output folder (created if missing)");
  dymesh::cli::BenchRequest bench;
  CLI::App* bench_cmd = app.add_subcommand("bench", "locate rates, step time and memory for two meshes in contact");
  bench_cmd->add_option("--master", bench.master, "master mesh file (metres)")->required();
  bench_cmd->add_option("--slave", bench.slave, "slave mesh file (metres)")->required();
  bench_cmd->add_option("--threads", bench.threads, "worker threads for the step timing")->check(CLI::PositiveNumber);
  bench_cmd->add_flag("--json", bench.json, "print JSON");
  std::vector<std::string> axes;
  bench_cmd->add_option("--axes", axes, "body x,y,z from signed mesh axes, e.g. --axes=x,z,-y for y-up meshes")
      ->delimiter(',')
      ->expected(3);
  CLI11_PARSE(app, argc, argv);
  try {
    if (bench_cmd->parsed()) {
      if (axes.size() == 3) bench.axes = {axes[0], axes[1], axes[2]};
      return dymesh::cli::RunBench(bench);
    }
    return Run(scenario_path, out_dir);
  } catch (const dymesh::InputError& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
}
