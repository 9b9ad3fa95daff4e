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
#include "dymesh/ensemble/sobol_sequence.h"
#include "dymesh/ensemble/statistics.h"
#include "dymesh/core/scenario.h"

#include <fstream>

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

TEST(Sampling, IncompleteBetaMatchesItsBinomialSum) {
  // integer a, b: I_x(a, b) = sum_{j = a}^{a + b - 1} C(a + b - 1, j) x^j (1 - x)^(a + b - 1 - j)
  for (double x : {0.05, 0.3, 0.5, 0.8, 0.99}) {
    const double expected = 6 * x * x * (1 - x) * (1 - x) + 4 * x * x * x * (1 - x) + x * x * x * x;  // a = 2, b = 3
    EXPECT_NEAR(IncompleteBeta(2, 3, x), expected, 1e-14) << x;
    EXPECT_NEAR(IncompleteBeta(1, 1, x), x, 1e-15);
  }
}

TEST(Sampling, BetaAndPertPassKolmogorovSmirnov) {
  const int n = 4000;
  Distribution beta{DistributionKind::kBeta, 2.0, 5.0, 10.0, 20.0};
  EXPECT_LT(KolmogorovSmirnov(beta, [](double x) { return IncompleteBeta(2.0, 5.0, (x - 10.0) / 10.0); }, n), Critical(n));
  // PERT(0, 2, 10): beta(1 + 4 * 2 / 10, 1 + 4 * 8 / 10) = beta(1.8, 4.2) on [0, 10]
  Distribution pert{DistributionKind::kPert, 0.0, 2.0, 10.0};
  EXPECT_LT(KolmogorovSmirnov(pert, [](double x) { return IncompleteBeta(1.8, 4.2, x / 10.0); }, n), Critical(n));
  EXPECT_NEAR(Mean(pert), (0.0 + 8.0 + 10.0) / 6.0, 1e-15);
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

TEST(Sobol, FirstPointsOfTheKnownSequence) {
  // the unshifted sequence in natural (not Gray-code) order: dimension 1 is van der Corput's,
  // dimension 2 has directions 1/2, 3/4, 5/8, ... (x^1 + 1, m_1 = 1)
  const double d0[] = {0.0, 0.5, 0.25, 0.75, 0.125, 0.625, 0.375, 0.875};
  const double d1[] = {0.0, 0.5, 0.75, 0.25, 0.625, 0.125, 0.375, 0.875};
  for (int i = 0; i < 8; ++i) {
    EXPECT_EQ(SobolCoordinate(i, 0), d0[i]) << i;
    EXPECT_EQ(SobolCoordinate(i, 1), d1[i]) << i;
  }
}

TEST(Sobol, EveryDimensionStratifiesAndTheFirstPairIsANet) {
  // the first 2^m points: one per interval of length 2^-m in every dimension, and (dimensions 1 and
  // 2, t = 0) one per cell of a 2^(m/2) x 2^(m/2) grid, for any scrambling seed (Owen's scramble
  // keeps every elementary interval's count)
  const int m = 10, n = 1 << m;
  for (std::uint32_t seed : {0u, 0x9e3779b9u, 12345u}) {
    for (int d = 0; d < kSobolDimensions; ++d) {
      std::vector<int> hits(n, 0);
      for (int i = 0; i < n; ++i) ++hits[static_cast<int>(ScrambledSobolCoordinate(i, d, seed) * n)];
      EXPECT_EQ(*std::min_element(hits.begin(), hits.end()), 1) << "dimension " << d;
    }
    std::vector<int> cells(n, 0);
    for (int i = 0; i < n; ++i)
      ++cells[static_cast<int>(ScrambledSobolCoordinate(i, 0, seed) * 32) * 32 +
              static_cast<int>(ScrambledSobolCoordinate(i, 1, seed) * 32)];
    EXPECT_EQ(*std::max_element(cells.begin(), cells.end()), 1);
  }
}

TEST(Sobol, ScrambleIsNestedNotADigitalShift) {
  // a digital shift XORs every point with one word, so the XOR of two points never changes; Owen's
  // nested scramble flips each digit by the digits above it, so it does
  auto word = [](std::uint64_t i, std::uint32_t seed) {
    return static_cast<std::uint32_t>(ScrambledSobolCoordinate(i, 2, seed) * 4294967296.0);
  };
  int changed = 0;
  for (std::uint32_t seed = 1; seed <= 20; ++seed) changed += (word(1, seed) ^ word(6, seed)) != (word(1, 0) ^ word(6, 0));
  EXPECT_GE(changed, 15);
  // each scrambled point is uniform over seeds: the first point of dimension 4 over 4000 seeds passes
  // the one-sample KS test at 1 %
  const int n = 4000;
  std::vector<double> x;
  for (int s = 0; s < n; ++s)
    x.push_back(ScrambledSobolCoordinate(0, 4, static_cast<std::uint32_t>(Uniform(5, TextHash("owen"), s) * 4294967296.0)));
  std::sort(x.begin(), x.end());
  double d = 0.0;
  for (int i = 0; i < n; ++i) d = std::max({d, std::abs(x[i] - static_cast<double>(i) / n), std::abs(x[i] - (i + 1.0) / n)});
  EXPECT_LT(d, Critical(n));
}

TEST(Designs, SobolDesignStratifiesEveryInput) {
  // 64 points of the scrambled sequence through the uniform quantiles: one per 1/64 of each range
  const Spec spec = LoadSpec(testing::WriteBoxSpec(::testing::TempDir() + "/sobol", 64, "sobol"));
  const DesignTable design(spec);
  std::vector<int> speed(64, 0), restitution(64, 0);
  for (int i = 0; i < 64; ++i) {
    const std::vector<double> v = design.Values(i);
    ++speed[static_cast<int>((v[0] - 25.0) / 10.0 * 64)];
    ++restitution[static_cast<int>(v[1] / 0.2 * 64)];
  }
  EXPECT_EQ(*std::min_element(speed.begin(), speed.end()), 1);
  EXPECT_EQ(*std::min_element(restitution.begin(), restitution.end()), 1);
}

TEST(Designs, GridOneAtATimeAndTableGiveTheirRuns) {
  const std::string dir = ::testing::TempDir() + "/designs";
  // grid: 3 x 3 levels at probabilities 1/6, 1/2, 5/6, the first input fastest
  const Spec grid = LoadSpec(testing::WriteBoxSpec(dir, 1, "grid"));
  ASSERT_EQ(grid.samples, 9);
  EXPECT_NEAR(DesignTable(grid).Values(0)[0], 25.0 + 10.0 / 6.0, 1e-12);
  EXPECT_NEAR(DesignTable(grid).Values(1)[0], 30.0, 1e-12);
  EXPECT_NEAR(DesignTable(grid).Values(7)[1], 0.2 * 5.0 / 6.0, 1e-12);  // 7 = 1 + 3 * 2: input 1 at its third level
  EXPECT_NEAR(DesignTable(grid).Values(7)[0], 30.0, 1e-12);
  // one at a time: the medians, then each input at P5 and P95
  const Spec oat = LoadSpec(testing::WriteBoxSpec(dir, 1, "one_at_a_time"));
  ASSERT_EQ(oat.samples, 5);
  EXPECT_EQ(DesignTable(oat).Values(0), (std::vector<double>{30.0, 0.1}));
  EXPECT_NEAR(DesignTable(oat).Values(1)[0], 25.5, 1e-12);
  EXPECT_NEAR(DesignTable(oat).Values(2)[0], 34.5, 1e-12);
  EXPECT_NEAR(DesignTable(oat).Values(3)[1], 0.01, 1e-12);
  EXPECT_EQ(DesignTable(oat).Values(3)[0], 30.0);
  // a table: the rows as given, refused when a row has the wrong length
  std::string path = testing::WriteBoxSpec(dir, 1, "table");
  std::ifstream in(path);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  text.insert(text.rfind('}'), R"(, "table": [[26, 0.05], [33, 0.15]])");
  std::ofstream(path) << text;
  const Spec table = LoadSpec(path);
  ASSERT_EQ(table.samples, 2);
  EXPECT_EQ(DesignTable(table).Values(1), (std::vector<double>{33.0, 0.15}));
  text.replace(text.find("[33, 0.15]"), 10, "[33]");
  std::ofstream(path) << text;
  EXPECT_THROW(LoadSpec(path), InputError);
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

TEST(Sampling, CopulaGivesTheRankCorrelationAndRefusesImpossibleMatrices) {
  const std::string good = R"(, {"name": "friction", "path": "bodies[0].friction", "distribution": {"uniform": {"low": 0, "high": 1}}})";
  std::string path = testing::WriteBoxSpec(::testing::TempDir() + "/copula", 3000, "monte_carlo", good);
  // add the correlation block to the written spec
  std::ifstream in(path);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  text.insert(text.rfind('}'), R"(, "correlation": {"inputs": ["speed", "friction"], "rank_matrix": [[1, 0.7], [0.7, 1]]})");
  std::ofstream(path) << text;
  const Spec spec = LoadSpec(path);
  const DesignTable design(spec);
  std::vector<double> speed, friction, restitution;
  for (int i = 0; i < spec.samples; ++i) {
    const std::vector<double> v = design.Values(i);
    speed.push_back(v[0]), restitution.push_back(v[1]), friction.push_back(v[2]);
  }
  // sampling error of a rank correlation near 0.7 at n = 3000: (1 - rho^2) / sqrt(n) ~ 0.01; 4 sd
  EXPECT_NEAR(Spearman(speed, friction), 0.7, 0.04);
  EXPECT_NEAR(Spearman(speed, restitution), 0.0, 4.0 / std::sqrt(3000.0));
  // Latin hypercube (Iman-Conover): the same rank correlation, and every input still one sample per
  // stratum. Sampling error of the induced rank correlation at n = 400: (1 - rho^2) / sqrt(n) ~ 0.026
  // for a free sample, smaller for the re-paired scores; 3 sd
  std::string lhs = text;
  lhs.replace(lhs.find("\"monte_carlo\""), 13, "\"latin_hypercube\"");
  lhs.replace(lhs.find("\"samples\": 3000"), 15, "\"samples\": 400");
  std::ofstream(path) << lhs;
  const Spec lhs_spec = LoadSpec(path);
  ASSERT_EQ(lhs_spec.samples, 400);
  const DesignTable lhs_design(lhs_spec);
  std::vector<std::vector<double>> columns(3);
  for (int i = 0; i < lhs_spec.samples; ++i)
    for (int k = 0; k < 3; ++k) columns[k].push_back(lhs_design.Values(i)[k]);
  EXPECT_NEAR(Spearman(columns[0], columns[2]), 0.7, 3 * 0.026);
  EXPECT_NEAR(Spearman(columns[0], columns[1]), 0.0, 3.0 / std::sqrt(400.0));
  for (int k = 0; k < 3; ++k) {
    std::vector<int> hits(400, 0);
    for (double v : columns[k]) {
      const double p = k == 0 ? (v - 25.0) / 10.0 : k == 1 ? v / 0.2 : v;  // uniform inputs
      ++hits[std::clamp(static_cast<int>(p * 400), 0, 399)];
    }
    EXPECT_EQ(*std::min_element(hits.begin(), hits.end()), 1) << "input " << k;
  }
  // a matrix no joint distribution has
  text.replace(text.find("[[1, 0.7], [0.7, 1]]"), 20, "[[1, 1.0], [1.0, 1]]");
  std::ofstream(path) << text;
  EXPECT_THROW(LoadSpec(path), InputError);
}

TEST(Statistics, RankSensitivityOfAnOutputThatFollowsOneInput) {
  // y = a exactly, b independent: Spearman and PRCC 1 for a, within 3 / sqrt(n) of 0 for b
  std::vector<SampleRecord> records;
  const int n = 500;
  std::vector<std::vector<double>> x;
  std::vector<double> y, a, b;
  for (int i = 0; i < n; ++i) {
    a.push_back(Uniform(1, 1, i)), b.push_back(Uniform(1, 2, i));
    x.push_back({a.back(), b.back()});
    y.push_back(a.back());
  }
  EXPECT_DOUBLE_EQ(Spearman(a, y), 1.0);
  EXPECT_NEAR(Spearman(b, y), 0.0, 3.0 / std::sqrt(n));
  const std::vector<double> prcc = PartialRankCorrelation(x, y);
  EXPECT_NEAR(prcc[0], 1.0, 1e-9);
  EXPECT_NEAR(prcc[1], 0.0, 3.0 / std::sqrt(n));
}

TEST(Statistics, BootstrapIntervalOfTheMeanHasTheNormalWidth) {
  // 400 uniform values: mean 0.5, sd 1/sqrt(12); the 95 % interval is about 2 * 1.96 sd / sqrt(n)
  std::vector<double> v;
  for (int i = 0; i < 400; ++i) v.push_back(Uniform(9, 3, i));
  const Interval ci = Bootstrap95(v, [](std::vector<double>& d) {
    double s = 0.0;
    for (double x : d) s += x;
    return s / d.size();
  }, 5, "mean");
  EXPECT_LT(ci.low, 0.5 + 0.03);
  EXPECT_GT(ci.high, 0.5 - 0.03);
  const double width = 2 * 1.96 / std::sqrt(12.0) / std::sqrt(400.0);
  EXPECT_NEAR(ci.high - ci.low, width, 0.25 * width);  // 400 resamples: the width is known to ~10 %
}

// Saltelli's estimators on a closed-form model of two independent uniform inputs
SobolIndices SobolOf(const std::function<double(double, double)>& f, int input, int n) {
  std::vector<double> fa, fb, fab;
  for (int j = 0; j < n; ++j) {
    const double a0 = Uniform(21, 1, j, 0), a1 = Uniform(21, 2, j, 0);  // row j of A
    const double b0 = Uniform(21, 1, j, 2), b1 = Uniform(21, 2, j, 2);  // row j of B
    fa.push_back(f(a0, a1));
    fb.push_back(f(b0, b1));
    fab.push_back(input == 0 ? f(b0, a1) : f(a0, b1));
  }
  return SobolFromSaltelli(fa, fb, fab);
}

TEST(Statistics, SobolIndicesOfClosedFormModels) {
  // additive y = 2a + b: V = 4/12 + 1/12, S_a = ST_a = 0.8, S_b = ST_b = 0.2
  const auto additive = [](double a, double b) { return 2 * a + b; };
  // product y = a b: V = 1/9 - 1/16 = 7/144, V_a = V_b = 1/48: S = 3/7, ST = 1 - 3/7 = 4/7
  const auto product = [](double a, double b) { return a * b; };
  const int n = 20000;  // estimator standard errors ~0.01 at this n: 0.03 is 3 of them
  EXPECT_NEAR(SobolOf(additive, 0, n).first, 0.8, 0.03);
  EXPECT_NEAR(SobolOf(additive, 0, n).total, 0.8, 0.03);
  EXPECT_NEAR(SobolOf(additive, 1, n).first, 0.2, 0.03);
  EXPECT_NEAR(SobolOf(additive, 1, n).total, 0.2, 0.03);
  EXPECT_NEAR(SobolOf(product, 0, n).first, 3.0 / 7.0, 0.03);
  EXPECT_NEAR(SobolOf(product, 0, n).total, 4.0 / 7.0, 0.03);
}

TEST(Evidence, PosteriorOfAnObservedInputIsTheLikelihood) {
  // x uniform on [0, 1] observed directly as 0.3 +- 0.05: the posterior is that normal (its tails
  // beyond [0, 1] are negligible); equal weights give an effective sample size of n
  Spec spec;
  spec.inputs.push_back(Input{"x"});
  spec.evidence.push_back({"b.x", 0.3, 0.05});
  std::vector<SampleRecord> records;
  const int n = 4000;
  for (int i = 0; i < n; ++i) {
    SampleRecord r{i, "", "complete", {}, {Uniform(8, 1, i)}};
    r.observables["b.x"] = r.inputs[0];
    records.push_back(r);
  }
  double effective = 0.0;
  const std::vector<double> w = EvidenceWeights(spec, records, &effective);
  double sum = 0.0, mean = 0.0;
  for (int i = 0; i < n; ++i) sum += w[i], mean += w[i] * records[i].inputs[0];
  mean /= sum;
  double var = 0.0;
  for (int i = 0; i < n; ++i) var += w[i] * (records[i].inputs[0] - mean) * (records[i].inputs[0] - mean);
  // sum w ~ n s sqrt(2 pi), sum w^2 ~ n s sqrt(pi): ESS ~ 2 sqrt(pi) n s = 709; the posterior
  // mean's error ~ s / sqrt(ESS) ~ 0.002
  EXPECT_NEAR(mean, 0.3, 0.01);
  EXPECT_NEAR(std::sqrt(var / sum), 0.05, 0.005);
  const double pi = 4 * std::atan(1.0);
  EXPECT_NEAR(effective, 2 * std::sqrt(pi) * n * 0.05, 0.1 * 2 * std::sqrt(pi) * n * 0.05);
  spec.evidence[0].sd = 1e6;  // no information: every weight 1
  EvidenceWeights(spec, records, &effective);
  EXPECT_NEAR(effective, n, 1e-6);
}

TEST(Crash3, CoefficientsFromB0AndB1) {
  // US: A = (W / g) (17.6 b0) (17.6 b1) / L, B = (W / g) (17.6 b1)^2 / L, g = 386.0886 in/s^2
  Crash3Preset p;
  p.us = true, p.mass = 3000 * 0.45359237, p.width = 66;
  const Crash3Stiffness k = Crash3ToAB(p, 5.0, 1.5);
  const double m = 3000 / 386.08858267716535;
  EXPECT_NEAR(k.a, m * 88.0 * 26.4 / 66.0, 1e-9);
  EXPECT_NEAR(k.b, m * 26.4 * 26.4 / 66.0, 1e-9);
  // A / B = b0 / b1 and G = A^2 / 2B = m b0^2 / 2L (the no-damage energy per width): never independent
  EXPECT_NEAR(k.a / k.b, 5.0 / 1.5, 1e-12);
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
