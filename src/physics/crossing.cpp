#include "physics/crossing.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "physics/coefficients.h"

namespace cb::detail {

namespace {

// g(s) on [lo, hi] with g(lo) < 0 <= g(hi): the crossing, to double precision in s.
// One bisection: mid = (lo + hi) / 2, then hi = mid where g(mid) >= 0, else lo = mid; it stops
// after 80 steps, at hi - lo <= 1e-17, or once mid rounds to lo or hi (no later step could move
// either: g(lo) < 0 <= g(hi); a root in [0.5, 1] is there after ~54 steps).
// Each round first evaluates g at all 2^kDepth - 1 midpoints its next kDepth steps may visit,
// independent of each other, so that the core overlaps them (an ensemble of 10^4 flawed chains
// spends most of a fast pull here, issue #23); then it takes those steps on the values. The
// midpoints are those the steps compute, 0.5 * (lo + hi) of the same lo and hi, and so are their
// values and every decision: the same bits as one step at a time (20 million random calls
// against the one-step loop, 13 million of them crossings: none differs). A quarter faster;
// most of the rest is the chain of three midpoints and a cubic a round.
template <class G>
double bisect(const G& g, double lo, double hi) {
  constexpr int kDepth = 3, kNodes = (1 << kDepth) - 1;
  for (int i = 0;;) {
    // Node k's children 2k + 1 (g(mid) >= 0: hi = mid) and 2k + 2 (lo = mid).
    double left[kNodes], right[kNodes], mid[kNodes];
    bool reached[kNodes];
    left[0] = lo, right[0] = hi;
    // Unrolled, or the arrays live in memory and the round costs what the steps did.
#pragma GCC unroll 8
    for (int k = 0; k < kNodes; ++k) {
      mid[k] = 0.5 * (left[k] + right[k]);
      if (2 * k + 2 < kNodes) {
        left[2 * k + 1] = left[k], right[2 * k + 1] = mid[k];
        left[2 * k + 2] = mid[k], right[2 * k + 2] = right[k];
      }
    }
#pragma GCC unroll 8
    for (int k = 0; k < kNodes; ++k) reached[k] = g(mid[k]) >= 0.0;
#pragma GCC unroll 8
    for (int level = 0, k = 0; level < kDepth; ++level, ++i) {
      if (i >= 80 || !(hi - lo > 1e-17) || mid[k] == lo || mid[k] == hi) return hi;
      (reached[k] ? hi : lo) = mid[k];
      k = reached[k] ? 2 * k + 1 : 2 * k + 2;
    }
  }
}

}  // namespace

double hermite_first_crossing(double p0, double p1, double m0, double m1, double h, double upper,
                              double lower) {
  // p(s) = a + b s + q s^2 + d s^3 on s = theta / h in [0, 1].
  const double a = p0, b = h * m0;
  const double q = -3.0 * p0 - 2.0 * h * m0 + 3.0 * p1 - h * m1;
  const double d = 2.0 * p0 + h * m0 - 2.0 * p1 + h * m1;
  auto p = [&](double s) { return a + s * (b + s * (q + s * d)); };
  // lower - p(s) is -(p(s) - lower): for lower = -c the bits of the one-sided -p(s) - c.
  const bool stretch_only = lower == -std::numeric_limits<double>::infinity();
  auto up = [&](double s) { return p(s) - upper; };
  auto down = [&](double s) { return lower - p(s); };
  auto reached = [&](double s) { return up(s) >= 0.0 || (!stretch_only && down(s) >= 0.0); };
  if (reached(0.0)) return 0.0;

  // Split [0, 1] where p' = b + 2 q s + 3 d s^2 vanishes: p is monotone on each piece, so
  // a sign change at a piece's ends is the only way to cross inside it.
  double cuts[4] = {0.0, 1.0, 1.0, 1.0};
  int count = 1;
  const double A = 3.0 * d, B = 2.0 * q, C = b;
  if (std::abs(A) > 1e-300) {
    const double disc = B * B - 4.0 * A * C;
    if (disc > 0.0) {
      const double r = std::sqrt(disc);
      // Stable roots of the quadratic (no cancellation).
      const double t = -0.5 * (B + std::copysign(r, B));
      double r1 = t / A, r2 = t != 0.0 ? C / t : r1;
      if (r1 > r2) std::swap(r1, r2);
      for (double r0 : {r1, r2})
        if (r0 > 0.0 && r0 < 1.0) cuts[count++] = r0;
    }
  } else if (std::abs(B) > 1e-300) {
    const double r0 = -C / B;
    if (r0 > 0.0 && r0 < 1.0) cuts[count++] = r0;
  }
  cuts[count++] = 1.0;
  for (int k = 0; k + 1 < count; ++k) {
    const double lo = cuts[k], hi = cuts[k + 1];
    double best = 2.0;
    if (up(lo) < 0.0 && up(hi) >= 0.0) best = bisect(up, lo, hi);
    if (!stretch_only && down(lo) < 0.0 && down(hi) >= 0.0)
      best = std::min(best, bisect(down, lo, hi));
    if (best <= 1.0) return best * h;
  }
  return -1.0;
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
