// Random thresholds by (seed, spring), with our own inverse CDFs (threshold_draw.h).
#include "physics/threshold_draw.h"

#include <array>
#include <bit>
#include <cmath>  // sqrt, abs: correctly rounded, exact (expm1, pow: bounds only)
#include <cstdint>
#include <numbers>

#include "physics/portable_math.h"
#include "physics/simd.h"

// See portable_math.cpp.
#ifdef __clang__
#pragma STDC FP_CONTRACT OFF
#endif

namespace cb {

namespace {

#include "physics/portable_lanes.inc"

// Phi(x), the standard normal CDF.
double normal_cdf(double x) {
  return 0.5 * portable::erfc(-x / std::sqrt(2.0));
}

}  // namespace

double uniform_open01(std::uint64_t seed, std::uint64_t index) {
  return uniform_of_bits(uniform_bits(seed_stream(seed), index));
}

double weibull_quantile(double u, double shape) {
  double t = 0.0;
  const auto parts = weibull_parts<double, std::uint64_t>(u, shape, 1.0 / shape, &t);
  return scaled_anywhere(parts, exp_in_range(t));
}

double weibull_threshold(double scale, double shape, double u) {
  // weibull_quantiles' value, then the scale, as draw_threshold_rows multiplies it.
  return weibull_quantile(u, shape) * scale;
}

bool weibull_draws_positive_finite(double scale, double shape) {
  // The quantile rises with u, to a few ulps: its values at the least and the largest u bound
  // every draw's, with room for those ulps.
  const double least = weibull_threshold(scale, shape, uniform_of_bits(0));
  const double most =
      weibull_threshold(scale, shape, uniform_of_bits((std::uint64_t{1} << 53) - 1));
  return least >= 1e-300 && most <= 1e300;
}

double weibull_cdf(double x, double shape) {
  return -std::expm1(-std::pow(x, shape));
}

namespace {
void weibull_quantiles_one_by_one(const double* u, std::size_t n, double shape, double* out) {
  for (std::size_t i = 0; i < n; ++i) out[i] = weibull_quantile(u[i], shape);
}
}  // namespace

void weibull_quantiles(const double* u, std::size_t n, double shape, double* out) {
  by_simd(active_simd(), &weibull_quantiles_one_by_one, &detail::avx2::weibull_quantiles,
          &detail::avx512::weibull_quantiles)(u, n, shape, out);
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
  draw_thresholds(dist, scale, shape, seed, n, out.data());
  return out;
}

void draw_thresholds(ThresholdDist dist, double scale, double shape, std::uint64_t seed, int n,
                     double* out) {
  draw_threshold_rows(dist, scale, shape, &seed, 1, n, out);
}

void draw_threshold_rows(ThresholdDist dist, double scale, double shape, const std::uint64_t* seeds,
                         std::size_t rows, int n, double* out) {
  const auto count = static_cast<std::size_t>(n);
  if (dist == ThresholdDist::Weibull) {
    for (std::size_t r = 0; r < rows; ++r) {
      const std::uint64_t stream = seed_stream(seeds[r]);
      for (std::size_t j = 1; j <= count; ++j)
        out[r * count + j - 1] = uniform_of_bits(uniform_bits(stream, j));
    }
    weibull_quantiles(out, rows * count, shape, out);
    for (std::size_t i = 0; i < rows * count; ++i) out[i] *= scale;
    return;
  }
  // Normal: z > -1/shape keeps 1 + shape z > 0; u is mapped into (Phi(-1/shape), 1).
  const double cut = normal_cdf(-1.0 / shape);
  for (std::size_t r = 0; r < rows; ++r) {
    const std::uint64_t stream = seed_stream(seeds[r]);
    for (std::size_t j = 1; j <= count; ++j) {
      const double u = uniform_of_bits(uniform_bits(stream, j));
      out[r * count + j - 1] = scale * (1.0 + shape * normal_quantile(cut + u * (1.0 - cut)));
    }
  }
}

}  // namespace cb
