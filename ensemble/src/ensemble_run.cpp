#include "dymesh/ensemble/ensemble_run.h"

#include <fcntl.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <deque>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <mutex>
#include <stdexcept>

#include "dymesh/core/scenario.h"
#include "dymesh/ensemble/design.h"
#include "dymesh/ensemble/ensemble_report.h"
#include "dymesh/ensemble/random_stream.h"
#include "dymesh/ensemble/sample_run.h"
#include "dymesh/ensemble/statistics.h"
#include "dymesh/io/atomic_file.h"
#include "dymesh/io/output_folder.h"
#include "dymesh/io/printable.h"

#ifdef DYMESH_WITH_MPI
#include <mpi.h>
#endif

namespace dymesh::ensemble {
namespace {

namespace fs = std::filesystem;

constexpr const char* kSamplesName = "samples.jsonl";
constexpr const char* kStatisticsName = "ensemble.json";
constexpr const char* kJournalName = "samples.journal.jsonl";
constexpr const char* kReportName = "report.html";

// the valid records of `file` (a missing file has none); a record of another spec is refused, and so
// is any other line of a file written whole (samples.jsonl: a line there that is not a record was
// edited or damaged; a journal's is left out, so its sample runs again)
void ReadRecords(const Spec& spec, const fs::path& file, std::map<int, SampleRecord>* records, bool whole_file) {
  std::ifstream in(file);
  std::string line, problem;
  for (long number = 1; std::getline(in, line); ++number) {
    if (line.empty()) continue;
    SampleRecord r;
    if (ParseRecord(spec, line, &r, &problem)) {
      // a later record of a sample replaces one that timed out (a resume ran it again)
      if (r.index >= 0 && r.index < spec.samples) {
        const auto [it, fresh] = records->emplace(r.index, r);
        if (!fresh && it->second.status == kTimedOut) it->second = r;
      }
      continue;
    }
    // a whole line of another spec: the folder is someone else's
    if (line.find("\"spec_hash\"") != std::string::npos && line.find(HashText(spec.hash)) == std::string::npos &&
        line.back() == '}')
      throw InputError(file.string(), "spec_hash",
                       "the folder holds samples of another spec (not " + HashText(spec.hash) +
                           "): use another --out, or remove the folder to start again");
    if (whole_file)
      throw InputError(file.string(), "line " + std::to_string(number),
                       Printable(problem) + " (not a sample record of this spec: the file was edited or damaged)");
  }
}

// a folder holding a sample outside the shard is another shard's or the whole ensemble's: finishing
// this shard there would rewrite its samples.jsonl with this shard's records only
void RefuseOtherShards(const RunOptions& options, const std::map<int, SampleRecord>& records) {
  for (const auto& [index, r] : records)
    if (index % options.shards != options.shard - 1)
      throw InputError(options.out_dir, "--shard",
                       "the folder holds sample " + std::to_string(index) + ", which is not in shard " +
                           std::to_string(options.shard) + "/" + std::to_string(options.shards) +
                           " (another shard's or the whole ensemble's results): give each shard its own --out, "
                           "then merge");
}

// appends one line with a single write (O_APPEND): a killed run never leaves half a record between two
class Journal {
 public:
  explicit Journal(const fs::path& path) : fd_(open(path.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644)) {
    if (fd_ < 0) throw std::runtime_error("cannot open the journal " + path.string());
  }
  ~Journal() { close(fd_); }
  void Append(const std::string& line) {
    const std::string text = line + "\n";
    std::lock_guard<std::mutex> lock(mutex_);
    if (write(fd_, text.data(), text.size()) != static_cast<ssize_t>(text.size()))
      throw std::runtime_error("cannot append to the journal");
  }

