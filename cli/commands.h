#pragma once
#include <functional>
#include <ostream>
#include <string>
#include <vector>

/// The dymesh subcommands, callable from main() and from tests. They hold no physics.
namespace dymesh {
class OutputFolder;
}

namespace dymesh::cli {

/// Exit codes (README "Exit codes"): 0 complete with no warnings; 1 failure (e.g. cannot write);
/// 2 refused input (scenario, mesh, option or output folder); 3 complete with warnings;
/// 4 ended in contact; 5 failed numerics; 6 output folder in use by another run; 130 interrupted.
inline constexpr int kExitOk = 0, kExitFailure = 1, kExitBadInput = 2, kExitWarnings = 3, kExitEndedInContact = 4,
                     kExitFailedNumerics = 5, kExitFolderBusy = 6, kExitInterrupted = 130;

/// Reports the exception being handled on stderr ("error: ...") and returns its exit code: refused
/// input kExitBadInput, an output folder in use kExitFolderBusy, anything else kExitFailure. Call
/// only inside a catch block.
int ReportFailure();

/// What `dymesh run` was asked to do.
struct RunRequest {
  std::string scenario_path;
  std::string out_dir = "out";
  bool quiet = false;     ///< no progress, no summary: errors only
  bool terminal = false;  ///< `out` is a terminal (progress bar rather than periodic lines)
  std::string locator = "embree";  ///< search: "embree", "neighbor_box" (DyMESH's own) or "brute_force"
  int threads = 0;                 ///< worker threads (0: all cores); results do not depend on it
  std::function<void()> on_setup_done;  ///< called once the run is set up, before the first step
  /// called once the output folder is taken, before set-up (a stop during set-up removes what it created)
  std::function<void(const OutputFolder&)> on_folder_taken;
};

/// Runs a scenario and writes its outputs. `interrupts()` counts the stop requests received so far
/// (Ctrl-C): the first stops the run at the next step, its outputs so far are written (summary
/// status "interrupted"); another one stops the writing between files. Throws InputError on bad input.
int RunCommand(const RunRequest& request, const std::function<int()>& interrupts, std::ostream& out,
               std::ostream& err);

/// What `dymesh ensemble` was asked to do.
struct EnsembleRequest {
  std::string spec_path;
  std::string out_dir = "ensemble";
  int threads = 0;     ///< worker threads (0: all cores)
  int samples = 0;     ///< 0: the spec's own count
  std::string shard = "1/1";  ///< "K/N": run every N-th sample from the K-th (1-based)
  double sample_time_limit = 0.0;  ///< [s] wall clock per sample (0: none)
  bool quiet = false;
};

/// Runs an ensemble spec into `out_dir` (resuming what is there); 130 when interrupted (the
/// journal keeps the samples done); 3 when no sample reached the statistics or the evidence leaves
/// too few effective samples (stderr says which). Throws InputError on a bad spec.
int EnsembleCommand(const EnsembleRequest& request, const std::function<int()>& interrupts, std::ostream& out,
                    std::ostream& err);

/// Re-runs sample `index` with the full single-run outputs and its record (record.json).
int EnsembleReplayCommand(const std::string& spec_path, int samples, int index, const std::string& out_dir,
                          std::ostream& out);

/// Joins shard folders into `out_dir`; 3 when the evidence leaves too few effective samples (stderr).
int EnsembleMergeCommand(const std::string& spec_path, int samples, const std::vector<std::string>& shards,
                         const std::string& out_dir, std::ostream& out, std::ostream& err);

/// Validates a scenario and its meshes without running and prints what it found (mesh statistics
/// in the scenario's units, body surfaces). Throws InputError on bad input.
int CheckCommand(const std::string& scenario_path, std::ostream& out);

}  // namespace dymesh::cli
