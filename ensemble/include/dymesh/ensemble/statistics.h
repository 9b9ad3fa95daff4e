#pragma once
#include <map>
#include <string>
#include <vector>

#include "dymesh/ensemble/sample_run.h"

/// Statistics of an ensemble's complete samples, per output, and the count of the others.
namespace dymesh::ensemble {

struct OutputStatistics {
  int n = 0;
  double mean = 0.0, sd = 0.0;         ///< sd with n - 1
  double min = 0.0, max = 0.0;
  double p5 = 0.0, p50 = 0.0, p95 = 0.0;  ///< linear interpolation between order statistics (type 7)
};

/// The percentile q in [0, 1] of sorted values (type 7: (n - 1) q, interpolated).
double Percentile(const std::vector<double>& sorted, double q);

/// Per output over the complete samples, in index order (so the sums are reproducible).
std::map<std::string, OutputStatistics> ComputeStatistics(const std::vector<SampleRecord>& records);

/// ensemble.json text: counts by status, statistics per output, exceedance probabilities.
std::string EnsembleJson(const Spec& spec, const std::vector<SampleRecord>& records);

}  // namespace dymesh::ensemble