 private:
  int fd_;
  std::mutex mutex_;
};

// samples.jsonl (ordered) and ensemble.json, atomically
void WriteResults(const Spec& spec, const std::map<int, SampleRecord>& records, const fs::path& dir) {
  std::string lines;
  std::vector<SampleRecord> ordered;
  for (const auto& [index, r] : records) {
    lines += r.line + "\n";
    ordered.push_back(r);
  }
  WriteFileAtomically((dir / kSamplesName).string(), lines);
  const std::string statistics = EnsembleJson(spec, ordered);
  WriteFileAtomically((dir / kStatisticsName).string(), statistics);
  WriteFileAtomically((dir / kReportName).string(), EnsembleReportHtml(spec, ordered, statistics));
}

}  // namespace

Spec WithSamples(Spec spec, int samples) {
  // a grid, one-at-a-time or table design has its own rows: fewer is a prefix, more do not exist
  const bool deterministic = spec.design == Design::kGrid || spec.design == Design::kOneAtATime || spec.design == Design::kTable;
  if (deterministic && samples > spec.samples)
    throw InputError(spec.file, "--samples", "this design has " + std::to_string(spec.samples) + " samples; expected at most that, got " +
                                             std::to_string(samples));
  // Saltelli counts rows of A and B
  if (spec.design == Design::kSaltelli) {
    if (samples == spec.base_samples) return spec;
    spec.base_samples = samples;
    samples *= static_cast<int>(spec.inputs.size()) + 2;
  }
  if (samples == spec.samples) return spec;
  spec.samples = samples;
  spec.hash = TextHash(HashText(spec.hash) + " samples " + std::to_string(samples));
  return spec;
}

namespace {

// the folder's side of a run: the lock, what is recorded already, the journal, and the results
class Collector {
 public:
  Collector(const Spec& spec, const RunOptions& options)
      : spec_(spec), options_(options), dir_(options.out_dir),
        folder_(options.out_dir, {kSamplesName, kStatisticsName, kJournalName, kReportName}, spec.input_files) {
    // what the folder already holds (a finished run, or the journal of a stopped one)
    ReadRecords(spec, dir_ / kSamplesName, &records_, true);
    ReadRecords(spec, dir_ / kJournalName, &records_, false);
    // a sample that ran over the time limit runs again (the limit is the machine's, not the spec's)
    for (auto it = records_.begin(); it != records_.end();) it = it->second.status == kTimedOut ? records_.erase(it) : std::next(it);
    RefuseOtherShards(options, records_);
    folder_.RecordOutputs();
    for (int i = options.shard - 1; i < spec.samples; i += options.shards) {
      ++counts_.total;
      if (records_.count(i)) ++counts_.resumed;
      else todo_.push_back(i);
    }
    journal_ = std::make_unique<Journal>(dir_ / kJournalName);
  }

  // the samples still to run below `end`
  std::vector<int> TodoBelow(int end) const {
    std::vector<int> todo;
    for (int i : todo_)
      if (i < end && !records_.count(i)) todo.push_back(i);
    return todo;
  }

  // a finished sample, kept as read back from its line (the same numbers after a resume): one a
  // worker rank sent, or one run here (RunSample reads its own line back)
  void Add(const std::string& line) { Add(ParseOwnRecord(spec_, line)); }
  void Add(const SampleRecord& record) {
    journal_->Append(record.line);
    std::lock_guard<std::mutex> lock(mutex_);
    records_.emplace(record.index, record);
    if (options_.progress) options_.progress(counts_.resumed + ++added_, counts_.total);
  }

  // the records so far (call between parallel sections)
  const std::map<int, SampleRecord>& records() const { return records_; }

  // counts, and the results once the shard is whole (up to `limit` samples when the stop
  // tolerance ended the run early)
  RunCounts Finish(int limit) {
    std::map<int, SampleRecord> mine;
    for (const auto& [index, r] : records_)
      if (index % options_.shards == options_.shard - 1 && index < limit) mine.emplace(index, r);
    if (limit < spec_.samples) {
      counts_.total = static_cast<int>(mine.size());
      counts_.resumed = std::min(counts_.resumed, counts_.total);
    }
    counts_.ran = static_cast<int>(mine.size()) - counts_.resumed;
    for (const auto& [index, r] : mine) {
      counts_.excluded += !r.in_statistics();
      counts_.voided += !r.in_statistics() && r.status == RunStatusName(RunStatus::kComplete);
      counts_.warned += r.in_statistics() && !r.warnings.empty();
    }
    counts_.finished = static_cast<int>(mine.size()) == counts_.total;
    if (counts_.finished) {
      WriteResults(spec_, mine, dir_);
      journal_.reset();
      fs::remove(dir_ / kJournalName);
    }
    return counts_;
  }

