#include "dymesh/ensemble/ensemble_run.h"

#include <fcntl.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <filesystem>
#include <fstream>
#include <map>
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

namespace dymesh::ensemble {
namespace {

namespace fs = std::filesystem;

constexpr const char* kSamplesName = "samples.jsonl";
constexpr const char* kStatisticsName = "ensemble.json";
constexpr const char* kJournalName = "samples.journal.jsonl";
constexpr const char* kReportName = "report.html";

// the valid records of `file` (a missing file has none); a record of another spec is refused
void ReadRecords(const Spec& spec, const fs::path& file, std::map<int, SampleRecord>* records) {
  std::ifstream in(file);
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    SampleRecord r;
    if (ParseRecord(spec, line, &r)) {
      if (r.index >= 0 && r.index < spec.samples) records->emplace(r.index, r);
      continue;
    }
    // a whole line of another spec: the folder is someone else's
    if (line.find("\"spec_hash\"") != std::string::npos && line.find(HashText(spec.hash)) == std::string::npos &&
        line.back() == '}')
      throw InputError(file.string(), "spec_hash",
                       "the folder holds samples of another spec (not " + HashText(spec.hash) +
                           "): use another --out, or remove the folder to start again");
  }
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
  WriteFileAtomically((dir / kStatisticsName).string(), EnsembleJson(spec, ordered));
  WriteFileAtomically((dir / kReportName).string(), EnsembleReportHtml(spec, ordered));
}

}  // namespace

Spec WithSamples(Spec spec, int samples) {
  if (samples == spec.samples) return spec;
  spec.samples = samples;
  spec.hash = TextHash(HashText(spec.hash) + " samples " + std::to_string(samples));
  return spec;
}

RunCounts RunEnsemble(const Spec& spec, const RunOptions& options) {
  const fs::path dir(options.out_dir);
  OutputFolder folder(options.out_dir, {kSamplesName, kStatisticsName, kJournalName, kReportName});
  // what the folder already holds (a finished run, or the journal of a stopped one)
  std::map<int, SampleRecord> records;
  ReadRecords(spec, dir / kSamplesName, &records);
  ReadRecords(spec, dir / kJournalName, &records);
  std::vector<int> todo;
  RunCounts counts;
  for (int i = options.shard - 1; i < spec.samples; i += options.shards) {
    ++counts.total;
    if (records.count(i)) ++counts.resumed;
    else todo.push_back(i);
  }
  // the missing samples, on oneTBB; each record journaled as it completes
  const DesignTable design(spec);
  MeshCache meshes;
  Journal journal(dir / kJournalName);
  std::mutex records_mutex;
  std::atomic<int> done{counts.resumed};
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, todo.size(), 1), [&](const tbb::blocked_range<std::size_t>& range) {
    for (std::size_t k = range.begin(); k != range.end(); ++k) {
      if (options.stop && options.stop()) return;
      SampleRecord r = RunSample(spec, todo[k], design.Values(todo[k]), &meshes);
      journal.Append(r.line);
      // the statistics read the record back as written (the same numbers after a resume)
      SampleRecord stored;
      ParseRecord(spec, r.line, &stored);
      {
        std::lock_guard<std::mutex> lock(records_mutex);
        records.emplace(stored.index, stored);
      }
      if (options.progress) options.progress(++done, counts.total);
    }
  });
  // counts, and the results once the shard is whole
  std::map<int, SampleRecord> mine;
  for (const auto& [index, r] : records)
    if (index % options.shards == options.shard - 1) mine.emplace(index, r);
  counts.ran = static_cast<int>(mine.size()) - counts.resumed;
  for (const auto& [index, r] : mine) counts.failed += r.status != "complete";
  counts.finished = static_cast<int>(mine.size()) == counts.total;
  if (counts.finished) {
    WriteResults(spec, mine, dir);
    fs::remove(dir / kJournalName);
  }
  return counts;
}

void MergeShards(const Spec& spec, const std::vector<std::string>& shard_dirs, const std::string& out_dir) {
  std::map<int, SampleRecord> records;
  for (const std::string& shard : shard_dirs) {
    std::map<int, SampleRecord> part;
    ReadRecords(spec, fs::path(shard) / kSamplesName, &part);
    for (auto& [index, r] : part)
      if (!records.emplace(index, r).second)
        throw InputError(shard, kSamplesName, "sample " + std::to_string(index) + " is in more than one shard");
  }
  for (int i = 0; i < spec.samples; ++i)
    if (!records.count(i))
      throw InputError(out_dir, kSamplesName, "sample " + std::to_string(i) + " is in no shard: run it, then merge again");
  OutputFolder folder(out_dir, {kSamplesName, kStatisticsName, kReportName});
  WriteResults(spec, records, fs::path(out_dir));
}

}  // namespace dymesh::ensemble
