#include "dymesh/ensemble/statistics.h"

#include <nlohmann/json.hpp>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numeric>

#include "dymesh/analysis/run_assessment.h"
#include "dymesh/ensemble/random_stream.h"

namespace dymesh::ensemble {

double Percentile(const std::vector<double>& sorted, double q) {
  if (sorted.empty()) return 0.0;
  const double h = (sorted.size() - 1) * q;
  const std::size_t lo = static_cast<std::size_t>(std::floor(h));
  const std::size_t hi = std::min(lo + 1, sorted.size() - 1);
  return sorted[lo] + (h - lo) * (sorted[hi] - sorted[lo]);
}

namespace {

// ranks 1..n, ties averaged
std::vector<double> Ranks(const std::vector<double>& v) {
  std::vector<int> order(v.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return v[a] < v[b]; });
  std::vector<double> rank(v.size());
  for (std::size_t i = 0; i < order.size();) {
    std::size_t j = i;
    while (j + 1 < order.size() && v[order[j + 1]] == v[order[i]]) ++j;
    for (std::size_t k = i; k <= j; ++k) rank[order[k]] = 0.5 * (i + j) + 1.0;
    i = j + 1;
  }
  return rank;
}

// Pearson correlation; 0 when either side is constant
double Pearson(const std::vector<double>& x, const std::vector<double>& y) {
  const double n = static_cast<double>(x.size());
  const double mx = std::accumulate(x.begin(), x.end(), 0.0) / n, my = std::accumulate(y.begin(), y.end(), 0.0) / n;
  double sxy = 0.0, sxx = 0.0, syy = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    sxy += (x[i] - mx) * (y[i] - my);
    sxx += (x[i] - mx) * (x[i] - mx);
    syy += (y[i] - my) * (y[i] - my);
  }
  return sxx > 0.0 && syy > 0.0 ? sxy / std::sqrt(sxx * syy) : 0.0;
}

// a sorted copy's percentile
double SortedPercentile(std::vector<double>& v, double q) {
  std::sort(v.begin(), v.end());
  return Percentile(v, q);
}

// the Sobol' block of one output: rows whose A, B and AB_i runs all completed
nlohmann::json SobolJson(const Spec& spec, const std::vector<SampleRecord>& records, const std::string& name) {
  std::map<int, double> value;
  for (const SampleRecord& r : records)
    if (const auto it = r.outputs.find(name); it != r.outputs.end()) value[r.index] = it->second;
  const int k = static_cast<int>(spec.inputs.size()), group = k + 2;
  nlohmann::json out = nlohmann::json::object();
  for (int i = 0; i < k; ++i) {
    std::vector<double> fa, fb, fab;
    for (int j = 0; j < spec.base_samples; ++j) {
      const auto a = value.find(j * group), b = value.find(j * group + 1), ab = value.find(j * group + 2 + i);
      if (a == value.end() || b == value.end() || ab == value.end()) continue;
      fa.push_back(a->second), fb.push_back(b->second), fab.push_back(ab->second);
    }
    const SobolIndices s = SobolFromSaltelli(fa, fb, fab);
    // bootstrap over the rows
    std::vector<double> firsts, totals;
    const std::uint64_t id = TextHash("sobol " + name + " " + spec.inputs[i].name);
    for (int b = 0; b < 200 && fa.size() >= 2; ++b) {
      std::vector<double> ra, rb, rab;
      for (std::size_t j = 0; j < fa.size(); ++j) {
        const std::size_t pick = std::min(fa.size() - 1, static_cast<std::size_t>(Uniform(spec.seed, id, b, static_cast<std::uint32_t>(j)) * fa.size()));
        ra.push_back(fa[pick]), rb.push_back(fb[pick]), rab.push_back(fab[pick]);
      }
      const SobolIndices e = SobolFromSaltelli(ra, rb, rab);
      firsts.push_back(e.first), totals.push_back(e.total);
    }
    std::sort(firsts.begin(), firsts.end());
    std::sort(totals.begin(), totals.end());
    out[spec.inputs[i].name] = {{"first", s.first}, {"total", s.total}, {"rows", fa.size()},
                                {"first_ci95", {Percentile(firsts, 0.025), Percentile(firsts, 0.975)}},
                                {"total_ci95", {Percentile(totals, 0.025), Percentile(totals, 0.975)}}};
  }
  return out;
}

