// dymesh ensemble: runs a Monte Carlo spec into a folder (resumable, shardable), replays one
// sample with the full single-run outputs, merges shards.
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <optional>
#include <sstream>

#include <nlohmann/json.hpp>
#include <tbb/global_control.h>

#include "commands.h"
#include "dymesh/accel/embree_locator.h"
#include "dymesh/analysis/summary.h"
#include "dymesh/ensemble/design.h"
#include "dymesh/ensemble/ensemble_run.h"
#include "dymesh/ensemble/sample_run.h"
#include "dymesh/ensemble/statistics.h"
#include "dymesh/io/atomic_file.h"
#include "dymesh/io/body_models.h"
#include "dymesh/io/output_folder.h"
#include "dymesh/report/output_files.h"
#include "format.h"

#ifdef DYMESH_WITH_MPI
#include <mpi.h>
#endif

namespace dymesh::cli {
namespace {

// "K/N" with 1 <= K <= N
void ParseShard(const std::string& text, int* shard, int* shards) {
  int k = 0, n = 0;
  char slash = 0;
  std::istringstream in(text);
  if (!(in >> k >> slash >> n) || slash != '/' || n < 1 || k < 1 || k > n || !in.eof())
    throw InputError("command line", "--shard", "expected K/N with 1 <= K <= N, got \"" + text + "\"");
  *shard = k, *shards = n;
}

// the spec as asked: its own sample count, or --samples
ensemble::Spec LoadRequestedSpec(const std::string& path, int samples) {
  ensemble::Spec spec = ensemble::LoadSpec(path);
  return samples > 0 ? ensemble::WithSamples(spec, samples) : spec;
}

// under mpirun (and built with MPI) the ranks share the samples; otherwise one process
ensemble::RunCounts RunOnRanks(const ensemble::Spec& spec, const ensemble::RunOptions& options) {
#ifdef DYMESH_WITH_MPI
  if (std::getenv("OMPI_COMM_WORLD_SIZE") != nullptr || std::getenv("PMI_SIZE") != nullptr) {
    MPI_Init(nullptr, nullptr);
    int rank = 0, size = 1;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm_size(MPI_COMM_WORLD, &size);
    ensemble::RunCounts counts;
    try {
      counts = ensemble::RunEnsembleMpi(spec, options, rank, size);
    } catch (...) {
      // the message and exit code a serial run gives (the other ranks may wait on this one: all stop)
      MPI_Abort(MPI_COMM_WORLD, ReportFailure());
    }
    MPI_Finalize();
    return counts;
  }
#endif
  return ensemble::RunEnsemble(spec, options);
}

// the warning ensemble.json holds on a posterior of too few effective samples, else empty
std::string PosteriorWarning(const std::string& out_dir) {
  std::ifstream in(out_dir + "/ensemble.json");
  const nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
  if (j.is_discarded() || !j.contains("posterior") || !j["posterior"].contains("warning")) return "";
  return j["posterior"]["warning"].get<std::string>();
}

// exit 3 with the posterior's warning on stderr when it has one
int ExitForPosterior(const std::string& out_dir, std::ostream& err) {
  const std::string warning = PosteriorWarning(out_dir);
  if (warning.empty()) return kExitOk;
  err << "warning: " << warning << " (posterior in " << out_dir << "/ensemble.json)\n";
  return kExitWarnings;
}

}  // namespace

int EnsembleCommand(const EnsembleRequest& request, const std::function<int()>& interrupts, std::ostream& out,
                    std::ostream& err) {
  const ensemble::Spec spec = LoadRequestedSpec(request.spec_path, request.samples);
  ensemble::RunOptions options;
  options.out_dir = request.out_dir;
  options.sample_time_limit = request.sample_time_limit;
  ParseShard(request.shard, &options.shard, &options.shards);
  std::optional<tbb::global_control> thread_limit;
  if (request.threads > 0) thread_limit.emplace(tbb::global_control::max_allowed_parallelism, request.threads);
  options.stop = [&] { return interrupts() > 0; };
  options.progress = [&](int done, int total) {
    if (!request.quiet && (done % 10 == 0 || done == total)) err << Format("progress: %d / %d samples\n", done, total);
  };
  const ensemble::RunCounts c = RunOnRanks(spec, options);
  if (c.total == 0 && !c.finished) return kExitOk;  // an MPI worker rank: the master reports
  // a sample out of the statistics either did not complete (in contact at the end, non-finite, refused,
  // timed out: status_counts) or completed with a warning that voids it (voided_by_warning)
  out << Format("%s: %d samples (shard %d/%d): %d run now, %d resumed, %d excluded from the statistics (%d not "
                "complete, %d voided by a warning), %d kept with warnings\n",
                request.spec_path.c_str(), c.total, options.shard, options.shards, c.ran, c.resumed, c.excluded,
                c.excluded - c.voided, c.voided, c.warned);
  if (!c.finished) {
    err << "interrupted: the samples recorded so far are kept in " << request.out_dir
        << "/samples.journal.jsonl; run the same command again to resume\n";
    return kExitInterrupted;
  }
  out << "outputs in " << request.out_dir << ": samples.jsonl, ensemble.json, report.html\n";
  // statistics of no sample are no result: say so in the exit code
  if (c.excluded == c.total) {
    err << "warning: no sample reached the statistics (every one failed or was voided by a warning; see "
           "status_counts and voided_by_warning in ensemble.json): ensemble.json holds no outputs\n";
    return kExitWarnings;
  }
  return ExitForPosterior(request.out_dir, err);
}

int EnsembleReplayCommand(const std::string& spec_path, int samples, int index, const std::string& out_dir,
                          std::ostream& out) {
  const ensemble::Spec spec = LoadRequestedSpec(spec_path, samples);
  if (index < 0 || index >= spec.samples)
    throw InputError(spec_path, "--index", "expected a sample index in 0.." + std::to_string(spec.samples - 1) +
                                               ", got " + std::to_string(index));
  const std::vector<double> values = ensemble::DesignTable(spec).Values(index);
  // the record, as the ensemble wrote it, and the full single-run outputs of the same run
  ensemble::SharedAssets meshes;
  const ensemble::SampleRecord record = ensemble::RunSample(spec, index, values, &meshes);
  const Scenario scenario = ensemble::SampleScenario(spec, values);
  std::vector<std::string> names = OutputFileNames(scenario);
  names.push_back("record.json");
  OutputFolder folder(out_dir, names, spec.input_files);
  Simulation sim(scenario, BuildBodyModels(scenario), accel::MakeEmbreeLocatorFactory(std::make_shared<const accel::EmbreeDevice>()));
  sim.Run();
  folder.ReplacePreviousRun();
  WriteOutputs(sim, Summarize(sim), out_dir);
  WriteFileAtomically(out_dir + "/record.json", record.line + "\n");
  out << "sample " << index << " (" << record.status << ") replayed into " << out_dir
      << ": the single-run outputs and record.json (its samples.jsonl line)\n";
  return kExitOk;
}

int EnsembleMergeCommand(const std::string& spec_path, int samples, const std::vector<std::string>& shards,
                         const std::string& out_dir, std::ostream& out, std::ostream& err) {
  const ensemble::Spec spec = LoadRequestedSpec(spec_path, samples);
  ensemble::MergeShards(spec, shards, out_dir);
  out << shards.size() << " shards merged into " << out_dir << ": samples.jsonl, ensemble.json, report.html\n";
  return ExitForPosterior(out_dir, err);
}

}  // namespace dymesh::cli