 private:
  const Spec& spec_;
  const RunOptions& options_;
  fs::path dir_;
  OutputFolder folder_;
  std::map<int, SampleRecord> records_;
  std::vector<int> todo_;
  RunCounts counts_;
  std::unique_ptr<Journal> journal_;
  std::mutex mutex_;
  int added_ = 0;
};

}  // namespace

namespace {

// mean, P5 and P95 of every output over the samples in the statistics with an index below `end`
using Checkpoint = std::map<std::string, std::array<double, 3>>;
Checkpoint CheckpointOf(const std::map<int, SampleRecord>& records, int end) {
  std::vector<SampleRecord> head;
  for (const auto& [index, r] : records)
    if (index < end) head.push_back(r);
  Checkpoint c;
  for (const auto& [name, s] : ComputeStatistics(head)) c[name] = {s.mean, s.p5, s.p95};
  return c;
}

// every figure moved by less than `tolerance` of its size since the previous checkpoint
bool Converged(const Checkpoint& before, const Checkpoint& now, double tolerance) {
  if (before.empty() || before.size() != now.size()) return false;
  for (const auto& [name, figures] : now) {
    const auto it = before.find(name);
    if (it == before.end()) return false;
    for (int k = 0; k < 3; ++k)
      if (std::abs(figures[k] - it->second[k]) > tolerance * std::max(std::abs(it->second[k]), 1e-12)) return false;
  }
  return true;
}

// the sample counts at which a run with a stop tolerance checks itself: min, 2 min, 4 min, ... samples
std::vector<int> Checkpoints(const Spec& spec) {
  std::vector<int> ends;
  for (int n = spec.stop_relative > 0.0 ? spec.stop_min_samples : spec.samples; n < spec.samples; n *= 2) ends.push_back(n);
  ends.push_back(spec.samples);
  return ends;
}

// the stop tolerance at a checkpoint: every output's mean, P5 and P95 settled since the previous one
bool SettledAt(const Spec& spec, const std::map<int, SampleRecord>& records, int end, Checkpoint* previous) {
  if (spec.stop_relative <= 0.0) return false;
  const Checkpoint now = CheckpointOf(records, end);
  const bool settled = Converged(*previous, now, spec.stop_relative);
  *previous = now;
  return settled;
}

}  // namespace

RunCounts RunEnsemble(const Spec& spec, const RunOptions& options) {
  if (spec.stop_relative > 0.0 && options.shards > 1)
    throw InputError(spec.file, "stop_tolerance", "needs the whole ensemble in one run (no --shard)");
  Collector collector(spec, options);
  const DesignTable design(spec);
  SharedAssets meshes;
  // the missing samples, on oneTBB, up to each checkpoint in turn; each record journaled as it completes
  int limit = spec.samples;
  Checkpoint previous;
  for (const int end : Checkpoints(spec)) {
    // below this checkpoint and not recorded yet (read before the parallel loop)
    const std::vector<int> todo = collector.TodoBelow(end);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, todo.size(), 1), [&](const tbb::blocked_range<std::size_t>& range) {
      for (std::size_t k = range.begin(); k != range.end(); ++k) {
        if (options.stop && options.stop()) return;
        collector.Add(RunSample(spec, todo[k], design.Values(todo[k]), &meshes, options.sample_time_limit));
      }
    });
    if (options.stop && options.stop()) break;
    if (SettledAt(spec, collector.records(), end, &previous)) {
      limit = end;
      break;
    }
  }
  return collector.Finish(limit);
}

