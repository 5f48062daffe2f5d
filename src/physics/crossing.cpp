#include "physics/crossing.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <type_traits>

#include "physics/coefficients.h"
#include "physics/simd.h"

namespace cb::detail {

int slope_zeros_inside(double A, double B, double C, double* zeros) {
  int count = 0;
  if (std::abs(A) > 1e-300) {
    const double disc = B * B - 4.0 * A * C;
    if (disc > 0.0) {
      const double root = std::sqrt(disc);
      // Stable roots of the quadratic (no cancellation).
      const double t = -0.5 * (B + std::copysign(root, B));
      double r1 = t / A, r2 = t != 0.0 ? C / t : r1;
      if (r1 > r2) std::swap(r1, r2);
      for (double r0 : {r1, r2})
        if (r0 > 0.0 && r0 < 1.0) zeros[count++] = r0;
    }
  } else if (std::abs(B) > 1e-300) {
    const double r0 = -C / B;
    if (r0 > 0.0 && r0 < 1.0) zeros[count++] = r0;
  }
  return count;
}

HermiteRoot hermite_root(double p0, double p1, double m0, double m1, double h, double upper,
                         double lower) {
  HermiteRoot r;
  // p(s) = a + b s + q s^2 + d s^3 on s = theta / h in [0, 1].
  r.a = p0, r.b = h * m0;
  r.q = -3.0 * p0 - 2.0 * h * m0 + 3.0 * p1 - h * m1;
  r.d = 2.0 * p0 + h * m0 - 2.0 * p1 + h * m1;
  r.h = h, r.upper = upper, r.lower = lower;
  auto p = [&](double s) { return r.a + s * (r.b + s * (r.q + s * r.d)); };
  // lower - p(s) is -(p(s) - lower): for lower = -c the bits of the one-sided -p(s) - c.
  const bool stretch_only = lower == -std::numeric_limits<double>::infinity();
  auto up = [&](double s) { return p(s) - upper; };
  auto down = [&](double s) { return lower - p(s); };
  if (up(0.0) >= 0.0 || (!stretch_only && down(0.0) >= 0.0)) {
    r.theta = 0.0;
    return r;
  }

  // Split [0, 1] where p' = b + 2 q s + 3 d s^2 vanishes: p is monotone on each piece, so
  // a sign change at a piece's ends is the only way to cross inside it.
  double cuts[4] = {0.0, 1.0, 1.0, 1.0};
  const double A = 3.0 * r.d, B = 2.0 * r.q, C = r.b;
  const int count = 1 + (slope_keeps_sign(A, B, C) ? 0 : slope_zeros_inside(A, B, C, cuts + 1));
  cuts[count] = 1.0;
  // The first piece where a bound is reached holds the crossing: its brackets.
  auto add = [&](double lo, double hi, bool is_down) {
    r.lo[r.brackets] = lo, r.hi[r.brackets] = hi, r.down[r.brackets] = is_down;
    ++r.brackets;
  };
  for (int k = 0; k < count && r.brackets == 0; ++k) {
    const double lo = cuts[k], hi = cuts[k + 1];
    if (up(lo) < 0.0 && up(hi) >= 0.0) add(lo, hi, false);
    if (!stretch_only && down(lo) < 0.0 && down(hi) >= 0.0) add(lo, hi, true);
  }
  return r;
}

#include "physics/crossing_bisect.inc"

namespace sse2 {
void finish_hermite_roots(HermiteRoot* roots, std::size_t count) {
  finish_roots<2, 8>(roots, count);
}
}  // namespace sse2

// One root (Integrator's break) in a group of four, which the baseline does in two registers: a
// wider group would only add idle lanes to its one chain. Many (an ensemble's) in the widest
// groups the CPU runs (crossing_avx2.cpp, crossing_avx512.cpp); the same bits either way.
void finish_hermite_roots(HermiteRoot* roots, std::size_t count) {
  if (count <= 1) return finish_roots<2, 2>(roots, count);
  by_simd(active_simd(), &sse2::finish_hermite_roots, &avx2::finish_hermite_roots,
          &avx512::finish_hermite_roots)(roots, count);
}

int earliest_crossing(const std::vector<Candidate>& candidates, const ChainCoefficients& coef,
                      double ta, double tb, double* first) {
  return earliest_crossing_within(
      candidates,
      [&](int spring, double* upper, double* lower) {
        *upper = coef.upper_of(spring);
        *lower = coef.lower_of(spring);
      },
      ta, tb, first);
}

double first_time_at_least(const std::function<double(double)>& f, double f_end, double ta,
                           double tb, double c) {
  if (f(ta) >= c) return ta;
  constexpr int kSamples = 16;
  double prev = ta;
  for (int k = 1; k <= kSamples; ++k) {
    const double t = k == kSamples ? tb : ta + (tb - ta) * k / kSamples;
    const double value = k == kSamples ? f_end : f(t);
    if (value >= c) {
      // Bisect inside (prev, t]; the end point itself uses its left limit.
      double lo = prev, hi = t;
      for (int i = 0; i < 100 && hi - lo > 1e-15 * std::max(1.0, std::abs(hi)); ++i) {
        const double mid = 0.5 * (lo + hi);
        (f(mid) >= c ? hi : lo) = mid;
      }
      return hi;
    }
    prev = t;
  }
  return -1.0;
}

}  // namespace cb::detail
