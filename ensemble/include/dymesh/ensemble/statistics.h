#pragma once
#include <cstdint>
#include <functional>
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

/// Spearman's rank correlation (ties get their average rank); 0 when either side is constant.
double Spearman(const std::vector<double>& x, const std::vector<double>& y);

/// Partial rank correlation of each column of `x` (n samples by k inputs) with `y`, the other
/// columns held out (through the inverse of the rank correlation matrix); 0 for a constant input.
std::vector<double> PartialRankCorrelation(const std::vector<std::vector<double>>& x, const std::vector<double>& y);

/// A percentile bootstrap 95 % interval of `statistic` over `values` (B resamples drawn from the
/// counter-based stream named `stream`, so it is reproducible).
struct Interval {
  double low, high;
};
Interval Bootstrap95(const std::vector<double>& values, const std::function<double(std::vector<double>&)>& statistic,
                     std::uint64_t seed, const std::string& stream, int resamples = 400);

/// Sobol' first-order and total indices of one input from Saltelli's runs: f(A_j), f(B_j), f(AB_i,j)
/// for the rows j where all three are known (Saltelli 2010 first order with f(B) centred, Jansen
/// total), over the variance of f(A) and f(B) together.
struct SobolIndices {
  double first = 0.0, total = 0.0;
};
SobolIndices SobolFromSaltelli(const std::vector<double>& fa, const std::vector<double>& fb, const std::vector<double>& fab);

/// The evidence weights of the records (0 for those not in the statistics or missing an observable), and
/// their effective sample size (sum w)^2 / sum w^2.
std::vector<double> EvidenceWeights(const Spec& spec, const std::vector<SampleRecord>& records, double* effective);

/// Fewer effective samples than this leave the posterior's 5 % tails without one sample each (1 / 0.05).
inline constexpr double kMinEffectiveSamples = 20.0;

/// ensemble.json text: counts by status, statistics per output, exceedance probabilities.
std::string EnsembleJson(const Spec& spec, const std::vector<SampleRecord>& records);

}  // namespace dymesh::ensemble
