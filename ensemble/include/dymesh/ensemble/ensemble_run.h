#pragma once
#include <functional>
#include <string>
#include <vector>

#include "dymesh/ensemble/spec.h"

/// Runs an ensemble into a folder: resumable, shardable, ordered and byte-identical outputs.
namespace dymesh::ensemble {

struct RunOptions {
  std::string out_dir;
  int shard = 1, shards = 1;           ///< this process runs the samples i with i % shards == shard - 1
  std::function<bool()> stop;          ///< asked before each sample: true stops (in-flight samples finish)
  std::function<void(int done, int total)> progress;  ///< after each sample
  double sample_time_limit = 0.0;      ///< [s] wall clock per sample (0: none); over it: a kTimedOut record
};

struct RunCounts {
  int total = 0;       ///< samples of this shard
  int resumed = 0;     ///< found already recorded in the folder
  int ran = 0;         ///< run now
  int excluded = 0;    ///< not in the statistics (SampleRecord::in_statistics): not complete, or voided
  int voided = 0;      ///< of those, complete but with a warning that voids the results
  int warned = 0;      ///< in the statistics, with warnings that leave the results standing
  bool finished = false;  ///< every sample of the shard has a record (samples.jsonl and ensemble.json written)
};

/// Runs the shard's samples that have no valid record in `out_dir` yet (on oneTBB, models and meshes
/// shared), appending each record to the journal `samples.journal.jsonl` as it completes (one write
/// per line: a killed run loses only the samples in flight). Once every sample has a record, writes
/// samples.jsonl (ordered by index) and ensemble.json, and removes the journal. The folder is locked
/// for the run; one holding another spec's samples is refused.
RunCounts RunEnsemble(const Spec& spec, const RunOptions& options);

/// The same under MPI (built when MPI is found; call between MPI_Init and MPI_Finalize): rank 0
/// keeps the folder and hands out chunks of sample indices to the other ranks on request (a dynamic
/// queue), collecting their records over MPI (no shared file system needed); one rank runs as
/// RunEnsemble. Outputs are byte-identical for any rank count. Returns the counts on rank 0.
RunCounts RunEnsembleMpi(const Spec& spec, const RunOptions& options, int rank, int size);

/// The spec with another sample count (its hash changes with it).
Spec WithSamples(Spec spec, int samples);

/// Joins shard folders' samples.jsonl into `out_dir` (samples.jsonl and ensemble.json), refusing
/// records of another spec, duplicates and missing indices.
void MergeShards(const Spec& spec, const std::vector<std::string>& shard_dirs, const std::string& out_dir);

}  // namespace dymesh::ensemble