// the one-at-a-time swings of one output: each input at its 5th and 95th percentile, the others at
// their medians (samples not in the statistics are left out)
nlohmann::json OneAtATimeJson(const Spec& spec, const std::vector<SampleRecord>& records, const std::string& name) {
  std::map<int, double> value;
  for (const SampleRecord& r : records)
    if (const auto it = r.outputs.find(name); it != r.outputs.end()) value[r.index] = it->second;
  nlohmann::json out = nlohmann::json::object();
  if (value.count(0)) out["baseline"] = value[0];
  for (std::size_t i = 0; i < spec.inputs.size(); ++i) {
    const int low = static_cast<int>(1 + 2 * i), high = low + 1;
    if (!value.count(low) || !value.count(high)) continue;
    out["inputs"][spec.inputs[i].name] = {{"at_p5", value[low]}, {"at_p95", value[high]}, {"swing", value[high] - value[low]}};
  }
  return out;
}

// the weighted mean, SD and 5/50/95 % quantiles of values with weights
nlohmann::json WeightedSummary(std::vector<std::pair<double, double>> vw) {
  std::sort(vw.begin(), vw.end());
  double sum = 0.0, mean = 0.0;
  for (const auto& [v, w] : vw) sum += w, mean += v * w;
  if (!(sum > 0.0)) return nullptr;
  mean /= sum;
  double var = 0.0;
  for (const auto& [v, w] : vw) var += w * (v - mean) * (v - mean);
  nlohmann::json out = {{"mean", mean}, {"sd", std::sqrt(var / sum)}};
  for (const auto& [key, q] : {std::pair{"p5", 0.05}, std::pair{"p50", 0.5}, std::pair{"p95", 0.95}}) {
    double acc = 0.0;
    for (const auto& [v, w] : vw)
      if ((acc += w) >= q * sum) {
        out[key] = v;
        break;
      }
  }
  return out;
}

// weighted mean, SD and percentiles of every input and output over the samples of positive weight
nlohmann::json WeightedInputsAndOutputs(const Spec& spec, const std::vector<SampleRecord>& records, const std::vector<double>& w) {
  nlohmann::json out;
  for (std::size_t k = 0; k < spec.inputs.size(); ++k) {
    std::vector<std::pair<double, double>> vw;
    for (std::size_t i = 0; i < records.size(); ++i)
      if (w[i] > 0.0 && k < records[i].inputs.size()) vw.push_back({records[i].inputs[k], w[i]});
    out["inputs"][spec.inputs[k].name] = WeightedSummary(vw);
  }
  std::map<std::string, std::vector<std::pair<double, double>>> outputs;
  for (std::size_t i = 0; i < records.size(); ++i)
    if (w[i] > 0.0)
      for (const auto& [name, v] : records[i].outputs) outputs[name].push_back({v, w[i]});
  out["outputs"] = nlohmann::json::object();
  for (auto& [name, vw] : outputs) out["outputs"][name] = WeightedSummary(vw);
  return out;
}

// posterior statistics of every input and output, the samples weighed by the evidence
nlohmann::json PosteriorJson(const Spec& spec, const std::vector<SampleRecord>& records) {
  double effective = 0.0;
  const std::vector<double> w = EvidenceWeights(spec, records, &effective);
  nlohmann::json out;
  out["effective_sample_size"] = effective;
  // a posterior carried by a handful of samples: its percentiles are those samples' values
  if (effective < kMinEffectiveSamples) {
    char text[320];
    std::snprintf(text, sizeof text,
                  "the evidence leaves an effective sample size of %.1f, under %.0f (P5 and P95 each need a sample "
                  "beyond them): the posterior statistics are not resolved; run more samples or check the evidence "
                  "against the prior's outputs", effective, kMinEffectiveSamples);
    out["warning"] = text;
  }
  for (const Evidence& e : spec.evidence) out["evidence"].push_back({{"observable", e.observable}, {"value", e.value}, {"sd", e.sd}});
  const nlohmann::json posterior = WeightedInputsAndOutputs(spec, records, w);
  out["inputs"] = posterior["inputs"];
  out["outputs"] = posterior["outputs"];
  // the prior by the same estimator (every sample in the statistics weighed 1), to compare like with like
  std::vector<double> ones(records.size(), 0.0);
  for (std::size_t i = 0; i < records.size(); ++i) ones[i] = records[i].in_statistics() ? 1.0 : 0.0;
  out["prior"] = WeightedInputsAndOutputs(spec, records, ones);
  return out;
}

}  // namespace

double Spearman(const std::vector<double>& x, const std::vector<double>& y) { return Pearson(Ranks(x), Ranks(y)); }

