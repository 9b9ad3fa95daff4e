// The dymesh command: runs or checks a scenario. Holds no physics.
#include <CLI/CLI.hpp>

#include <unistd.h>

#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
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

// what a stop during set-up removes (the run has written nothing yet): the lock, then the folders the
// run created, innermost first, each only while empty; copied before set-up, read by the handler
struct SetupLeftovers {
  static constexpr int kMaxFolders = 32, kMaxPath = 4096;
  char lock[kMaxPath];
  char folders[kMaxFolders][kMaxPath];
  int count = 0;
};
SetupLeftovers leftovers;
volatile std::sig_atomic_t leftovers_armed = 0;

// keeps the folder's leftovers for the handler (none when the folder existed, or a path is too long)
void ArmSetupLeftovers(const dymesh::OutputFolder& folder) {
  const std::vector<std::string> created = folder.CreatedFolders();
  const std::string lock = folder.LockPath();
  if (created.empty() || created.size() > SetupLeftovers::kMaxFolders || lock.size() >= SetupLeftovers::kMaxPath) return;
  for (const std::string& f : created)
    if (f.size() >= SetupLeftovers::kMaxPath) return;
  std::snprintf(leftovers.lock, sizeof leftovers.lock, "%s", lock.c_str());
  for (std::size_t i = 0; i < created.size(); ++i)
    std::snprintf(leftovers.folders[i], sizeof leftovers.folders[i], "%s", created[i].c_str());
  leftovers.count = static_cast<int>(created.size());
  leftovers_armed = 1;
}

// during set-up: remove the set-up's leftovers and die at once; then first request: stop at the next
// step; second: stop writing; third: die at once (unlink and rmdir are async-signal-safe)
extern "C" void OnStopSignal(int signal) {
  stop_requests = stop_requests + 1;
  if (!running && leftovers_armed) {
    unlink(leftovers.lock);
    for (int i = 0; i < leftovers.count && rmdir(leftovers.folders[i]) == 0; ++i) {
    }
  }
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
  } catch (...) {
    return dymesh::cli::ReportFailure();
  }
}

// a worker thread count: 1..4096, said in words when refused
// a whole number of `what` from lo to hi, said in words when refused (CLI11's Range called "abc" out of range)
CLI::Validator WholeNumber(int lo, int hi, const std::string& what) {
  return CLI::Validator(
      [=](std::string& value) -> std::string {
        int n = 0;
        const bool number = CLI::detail::lexical_cast(value, n);
        return number && n >= lo && n <= hi ? ""
                                            : "expected a whole number of " + what + " from " + std::to_string(lo) +
                                                  " to " + std::to_string(hi) + ", got " + value;
      },
      std::to_string(lo) + ".." + std::to_string(hi));
}

