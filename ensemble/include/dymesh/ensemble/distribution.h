#pragma once
#include <string>
#include <vector>

/// The distribution of one uncertain input, sampled by its quantile function (inverse CDF), so
/// that Monte Carlo, Latin hypercube and later designs share one path from a uniform number.
namespace dymesh::ensemble {

enum class DistributionKind {
  kFixed, kUniform, kNormal, kTruncatedNormal, kTriangular, kLognormal, kDiscrete, kBeta, kPert
};

struct Distribution {
  DistributionKind kind = DistributionKind::kFixed;
  double a = 0.0, b = 0.0, c = 0.0, d = 0.0;  ///< parameters by kind (see Quantile)
  std::vector<double> values{}, cumulative{};    ///< discrete: the values and their cumulative weights
};

/// The value at probability u in (0, 1):
/// fixed (a); uniform (a = low, b = high); normal (a = mean, b = sd); truncated normal (a = mean,
/// b = sd, c = low, d = high); triangular (a = low, b = mode, c = high); lognormal (a = median,
/// b = sigma of the log); discrete (values with cumulative weights); beta (a = alpha, b = beta on
/// [c = low, d = high]); PERT (a = low, b = mode, c = high: a beta with alpha = 1 + 4 (mode - low) /
/// (high - low), beta = 1 + 4 (high - mode) / (high - low)).
double Quantile(const Distribution& dist, double u);

/// The standard normal CDF and its inverse (Acklam's rational start, one Halley step: ~1e-15).
double NormalCdf(double x);
double NormalQuantile(double p);

/// The regularized incomplete beta function I_x(a, b) (continued fraction, ~1e-14).
double IncompleteBeta(double a, double b, double x);

/// The distribution's mean where a closed form exists (tests, reports).
double Mean(const Distribution& dist);

/// Name of a kind as written in specs ("uniform", ...).
const char* DistributionName(DistributionKind kind);

}  // namespace dymesh::ensemble
