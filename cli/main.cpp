// The dymesh command: runs or checks a scenario. Holds no physics.
#include <CLI/CLI.hpp>

#include <unistd.h>

#include <csignal>
#include <cstdio>
#include <exception>
#include <iostream>

#include "bench_command.h"
#include "commands.h"
#include "dymesh/io/output_folder.h"
#include "dymesh/core/scenario.h"

namespace {

// stop requests received (SIGINT, SIGTERM): the command's only global state, polled between steps
// and between output files; core never sees it
volatile std::sig_atomic_t stop_requests = 0;
// set once set-up is over: before, a request ends the process at once (set-up writes nothing)
volatile std::sig_atomic_t running = 0;

// during set-up: die at once; then first request: stop at the next step; second: stop writing;
// third: die at once
extern "C" void OnStopSignal(int signal) {
  stop_requests = stop_requests + 1;
  if (!running || stop_requests >= 3) {
    std::signal(signal, SIG_DFL);
    std::raise(signal);
  }
}

void InstallStopHandlers() {
  struct sigaction action {};
  action.sa_handler = OnStopSignal;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

// runs a subcommand, turning refused input and other failures into messages and exit codes
template <typename F>
int Guarded(F&& command) {
  try {
    return command();
  } catch (const dymesh::InputError& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return dymesh::cli::kExitBadInput;
  } catch (const dymesh::OutputFolderBusy& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return dymesh::cli::kExitFolderBusy;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return dymesh::cli::kExitFailure;
  }
}

// a worker thread count: 1..4096, said in words when refused
const CLI::Validator kThreadCount(
    [](std::string& value) -> std::string {
      int n = 0;
      const bool number = CLI::detail::lexical_cast(value, n);
      return number && n >= 1 && n <= 4096 ? "" : "expected a whole number of threads from 1 to 4096, got " + value;
    },
    "1..4096");

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"dymesh: DyMESH mesh-based vehicle collision simulation"};
  app.require_subcommand(1);
  // run: simulate and write the outputs
  dymesh::cli::RunRequest request;
  CLI::App* run = app.add_subcommand(
      "run", "simulate a scenario; write summary.json, history.csv, report.html and meshes (OBJ, PLY)");
  run->add_option("scenario", request.scenario_path, "scenario JSON file")->required();
  run->add_option("--out", request.out_dir, "output folder (created if missing)");
  run->add_flag("-q,--quiet", request.quiet, "print nothing but errors (no progress, no summary)");
  run->add_option("--locator", request.locator, "search: embree (default), neighbor_box (DyMESH's), brute_force")
      ->check(CLI::IsMember({"embree", "neighbor_box", "brute_force"}));
  run->add_option("--threads", request.threads, "worker threads (default: all cores); results are identical")
      ->check(kThreadCount);
  // check: validate without running
  std::string check_path;
  CLI::App* check = app.add_subcommand("check", "validate a scenario and its meshes without running; print mesh statistics");
  check->add_option("scenario", check_path, "scenario JSON file")->required();
  // bench: the benchmark figures for two meshes the user brings
  dymesh::cli::BenchRequest bench;
  std::vector<std::string> axes;
  CLI::App* bench_cmd = app.add_subcommand("bench", "locate rates, step time and memory for two meshes in contact");
  bench_cmd->add_option("--master", bench.master, "master mesh file (metres)")->required();
  bench_cmd->add_option("--slave", bench.slave, "slave mesh file (metres)")->required();
  bench_cmd->add_option("--threads", bench.threads, "worker threads for the step timing")->check(kThreadCount);
  bench_cmd->add_option("--axes", axes, "body x,y,z from signed mesh axes, e.g. --axes=x,z,-y for y-up meshes")
      ->delimiter(',')
      ->expected(3);
  bench_cmd->add_flag("--json", bench.json, "print JSON");
  // command-line mistakes: one human line and exit 2 (help and version exit 0)
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::fprintf(stderr, "error: %s\nrun 'dymesh --help' or 'dymesh COMMAND --help' for the options\n", e.what());
    return dymesh::cli::kExitBadInput;
  }

  if (*check) return Guarded([&] { return dymesh::cli::CheckCommand(check_path, std::cout); });
  if (*bench_cmd) {
    if (axes.size() == 3) bench.axes = {axes[0], axes[1], axes[2]};
    return Guarded([&] { return dymesh::cli::RunBench(bench); });
  }
  request.terminal = isatty(STDOUT_FILENO) != 0;
  request.on_setup_done = [] { running = 1; };
  InstallStopHandlers();
  return Guarded([&] {
    return dymesh::cli::RunCommand(request, [] { return static_cast<int>(stop_requests); }, std::cout, std::cerr);
  });
}