#ifdef DYMESH_WITH_MPI
namespace {

constexpr int kTagRequest = 1, kTagChunk = 2, kTagRecord = 3;
constexpr int kChunk = 2;  // samples handed out at a time

// a worker: asks for chunks, runs them, returns each record, until an empty chunk
void MpiWorker(const Spec& spec, double time_limit) {
  const DesignTable design(spec);
  SharedAssets meshes;
  for (;;) {
    MPI_Send(nullptr, 0, MPI_INT, 0, kTagRequest, MPI_COMM_WORLD);
    int chunk[kChunk];
    MPI_Status status;
    MPI_Recv(chunk, kChunk, MPI_INT, 0, kTagChunk, MPI_COMM_WORLD, &status);
    int n = 0;
    MPI_Get_count(&status, MPI_INT, &n);
    if (n == 0) return;
    for (int k = 0; k < n; ++k) {
      const std::string line = RunSample(spec, chunk[k], design.Values(chunk[k]), &meshes, time_limit).line;
      MPI_Send(line.data(), static_cast<int>(line.size()), MPI_CHAR, 0, kTagRecord, MPI_COMM_WORLD);
    }
  }
}

// the master: hands out chunks on request (a dynamic queue), collects the records, stops the workers.
// With a stop tolerance it works checkpoint by checkpoint, as a threaded run does: a checkpoint's
// samples are handed out, its statistics judged once all their records are in, then the next one
RunCounts MpiMaster(const Spec& spec, const RunOptions& options, int size) {
  Collector collector(spec, options);
  const std::vector<int> ends = Checkpoints(spec);
  std::size_t phase = 0, next = 0;
  std::vector<int> todo = collector.TodoBelow(ends[0]);
  Checkpoint previous;
  int limit = spec.samples;
  bool done = false;
  std::deque<int> waiting;  // ranks that asked for work
  int outstanding = 0, stopped = 0;
  while (stopped < size - 1) {
    MPI_Status status;
    MPI_Probe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &status);
    if (status.MPI_TAG == kTagRecord) {
      int length = 0;
      MPI_Get_count(&status, MPI_CHAR, &length);
      std::string line(length, '\0');
      MPI_Recv(line.data(), length, MPI_CHAR, status.MPI_SOURCE, kTagRecord, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
      collector.Add(line);
      --outstanding;
    } else {
      MPI_Recv(nullptr, 0, MPI_INT, status.MPI_SOURCE, kTagRequest, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
      waiting.push_back(status.MPI_SOURCE);
    }
    // answer the waiting ranks (a record may complete the checkpoint they wait on)
    while (!waiting.empty()) {
      const bool stop = done || (options.stop && options.stop());
      if (!stop && next < todo.size()) {
        // the next chunk of this checkpoint
        int chunk[kChunk];
        int n = 0;
        while (n < kChunk && next < todo.size()) chunk[n++] = todo[next++];
        outstanding += n;
        MPI_Send(chunk, n, MPI_INT, waiting.front(), kTagChunk, MPI_COMM_WORLD);
        waiting.pop_front();
        continue;
      }
      if (!stop) {
        // the checkpoint is handed out: wait for its last records, then judge it
        if (outstanding > 0) break;
        if (SettledAt(spec, collector.records(), ends[phase], &previous)) {
          limit = ends[phase];
          done = true;
        } else if (++phase == ends.size()) {
          done = true;
        } else {
          todo = collector.TodoBelow(ends[phase]);
          next = 0;
        }
        continue;
      }
      // no more work: an empty chunk ends the worker
      MPI_Send(nullptr, 0, MPI_INT, waiting.front(), kTagChunk, MPI_COMM_WORLD);
      waiting.pop_front();
      ++stopped;
    }
  }
  return collector.Finish(limit);
}

}  // namespace

RunCounts RunEnsembleMpi(const Spec& spec, const RunOptions& options, int rank, int size) {
  if (size <= 1) return RunEnsemble(spec, options);
  if (rank != 0) {
    MpiWorker(spec, options.sample_time_limit);
    return RunCounts{};
  }
  return MpiMaster(spec, options, size);
}
#endif

void MergeShards(const Spec& spec, const std::vector<std::string>& shard_dirs, const std::string& out_dir) {
  std::map<int, SampleRecord> records;
  for (const std::string& shard : shard_dirs) {
    // a shard is a folder an ensemble wrote: a typo is refused, not merged as an empty shard
    std::error_code error;
    if (!fs::is_regular_file(fs::path(shard) / kSamplesName, error))
      throw InputError(shard, kSamplesName, "missing: expected a shard folder holding samples.jsonl");
    // the merged ensemble goes to its own folder: written into a shard, it would replace that shard's records
    if (fs::equivalent(shard, out_dir, error))
      throw InputError(out_dir, "--out", "is the shard folder " + shard + ": merge into a new folder");
    std::map<int, SampleRecord> part;
    ReadRecords(spec, fs::path(shard) / kSamplesName, &part, true);
    for (auto& [index, r] : part)
      if (!records.emplace(index, r).second)
        throw InputError(shard, kSamplesName, "sample " + std::to_string(index) + " is in more than one shard");
  }
  for (int i = 0; i < spec.samples; ++i)
    if (!records.count(i))
      throw InputError(out_dir, kSamplesName, "sample " + std::to_string(i) + " is in no shard: run it, then merge again");
  OutputFolder folder(out_dir, {kSamplesName, kStatisticsName, kReportName}, spec.input_files);
  folder.RecordOutputs();
  WriteResults(spec, records, fs::path(out_dir));
}

}  // namespace dymesh::ensemble
