// Random thresholds by (seed, spring), with our own inverse CDFs (threshold_draw.h).
#include "physics/threshold_draw.h"

#include <algorithm>
#include <cmath>  // sqrt, abs: correctly rounded, exact
#include <numbers>

#include "physics/portable_math.h"

namespace cb {

namespace {

// SplitMix64's finaliser: a bijection of 64-bit words whose every output bit depends on every
// input bit (Steele, Lea and Flood, "Fast splittable pseudorandom number generators", 2014).
std::uint64_t mix(std::uint64_t z) {
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

// Phi(x), the standard normal CDF.
double normal_cdf(double x) {
  return 0.5 * portable::erfc(-x / std::sqrt(2.0));
}

}  // namespace

double uniform_open01(std::uint64_t seed, std::uint64_t index) {
  // The seed is mixed first, so that neighbouring seeds give unrelated streams, then the
  // index on a Weyl step of its own.
  const std::uint64_t bits =
      mix(mix(seed + 0x9E3779B97F4A7C15ull) ^ (index * 0xD1B54A32D192ED03ull));
  return (static_cast<double>(bits >> 11) + 0.5) * 0x1.0p-53;
}

double weibull_quantile(double u, double shape) {
  // e^(ln(l) / shape), l = -ln(1 - u), with ln l as a pair: for u near 2^-53 it is near -37,
  // and its rounding alone would cost x a few ulps. t + rest = ln l / shape to ~2^-106.
  // (rest is a correction below t's ulp: its own rounding, and 1 / shape's, do not show.)
  const double inverse = 1.0 / shape;  // independent of u: off the chain of dependent steps
  const portable::Pair ln = portable::log_pair(-portable::log1p(-u));
  const double t = ln.hi / shape;
  const portable::Pair back = portable::times(t, shape);  // t shape, exactly
  const double rest = ((ln.hi - back.hi) - back.lo + ln.lo) * inverse;
  return portable::exp_pair({t, rest});
}

double normal_quantile(double p) {
  // Symmetric: solve in the lower half, where p itself is represented most finely.
  if (p > 0.5) return -normal_quantile(1.0 - p);
  // A start within a few tenths everywhere: the tail's asymptote, or the linearised centre.
  double x = p < 0.02 ? -std::sqrt(-2.0 * portable::log(p) -
                                   portable::log(-4.0 * std::numbers::pi * portable::log(p)))
                      : (p - 0.5) * std::sqrt(2.0 * std::numbers::pi);
  for (int i = 0; i < 60; ++i) {
    const double density = portable::exp(-0.5 * x * x) / std::sqrt(2.0 * std::numbers::pi);
    const double residual = normal_cdf(x) - p;
    // Halley's step (Phi'' = -x Phi'): cubic convergence, safe from the starts above.
    const double newton = residual / density;
    const double step = newton / (1.0 + 0.5 * x * newton);
    x -= step;
    if (std::abs(step) <= 1e-15 * std::max(1.0, std::abs(x))) break;
  }
  return x;
}

std::vector<double> draw_thresholds(ThresholdDist dist, double scale, double shape,
                                    std::uint64_t seed, int n) {
  std::vector<double> out(static_cast<std::size_t>(n));
  // Normal: z > -1/shape keeps 1 + shape z > 0; u is mapped into (Phi(-1/shape), 1).
  const double cut = dist == ThresholdDist::Normal ? normal_cdf(-1.0 / shape) : 0.0;
  for (int j = 1; j <= n; ++j) {
    const double u = uniform_open01(seed, static_cast<std::uint64_t>(j));
    out[j - 1] = dist == ThresholdDist::Weibull
                     ? scale * weibull_quantile(u, shape)
                     : scale * (1.0 + shape * normal_quantile(cut + u * (1.0 - cut)));
  }
  return out;
}

}  // namespace cb
