#include "dymesh/ensemble/distribution.h"

#include <algorithm>
#include <cmath>

namespace dymesh::ensemble {
namespace {

// Acklam's rational approximation of the standard normal quantile (relative error 1.15e-9)
double AcklamQuantile(double p) {
  static const double a[] = {-3.969683028665376e+01, 2.209460984245205e+02, -2.759285104469687e+02,
                             1.383577518672690e+02, -3.066479806614716e+01, 2.506628277459239e+00};
  static const double b[] = {-5.447609879822406e+01, 1.615858368580409e+02, -1.556989798598866e+02,
                             6.680131188771972e+01, -1.328068155288572e+01};
  static const double c[] = {-7.784894002430293e-03, -3.223964580411365e-01, -2.400758277161838e+00,
                             -2.549732539343734e+00, 4.374664141464968e+00, 2.938163982698783e+00};
  static const double d[] = {7.784695709041462e-03, 3.224671290700398e-01, 2.445134137142996e+00,
                             3.754408661907416e+00};
  constexpr double kLow = 0.02425;
  if (p < kLow) {
    const double q = std::sqrt(-2 * std::log(p));
    return (((((c[0] * q + c[1]) * q + c[2]) * q + c[3]) * q + c[4]) * q + c[5]) /
           ((((d[0] * q + d[1]) * q + d[2]) * q + d[3]) * q + 1);
  }
  if (p > 1 - kLow) return -AcklamQuantile(1 - p);
  const double q = p - 0.5, r = q * q;
  return (((((a[0] * r + a[1]) * r + a[2]) * r + a[3]) * r + a[4]) * r + a[5]) * q /
         (((((b[0] * r + b[1]) * r + b[2]) * r + b[3]) * r + b[4]) * r + 1);
}

// ln B(a, b)
double LogBeta(double a, double b) { return std::lgamma(a) + std::lgamma(b) - std::lgamma(a + b); }

// the continued fraction of the incomplete beta (modified Lentz)
double BetaContinuedFraction(double a, double b, double x) {
  constexpr double kTiny = 1e-300;
  double c = 1.0, d = 1.0 - (a + b) * x / (a + 1.0);
  if (std::abs(d) < kTiny) d = kTiny;
  d = 1.0 / d;
  double h = d;
  for (int m = 1; m <= 300; ++m) {
    const double m2 = 2.0 * m;
    for (const double aa : {m * (b - m) * x / ((a + m2 - 1) * (a + m2)), -(a + m) * (a + b + m) * x / ((a + m2) * (a + m2 + 1))}) {
      d = 1.0 + aa * d;
      if (std::abs(d) < kTiny) d = kTiny;
      c = 1.0 + aa / c;
      if (std::abs(c) < kTiny) c = kTiny;
      d = 1.0 / d;
      h *= d * c;
    }
    if (std::abs(d * c - 1.0) < 1e-16) break;
  }
  return h;
}

// the beta(a, b) quantile on [0, 1]: bisection on the regularized incomplete beta (monotone)
double BetaQuantile(double a, double b, double u) {
  double lo = 0.0, hi = 1.0;
  for (int i = 0; i < 200 && hi - lo > 1e-15; ++i) {
    const double mid = 0.5 * (lo + hi);
    (IncompleteBeta(a, b, mid) < u ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

// PERT's beta shape parameters
void PertShape(const Distribution& d, double* alpha, double* beta) {
  *alpha = 1.0 + 4.0 * (d.b - d.a) / (d.c - d.a);
  *beta = 1.0 + 4.0 * (d.c - d.b) / (d.c - d.a);
}

}  // namespace

double IncompleteBeta(double a, double b, double x) {
  if (x <= 0.0) return 0.0;
  if (x >= 1.0) return 1.0;
  const double front = std::exp(a * std::log(x) + b * std::log1p(-x) - LogBeta(a, b));
  // the fraction converges fast on the side of the mean
  if (x < (a + 1.0) / (a + b + 2.0)) return front * BetaContinuedFraction(a, b, x) / a;
  return 1.0 - front * BetaContinuedFraction(b, a, 1.0 - x) / b;
}

double NormalCdf(double x) { return 0.5 * std::erfc(-x / std::sqrt(2.0)); }

double NormalQuantile(double p) {
  // start, then one Halley step on the exact CDF
  const double x = AcklamQuantile(p);
  const double e = NormalCdf(x) - p;
  const double u = e * std::sqrt(2 * 3.14159265358979323846) * std::exp(x * x / 2);
  return x - u / (1 + x * u / 2);
}

double Quantile(const Distribution& dist, double u) {
  switch (dist.kind) {
    case DistributionKind::kFixed: return dist.a;
    case DistributionKind::kUniform: return dist.a + u * (dist.b - dist.a);
    case DistributionKind::kNormal: return dist.a + dist.b * NormalQuantile(u);
    case DistributionKind::kTruncatedNormal: {
      // the normal's quantile over the probability band the bounds cut out
      const double lo = NormalCdf((dist.c - dist.a) / dist.b), hi = NormalCdf((dist.d - dist.a) / dist.b);
      const double x = dist.a + dist.b * NormalQuantile(lo + u * (hi - lo));
      return std::clamp(x, dist.c, dist.d);
    }
    case DistributionKind::kTriangular: {
      const double lo = dist.a, mode = dist.b, hi = dist.c;
      const double split = (mode - lo) / (hi - lo);
      return u < split ? lo + std::sqrt(u * (hi - lo) * (mode - lo)) : hi - std::sqrt((1 - u) * (hi - lo) * (hi - mode));
    }
    case DistributionKind::kLognormal: return dist.a * std::exp(dist.b * NormalQuantile(u));
    case DistributionKind::kBeta: return dist.c + (dist.d - dist.c) * BetaQuantile(dist.a, dist.b, u);
    case DistributionKind::kPert: {
      double alpha = 0.0, beta = 0.0;
      PertShape(dist, &alpha, &beta);
      return dist.a + (dist.c - dist.a) * BetaQuantile(alpha, beta, u);
    }
    case DistributionKind::kDiscrete: {
      const auto it = std::upper_bound(dist.cumulative.begin(), dist.cumulative.end(), u * dist.cumulative.back());
      return dist.values[std::min<std::size_t>(it - dist.cumulative.begin(), dist.values.size() - 1)];
    }
  }
  return dist.a;
}

double Mean(const Distribution& dist) {
  switch (dist.kind) {
    case DistributionKind::kFixed: return dist.a;
    case DistributionKind::kUniform: return 0.5 * (dist.a + dist.b);
    case DistributionKind::kNormal: return dist.a;
    case DistributionKind::kTruncatedNormal: {
      const double alpha = (dist.c - dist.a) / dist.b, beta = (dist.d - dist.a) / dist.b;
      const double phi = [](double x) { return std::exp(-x * x / 2) / std::sqrt(2 * 3.14159265358979323846); }(alpha);
      const double phib = std::exp(-beta * beta / 2) / std::sqrt(2 * 3.14159265358979323846);
      return dist.a + dist.b * (phi - phib) / (NormalCdf(beta) - NormalCdf(alpha));
    }
    case DistributionKind::kTriangular: return (dist.a + dist.b + dist.c) / 3.0;
    case DistributionKind::kLognormal: return dist.a * std::exp(dist.b * dist.b / 2);
    case DistributionKind::kBeta: return dist.c + (dist.d - dist.c) * dist.a / (dist.a + dist.b);
    case DistributionKind::kPert: return (dist.a + 4.0 * dist.b + dist.c) / 6.0;
    case DistributionKind::kDiscrete: {
      double mean = 0.0, previous = 0.0;
      for (std::size_t i = 0; i < dist.values.size(); ++i) {
        mean += dist.values[i] * (dist.cumulative[i] - previous);
        previous = dist.cumulative[i];
      }
      return mean / dist.cumulative.back();
    }
  }
  return dist.a;
}

const char* DistributionName(DistributionKind kind) {
  switch (kind) {
    case DistributionKind::kFixed: return "fixed";
    case DistributionKind::kUniform: return "uniform";
    case DistributionKind::kNormal: return "normal";
    case DistributionKind::kTruncatedNormal: return "truncated_normal";
    case DistributionKind::kTriangular: return "triangular";
    case DistributionKind::kLognormal: return "lognormal";
    case DistributionKind::kDiscrete: return "discrete";
    case DistributionKind::kBeta: return "beta";
    case DistributionKind::kPert: return "pert";
  }
  return "fixed";
}

}  // namespace dymesh::ensemble
