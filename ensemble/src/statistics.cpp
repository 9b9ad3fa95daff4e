#include "dymesh/ensemble/statistics.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>

namespace dymesh::ensemble {

double Percentile(const std::vector<double>& sorted, double q) {
  if (sorted.empty()) return 0.0;
  const double h = (sorted.size() - 1) * q;
  const std::size_t lo = static_cast<std::size_t>(std::floor(h));
  const std::size_t hi = std::min(lo + 1, sorted.size() - 1);
  return sorted[lo] + (h - lo) * (sorted[hi] - sorted[lo]);
}

std::map<std::string, OutputStatistics> ComputeStatistics(const std::vector<SampleRecord>& records) {
  // the values of each output, in sample order
  std::map<std::string, std::vector<double>> values;
  for (const SampleRecord& r : records)
    for (const auto& [name, v] : r.outputs) values[name].push_back(v);
  std::map<std::string, OutputStatistics> stats;
  for (auto& [name, v] : values) {
    OutputStatistics s;
    s.n = static_cast<int>(v.size());
    double sum = 0.0;
    for (double x : v) sum += x;
    s.mean = sum / s.n;
    double squares = 0.0;
    for (double x : v) squares += (x - s.mean) * (x - s.mean);
    s.sd = s.n > 1 ? std::sqrt(squares / (s.n - 1)) : 0.0;
    std::sort(v.begin(), v.end());
    s.min = v.front(), s.max = v.back();
    s.p5 = Percentile(v, 0.05), s.p50 = Percentile(v, 0.5), s.p95 = Percentile(v, 0.95);
    stats[name] = s;
  }
  return stats;
}

std::string EnsembleJson(const Spec& spec, const std::vector<SampleRecord>& records) {
  nlohmann::json j;
  j["spec_hash"] = HashText(spec.hash);
  j["engine_version"] = kEngineVersion;
  j["samples"] = records.size();
  // counts by status: only complete samples enter the statistics
  nlohmann::json counts = nlohmann::json::object();
  for (const SampleRecord& r : records) counts[r.status] = counts.value(r.status, 0) + 1;
  j["status_counts"] = counts;
  const auto stats = ComputeStatistics(records);
  for (const auto& [name, s] : stats)
    j["outputs"][name] = {{"n", s.n}, {"mean", s.mean}, {"sd", s.sd}, {"min", s.min}, {"max", s.max},
                          {"p5", s.p5}, {"p50", s.p50}, {"p95", s.p95}};
  // exceedance: P(output > threshold) over the complete samples
  for (const Threshold& t : spec.thresholds) {
    int above = 0, n = 0;
    for (const SampleRecord& r : records)
      if (const auto it = r.outputs.find(t.output); it != r.outputs.end()) {
        ++n;
        above += it->second > t.above;
      }
    j["exceedance"].push_back({{"output", t.output}, {"above", t.above}, {"n", n},
                               {"probability", n > 0 ? static_cast<double>(above) / n : 0.0}});
  }
  return j.dump(2) + "\n";
}

}  // namespace dymesh::ensemble