const CLI::Validator kThreadCount = WholeNumber(1, 4096, "threads");
const CLI::Validator kSampleCount = WholeNumber(1, 10000000, "samples");

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"dymesh: DyMESH mesh-based vehicle collision simulation"};
  app.require_subcommand(1);
  // run: simulate and write the outputs
  dymesh::cli::RunRequest request;
  CLI::App* run = app.add_subcommand(
      "run", "simulate a scenario; write summary.json, history.csv, report.html and meshes (OBJ, PLY)");
  run->add_option("scenario", request.scenario_path, "scenario JSON file")->required();
  run->add_option("--out", request.out_dir, "output folder (created if missing; default: out)");
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
  CLI::Option* bench_master = bench_cmd->add_option("--master", bench.master, "master mesh file (metres)");
  CLI::Option* bench_slave = bench_cmd->add_option("--slave", bench.slave, "slave mesh file (metres)");
  CLI::Option* bench_ensemble =
      bench_cmd->add_option("--ensemble", bench.ensemble, "time an ensemble spec's samples instead of two meshes");
  bench_cmd->add_option("--samples", bench.samples, "ensemble samples timed per thread setting")
      ->check(WholeNumber(1, 100000, "samples"))
      ->needs(bench_ensemble);
  bench_cmd->add_option("--threads", bench.threads, "worker threads for the step timing")->check(kThreadCount);
  CLI::Option* bench_axes =
      bench_cmd->add_option("--axes", axes, "body x,y,z from signed mesh axes, e.g. --axes=x,z,-y for y-up meshes")
          ->delimiter(',')
          ->expected(3);
  // an ensemble is timed, or two meshes: never both (one would be silently ignored)
  bench_ensemble->excludes(bench_master)->excludes(bench_slave)->excludes(bench_axes);
  bench_cmd->add_flag("--json", bench.json, "print JSON");
  // ensemble: run a spec; replay one sample; merge shards
  dymesh::cli::EnsembleRequest ens;
  CLI::App* ensemble = app.add_subcommand("ensemble", "run a Monte Carlo spec: samples.jsonl and ensemble.json (resumable)");
  ensemble->add_option("spec", ens.spec_path, "ensemble spec JSON file");
  ensemble->add_option("--out", ens.out_dir, "output folder (a re-run resumes it; default: ensemble)");
  ensemble->add_option("--threads", ens.threads, "worker threads (default: all cores); results are identical")->check(kThreadCount);
  ensemble->add_option("--samples", ens.samples, "number of samples (default: the spec's)")->check(kSampleCount);
  ensemble->add_option("--shard", ens.shard, "K/N: run every N-th sample from the K-th (Slurm arrays, GNU parallel; default: 1/1)");
  ensemble->add_option("--sample-time-limit", ens.sample_time_limit,
                       "seconds (wall clock) a sample may run; over it the sample is recorded as timed_out and a resume runs it again")
      ->check(CLI::Validator(
          [](std::string& text) {
            // a finite number of seconds (NaN passes a plain range check)
            char* end = nullptr;
            const double v = std::strtod(text.c_str(), &end);
            const bool ok = end != text.c_str() && *end == '\0' && std::isfinite(v) && v > 0.0 && v <= 1e7;
            return ok ? std::string() : "expected a number of seconds > 0 and at most 1e7, got " + text;
          },
          "SECONDS"));
  ensemble->add_flag("-q,--quiet", ens.quiet, "no progress lines");
  int replay_index = -1;
  std::string replay_spec, replay_out = "replay", merge_spec, merge_out = "ensemble";
  std::vector<std::string> merge_shards;
  CLI::App* replay = ensemble->add_subcommand("replay", "re-run one sample with the full single-run outputs");
  replay->add_option("spec", replay_spec, "ensemble spec JSON file")->required();
  replay->add_option("--index", replay_index, "sample index")->required();
  replay->add_option("--out", replay_out, "output folder (default: replay)");
  replay->add_option("--samples", ens.samples, "number of samples, if the ensemble was run with --samples")
      ->check(kSampleCount);
  CLI::App* merge = ensemble->add_subcommand("merge", "join shard folders into one ensemble");
  merge->add_option("spec", merge_spec, "ensemble spec JSON file")->required();
  merge->add_option("shards", merge_shards, "shard output folders")->required();
  merge->add_option("--out", merge_out, "output folder (default: ensemble)");
  merge->add_option("--samples", ens.samples, "number of samples, if the shards were run with --samples")
      ->check(kSampleCount);

  // command-line mistakes: one human line and exit 2 (help and version exit 0); a mistyped command
  // is named (CLI11 takes it for a stray argument and asks for a command)
  const std::string first = argc > 1 ? argv[1] : "-";
  std::string commands;
  bool known = false;
  for (const CLI::App* command : app.get_subcommands({})) {
    if (!commands.empty()) commands += ", ";
    commands += command->get_name();
    known = known || command->get_name() == first;
  }
  if (first[0] != '-' && !known) {
    std::fprintf(stderr, "error: unknown command \"%s\": expected one of %s\nrun 'dymesh --help' for the commands\n",
                 first.c_str(), commands.c_str());
    return dymesh::cli::kExitBadInput;
  }
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
  if (*replay)
    return Guarded([&] { return dymesh::cli::EnsembleReplayCommand(replay_spec, ens.samples, replay_index, replay_out, std::cout); });
  if (*merge)
    return Guarded([&] { return dymesh::cli::EnsembleMergeCommand(merge_spec, ens.samples, merge_shards, merge_out, std::cout, std::cerr); });
  if (*ensemble) {
    if (ens.spec_path.empty()) {
      std::fprintf(stderr, "error: ensemble: give a spec file (or: ensemble replay | ensemble merge)\n");
      return dymesh::cli::kExitBadInput;
    }
    InstallStopHandlers();
    running = 1;
    return Guarded([&] {
      return dymesh::cli::EnsembleCommand(ens, [] { return static_cast<int>(stop_requests); }, std::cout, std::cerr);
    });
  }
  if (*bench_cmd) {
    if (axes.size() == 3) bench.axes = {axes[0], axes[1], axes[2]};
    return Guarded([&] { return dymesh::cli::RunBench(bench); });
  }
  request.terminal = isatty(STDOUT_FILENO) != 0;
  request.on_setup_done = [] { running = 1; };
  request.on_folder_taken = ArmSetupLeftovers;
  InstallStopHandlers();
  return Guarded([&] {
    return dymesh::cli::RunCommand(request, [] { return static_cast<int>(stop_requests); }, std::cout, std::cerr);
  });
}
