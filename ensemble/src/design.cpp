#include "dymesh/ensemble/design.h"

#include <algorithm>
#include <numeric>

#include "dymesh/ensemble/random_stream.h"
#include "dymesh/ensemble/sobol_sequence.h"

namespace dymesh::ensemble {
namespace {

// the draws of an input's stream (random_stream.h): one number per (sample or row, draw)
constexpr std::uint32_t kValueDraw = 0;        // Monte Carlo value; the place inside an LHS stratum; Saltelli's A
constexpr std::uint32_t kStratumKeyDraw = 1;   // LHS: the key that orders the samples into strata
constexpr std::uint32_t kSaltelliBDraw = 2;    // Saltelli's B
constexpr std::uint32_t kSobolSeedDraw = 3;    // Sobol': the scramble seed (row 0 only)

}  // namespace

DesignTable::DesignTable(const Spec& spec) : spec_(spec) {
  if (spec.design != Design::kLatinHypercube) return;
  // per input, the samples ordered by a random key of their own: sample j takes stratum rank(j)
  for (const Input& in : spec.inputs) {
    const std::uint64_t stream = TextHash(in.name);
    std::vector<std::pair<double, int>> keys(spec.samples);
    for (int j = 0; j < spec.samples; ++j) keys[j] = {Uniform(spec.seed, stream, j, kStratumKeyDraw), j};
    std::sort(keys.begin(), keys.end());
    std::vector<int> stratum(spec.samples);
    for (int rank = 0; rank < spec.samples; ++rank) stratum[keys[rank].second] = rank;
    strata_.push_back(std::move(stratum));
  }
  if (!spec.correlation.inputs.empty()) InduceRankCorrelation();
}

void DesignTable::InduceRankCorrelation() {
  // Iman and Conover (1982): the correlated inputs keep their strata, re-paired between samples so
  // that their ranks follow normal scores carrying the copula's correlation. Scores: van der
  // Waerden's of each input's current strata (independent random permutations)
  const Correlation& c = spec_.correlation;
  const int n = spec_.samples, k = static_cast<int>(c.inputs.size());
  Eigen::MatrixXd scores(n, k);
  for (int a = 0; a < k; ++a)
    for (int j = 0; j < n; ++j) scores(j, a) = NormalQuantile((strata_[c.inputs[a]][j] + 0.5) / n);
  // the scores' own correlation E = Q Q^T is replaced by the target P = L L^T: rows s -> L Q^-1 s
  const Eigen::MatrixXd centred = scores.rowwise() - scores.colwise().mean();
  const Eigen::MatrixXd covariance = centred.transpose() * centred / std::max(n - 1, 1);
  const Eigen::VectorXd sd = covariance.diagonal().cwiseSqrt();
  const Eigen::MatrixXd own = covariance.cwiseQuotient(sd * sd.transpose());
  const Eigen::LLT<Eigen::MatrixXd> llt(own);
  if (llt.info() != Eigen::Success) return;  // too few samples to carry a correlation: left independent
  const Eigen::MatrixXd target = (c.cholesky * llt.matrixL().solve(scores.transpose())).transpose();
  // each input's strata handed out in the order of its target column (ties: lower sample first)
  for (int a = 0; a < k; ++a) {
    std::vector<int> order(n);
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](int x, int y) { return target(x, a) < target(y, a); });
    for (int rank = 0; rank < n; ++rank) strata_[c.inputs[a]][order[rank]] = rank;
  }
}

std::vector<double> DesignTable::Values(int sample) const {
  if (spec_.design == Design::kTable) return spec_.table[sample];
  if (spec_.design == Design::kGrid || spec_.design == Design::kOneAtATime) return Deterministic(sample);
  // each input's uniform number; Latin hypercube places it inside the sample's stratum
  std::vector<double> u;
  const int group = static_cast<int>(spec_.inputs.size()) + 2;
  for (std::size_t k = 0; k < spec_.inputs.size(); ++k) {
    const std::uint64_t stream = TextHash(spec_.inputs[k].name);
    if (spec_.design == Design::kSaltelli) {
      // row j of A (draw 0) or of B (draw 2); AB_i takes input i from B
      const int j = sample / group, m = sample % group;
      const bool from_b = m == 1 || m == 2 + static_cast<int>(k);
      u.push_back(Uniform(spec_.seed, stream, j, from_b ? kSaltelliBDraw : kValueDraw));
      continue;
    }
    if (spec_.design == Design::kSobol) {
      // the input's dimension, Owen-scrambled by a random 32-bit seed of its own stream
      const auto seed = static_cast<std::uint32_t>(Uniform(spec_.seed, stream, 0, kSobolSeedDraw) * 4294967296.0);
      u.push_back(ScrambledSobolCoordinate(static_cast<std::uint64_t>(sample), static_cast<int>(k), seed));
      continue;
    }
    u.push_back(Uniform(spec_.seed, stream, sample, kValueDraw));
    if (spec_.design == Design::kLatinHypercube) u[k] = (strata_[k][sample] + u[k]) / spec_.samples;
  }
  // Gaussian copula: the correlated inputs' normal scores mixed by the Cholesky factor (Latin
  // hypercube: induced on the strata instead, so every input stays stratified)
  const Correlation& c = spec_.correlation;
  if (!c.inputs.empty() && spec_.design != Design::kLatinHypercube) {
    Eigen::VectorXd z(c.inputs.size());
    for (std::size_t a = 0; a < c.inputs.size(); ++a) z[a] = NormalQuantile(u[c.inputs[a]]);
    const Eigen::VectorXd mixed = c.cholesky * z;
    for (std::size_t a = 0; a < c.inputs.size(); ++a) u[c.inputs[a]] = NormalCdf(mixed[a]);
  }
  std::vector<double> values;
  for (std::size_t k = 0; k < spec_.inputs.size(); ++k) values.push_back(Quantile(spec_.inputs[k].distribution, u[k]));
  return values;
}

std::vector<double> DesignTable::Deterministic(int sample) const {
  std::vector<double> values;
  int rest = sample;
  for (std::size_t k = 0; k < spec_.inputs.size(); ++k) {
    const Input& in = spec_.inputs[k];
    double u = 0.5;
    if (spec_.design == Design::kGrid) {
      // mixed radix, the first input fastest: level l sits at the probability (l + 1/2) / levels
      u = (rest % in.levels + 0.5) / in.levels;
      rest /= in.levels;
    } else if (sample > 0 && static_cast<int>(k) == (sample - 1) / 2) {
      u = (sample - 1) % 2 == 0 ? 0.05 : 0.95;
    }
    values.push_back(Quantile(in.distribution, u));
  }
  return values;
}

}  // namespace dymesh::ensemble