std::vector<double> PartialRankCorrelation(const std::vector<std::vector<double>>& x, const std::vector<double>& y) {
  const std::size_t n = y.size(), k = x.empty() ? 0 : x.front().size();
  std::vector<double> prcc(k, 0.0);
  // the inputs that vary, with the output, as rank columns
  std::vector<std::vector<double>> columns;
  std::vector<int> which;
  for (std::size_t c = 0; c < k; ++c) {
    std::vector<double> col(n);
    for (std::size_t i = 0; i < n; ++i) col[i] = x[i][c];
    if (*std::max_element(col.begin(), col.end()) == *std::min_element(col.begin(), col.end())) continue;
    columns.push_back(Ranks(col));
    which.push_back(static_cast<int>(c));
  }
  const std::vector<double> ry = Ranks(y);
  const int m = static_cast<int>(columns.size());
  if (m < 1 || n < static_cast<std::size_t>(m) + 2) return prcc;
  // each input: the correlation of its ranks and the output's ranks, both with the other inputs'
  // ranks regressed out (least squares; robust when the output follows one input exactly)
  for (int a = 0; a < m; ++a) {
    Eigen::MatrixXd others(n, m);  // intercept and the other columns
    others.col(0).setOnes();
    for (int b = 0, c = 1; b < m; ++b)
      if (b != a) others.col(c++) = Eigen::Map<const Eigen::VectorXd>(columns[b].data(), n);
    const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(others);
    const Eigen::VectorXd xa = Eigen::Map<const Eigen::VectorXd>(columns[a].data(), n);
    const Eigen::VectorXd yy = Eigen::Map<const Eigen::VectorXd>(ry.data(), n);
    const Eigen::VectorXd rx = xa - others * qr.solve(xa), rr = yy - others * qr.solve(yy);
    const double denominator = std::sqrt(rx.squaredNorm() * rr.squaredNorm());
    prcc[which[a]] = denominator > 0.0 ? rx.dot(rr) / denominator : 0.0;
  }
  return prcc;
}

Interval Bootstrap95(const std::vector<double>& values, const std::function<double(std::vector<double>&)>& statistic,
                     std::uint64_t seed, const std::string& stream, int resamples) {
  const std::uint64_t id = TextHash("bootstrap " + stream);
  std::vector<double> estimates, draw(values.size());
  for (int b = 0; b < resamples; ++b) {
    for (std::size_t i = 0; i < values.size(); ++i)
      draw[i] = values[std::min(values.size() - 1, static_cast<std::size_t>(Uniform(seed, id, b, static_cast<std::uint32_t>(i)) * values.size()))];
    estimates.push_back(statistic(draw));
  }
  std::sort(estimates.begin(), estimates.end());
  return {Percentile(estimates, 0.025), Percentile(estimates, 0.975)};
}

SobolIndices SobolFromSaltelli(const std::vector<double>& fa, const std::vector<double>& fb, const std::vector<double>& fab) {
  const std::size_t n = fa.size();
  if (n < 2) return {};
  double sum = 0.0, squares = 0.0;
  for (std::size_t j = 0; j < n; ++j) sum += fa[j] + fb[j];
  const double mean = sum / (2.0 * n);
  for (std::size_t j = 0; j < n; ++j) squares += (fa[j] - mean) * (fa[j] - mean) + (fb[j] - mean) * (fb[j] - mean);
  const double variance = squares / (2.0 * n - 1.0);
  if (!(variance > 0.0)) return {};
  double first = 0.0, total = 0.0;
  for (std::size_t j = 0; j < n; ++j) {
    first += (fb[j] - mean) * (fab[j] - fa[j]);  // centred: the same expectation, far less variance
    total += (fa[j] - fab[j]) * (fa[j] - fab[j]);
  }
  return {first / n / variance, total / (2.0 * n) / variance};
}

