// The samplers against their distributions: quantile functions against closed-form CDFs
// (Kolmogorov-Smirnov at the 1 % level), Latin hypercube stratification, independent streams.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>

#include "box_spec.h"
#include "dymesh/ensemble/design.h"
#include "dymesh/ensemble/distribution.h"
#include "dymesh/ensemble/random_stream.h"
#include "dymesh/ensemble/statistics.h"

namespace dymesh::ensemble {
namespace {

// KS statistic of n stream draws through `dist` against the CDF `cdf`
double KolmogorovSmirnov(const Distribution& dist, const std::function<double(double)>& cdf, int n) {
  std::vector<double> x;
  for (int i = 0; i < n; ++i) x.push_back(Quantile(dist, Uniform(11, TextHash("ks"), i)));
  std::sort(x.begin(), x.end());
  double d = 0.0;
  for (int i = 0; i < n; ++i) d = std::max({d, std::abs(cdf(x[i]) - static_cast<double>(i) / n),
                                           std::abs(cdf(x[i]) - static_cast<double>(i + 1) / n)});
  return d;
}

// the 1 % critical value of the one-sample KS test for large n: 1.628 / sqrt(n)
double Critical(int n) { return 1.628 / std::sqrt(static_cast<double>(n)); }

TEST(Sampling, NormalQuantileInvertsTheCdf) {
  for (double p : {1e-12, 1e-6, 0.001, 0.02425, 0.1, 0.5, 0.77, 0.975, 0.999999})
    EXPECT_NEAR(NormalCdf(NormalQuantile(p)), p, 1e-15 + 1e-12 * p) << p;
  EXPECT_NEAR(NormalQuantile(0.975), 1.959963984540054, 1e-12);
}

TEST(Sampling, DistributionsPassKolmogorovSmirnovAtOnePercent) {
  const int n = 4000;
  Distribution uniform{DistributionKind::kUniform, 2.0, 5.0};
  EXPECT_LT(KolmogorovSmirnov(uniform, [](double x) { return (x - 2.0) / 3.0; }, n), Critical(n));
  Distribution normal{DistributionKind::kNormal, 30.0, 2.0};
  EXPECT_LT(KolmogorovSmirnov(normal, [](double x) { return NormalCdf((x - 30.0) / 2.0); }, n), Critical(n));
  Distribution truncated{DistributionKind::kTruncatedNormal, 0.2, 0.1, 0.0, 0.4};
  const double lo = NormalCdf(-2.0), hi = NormalCdf(2.0);
  EXPECT_LT(KolmogorovSmirnov(truncated, [&](double x) { return (NormalCdf((x - 0.2) / 0.1) - lo) / (hi - lo); }, n),
            Critical(n));
  Distribution triangular{DistributionKind::kTriangular, 0.0, 1.0, 4.0};
  auto tri_cdf = [](double x) { return x < 1.0 ? x * x / 4.0 : 1.0 - (4.0 - x) * (4.0 - x) / 12.0; };
  EXPECT_LT(KolmogorovSmirnov(triangular, tri_cdf, n), Critical(n));
  Distribution lognormal{DistributionKind::kLognormal, 3.0, 0.25};
  EXPECT_LT(KolmogorovSmirnov(lognormal, [](double x) { return NormalCdf(std::log(x / 3.0) / 0.25); }, n), Critical(n));
}

TEST(Sampling, DiscreteFollowsItsWeights) {
  Distribution d{DistributionKind::kDiscrete};
  d.values = {1.0, 2.0, 3.0};
  d.cumulative = {1.0, 3.0, 4.0};  // weights 1, 2, 1
  int count[3] = {0, 0, 0};
  const int n = 8000;
  for (int i = 0; i < n; ++i) ++count[static_cast<int>(Quantile(d, Uniform(3, 5, i))) - 1];
  // binomial sampling error: 3 sd of n p (1 - p)
  EXPECT_NEAR(count[1], n / 2.0, 3 * std::sqrt(n * 0.25));
  EXPECT_NEAR(count[0], n / 4.0, 3 * std::sqrt(n * 0.1875));
  EXPECT_NEAR(Mean(d), 2.0, 1e-15);
}

TEST(Sampling, LatinHypercubeFillsEveryStratumOnce) {
  const Spec spec = LoadSpec(testing::WriteBoxSpec(::testing::TempDir() + "/lhs", 50));
  const DesignTable design(spec);
  for (std::size_t k = 0; k < spec.inputs.size(); ++k) {
    std::vector<int> hits(spec.samples, 0);
    for (int i = 0; i < spec.samples; ++i) {
      const double u = k == 0 ? (design.Values(i)[0] - 25.0) / 10.0 : design.Values(i)[1] / 0.2;
      ++hits[std::min(spec.samples - 1, static_cast<int>(u * spec.samples))];
    }
    for (int h : hits) EXPECT_EQ(h, 1);
  }
}

TEST(Sampling, AddingAnInputDoesNotShiftTheOthers) {
  const Spec two = LoadSpec(testing::WriteBoxSpec(::testing::TempDir() + "/two", 20, "monte_carlo"));
  const Spec three = LoadSpec(testing::WriteBoxSpec(
      ::testing::TempDir() + "/three", 20, "monte_carlo",
      R"(, {"name": "friction", "path": "bodies[0].friction", "distribution": {"uniform": {"low": 0, "high": 0.5}}})"));
  ASSERT_NE(two.hash, three.hash);
  for (int i = 0; i < 20; ++i) {
    EXPECT_EQ(DesignTable(two).Values(i)[0], DesignTable(three).Values(i)[0]);
    EXPECT_EQ(DesignTable(two).Values(i)[1], DesignTable(three).Values(i)[1]);
  }
}

TEST(Statistics, MomentsAndPercentilesOfAKnownSample) {
  // x_i = i for i = 0..100: mean 50, sd sqrt(101 * 102 / 12 * ...) = sqrt(sum (i - 50)^2 / 100)
  std::vector<SampleRecord> records;
  for (int i = 0; i <= 100; ++i) records.push_back({i, "", "complete", {{"x", static_cast<double>(i)}}});
  records.push_back({101, "", "ended_in_contact", {}});  // excluded
  const auto stats = ComputeStatistics(records);
  const OutputStatistics& s = stats.at("x");
  EXPECT_EQ(s.n, 101);
  EXPECT_DOUBLE_EQ(s.mean, 50.0);
  EXPECT_NEAR(s.sd, std::sqrt(101.0 * 102.0 / 12.0), 1e-12);  // sum (i - 50)^2 / 100 = 101 * 102 / 12
  EXPECT_DOUBLE_EQ(s.p5, 5.0);
  EXPECT_DOUBLE_EQ(s.p50, 50.0);
  EXPECT_DOUBLE_EQ(s.p95, 95.0);
}

}  // namespace
}  // namespace dymesh::ensemble