std::vector<double> EvidenceWeights(const Spec& spec, const std::vector<SampleRecord>& records, double* effective) {
  // log-likelihoods first (relative to the best sample: no underflow)
  std::vector<double> log_w(records.size(), -std::numeric_limits<double>::infinity());
  double best = -std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < records.size(); ++i) {
    if (!records[i].in_statistics()) continue;
    double l = 0.0;
    bool known = true;
    for (const Evidence& e : spec.evidence) {
      const auto it = records[i].observables.find(e.observable);
      if (it == records[i].observables.end()) {
        known = false;
        break;
      }
      const double z = (it->second - e.value) / e.sd;
      l -= 0.5 * z * z;
    }
    if (!known) continue;
    log_w[i] = l;
    best = std::max(best, l);
  }
  std::vector<double> w(records.size(), 0.0);
  double sum = 0.0, squares = 0.0;
  for (std::size_t i = 0; i < records.size(); ++i) {
    if (!std::isfinite(log_w[i])) continue;
    w[i] = std::exp(log_w[i] - best);
    sum += w[i];
    squares += w[i] * w[i];
  }
  *effective = squares > 0.0 ? sum * sum / squares : 0.0;
  return w;
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
  // a stop tolerance that ended the run before its sample count
  if (spec.stop_relative > 0.0 && static_cast<int>(records.size()) < spec.samples) j["converged_at_samples"] = records.size();
  // counts by status, and of the complete samples a warning voids: the rest enter the statistics,
  // counted by the warnings they carry (each code once per sample)
  nlohmann::json counts = nlohmann::json::object(), voided = nlohmann::json::object(), kept = nlohmann::json::object();
  int used = 0;
  for (const SampleRecord& r : records) {
    counts[r.status] = counts.value(r.status, 0) + 1;
    used += r.in_statistics();
    for (const std::string& code : r.warning_codes()) {
      if (r.in_statistics()) kept[code] = kept.value(code, 0) + 1;
      else if (r.status == RunStatusName(RunStatus::kComplete) && WarningVoidsResults(code))
        voided[code] = voided.value(code, 0) + 1;
    }
  }
  j["status_counts"] = counts;
  j["voided_by_warning"] = voided;
  j["kept_with_warning"] = kept;
  j["in_statistics"] = used;
  const auto stats = ComputeStatistics(records);
  for (const auto& [name, s] : stats) {
    nlohmann::json& o = j["outputs"][name];
    o = {{"n", s.n}, {"mean", s.mean}, {"sd", s.sd}, {"min", s.min}, {"max", s.max},
         {"p5", s.p5}, {"p50", s.p50}, {"p95", s.p95}};
    // the output's values and inputs over the samples in the statistics, in index order
    std::vector<double> v;
    std::vector<std::vector<double>> x;
    for (const SampleRecord& r : records)
      if (const auto it = r.outputs.find(name); it != r.outputs.end()) {
        v.push_back(it->second);
        x.push_back(r.inputs);
      }
    // bootstrap 95 % intervals of the mean and the percentiles
    const auto mean = [](std::vector<double>& d) { return std::accumulate(d.begin(), d.end(), 0.0) / d.size(); };
    for (const auto& [key, q] : {std::pair{"p5", 0.05}, std::pair{"p50", 0.5}, std::pair{"p95", 0.95}}) {
      const Interval ci = Bootstrap95(v, [q = q](std::vector<double>& d) { return SortedPercentile(d, q); }, spec.seed, name + key);
      o["ci95"][key] = {ci.low, ci.high};
    }
    const Interval ci = Bootstrap95(v, mean, spec.seed, name + "mean");
    o["ci95"]["mean"] = {ci.low, ci.high};
    // running convergence of the mean and the 5th and 95th percentiles against N
    for (std::size_t n = 10; n <= v.size(); n = n < 20 ? 20 : n < 50 ? 50 : n * 2) {
      std::vector<double> head(v.begin(), v.begin() + n);
      const double m = mean(head);
      o["convergence"].push_back({{"n", n}, {"mean", m}, {"p5", SortedPercentile(head, 0.05)}, {"p95", SortedPercentile(head, 0.95)}});
    }
    // Saltelli's design: Sobol' first-order and total indices per input, with bootstrap intervals
    if (spec.design == Design::kSaltelli) o["sobol"] = SobolJson(spec, records, name);
    if (spec.design == Design::kOneAtATime) o["one_at_a_time"] = OneAtATimeJson(spec, records, name);
    // sensitivity: Spearman and partial rank correlation of every input with this output
    const std::vector<double> prcc = PartialRankCorrelation(x, v);
    for (std::size_t k = 0; k < spec.inputs.size() && !x.empty(); ++k) {
      std::vector<double> input(x.size());
      for (std::size_t i = 0; i < x.size(); ++i) input[i] = x[i][k];
      o["sensitivity"][spec.inputs[k].name] = {{"spearman", Spearman(input, v)}, {"prcc", prcc[k]}};
    }
  }
  // exceedance: P(output > threshold) over the samples in the statistics
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
  if (!spec.evidence.empty()) j["posterior"] = PosteriorJson(spec, records);
  return j.dump(2) + "\n";
}

}  // namespace dymesh::ensemble
