#include "physics/crossing.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "physics/coefficients.h"

namespace cb::detail {

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
  int count = 1;
  const double A = 3.0 * r.d, B = 2.0 * r.q, C = r.b;
  if (std::abs(A) > 1e-300) {
    const double disc = B * B - 4.0 * A * C;
    if (disc > 0.0) {
      const double root = std::sqrt(disc);
      // Stable roots of the quadratic (no cancellation).
      const double t = -0.5 * (B + std::copysign(root, B));
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
  // The first piece where a bound is reached holds the crossing: its brackets.
  auto add = [&](double lo, double hi, bool is_down) {
    r.lo[r.brackets] = lo, r.hi[r.brackets] = hi, r.down[r.brackets] = is_down;
    ++r.brackets;
  };
  for (int k = 0; k + 1 < count && r.brackets == 0; ++k) {
    const double lo = cuts[k], hi = cuts[k + 1];
    if (up(lo) < 0.0 && up(hi) >= 0.0) add(lo, hi, false);
    if (!stretch_only && down(lo) < 0.0 && down(hi) >= 0.0) add(lo, hi, true);
  }
  return r;
}

namespace {

// Four lanes (two SSE2 registers, or what the target has). Only ever local values: a function
// taking or returning them would change the ABI with the instruction set (-Wpsabi).
typedef double V4 __attribute__((vector_size(32)));
typedef long long L4 __attribute__((vector_size(32)));

}  // namespace

// The bisection of g on [lo, hi], g(lo) < 0 <= g(hi): mid = (lo + hi) / 2, then hi = mid where
// g(mid) >= 0, else lo = mid; it stops after 80 steps, at hi - lo <= 1e-17, or once mid rounds
// to lo or hi (no later step could move either; a root in [0.5, 1] is there after ~54 steps),
// and returns hi: the crossing, to double precision in s. Four brackets at a time, one per lane
// of a vector, each lane's operations and decisions those of its bracket alone (IEEE lane by
// lane; a lane that has stopped keeps its lo and hi): the same bits as one at a time (20 million
// random roots against the scalar loop compared, session 13).
void finish_hermite_roots(HermiteRoot* roots, std::size_t count) {
  struct Job {
    HermiteRoot* root;
    int bracket;
  };
  Job group[4];
  std::size_t lanes = 0;
  auto bisect_group = [&] {
    V4 a{}, b{}, q{}, d{}, c{}, lo{}, hi{};
    L4 down{}, active{};
    for (std::size_t l = 0; l < lanes; ++l) {
      const HermiteRoot& r = *group[l].root;
      const int k = group[l].bracket;
      a[l] = r.a, b[l] = r.b, q[l] = r.q, d[l] = r.d;
      c[l] = r.down[k] ? r.lower : r.upper;
      down[l] = r.down[k] ? -1 : 0;
      lo[l] = r.lo[k], hi[l] = r.hi[k];
      active[l] = -1;
    }
    const V4 half = V4{} + 0.5;
    const V4 width = V4{} + 1e-17;
    for (int i = 0; i < 80; ++i) {
      active &= hi - lo > width;
      const V4 mid = half * (lo + hi);
      active &= (mid != lo) & (mid != hi);
      if (!(active[0] | active[1] | active[2] | active[3])) break;
      const V4 p = a + mid * (b + mid * (q + mid * d));
      // g = c - p where the bracket is the lower bound's, else p - c (bits chosen, not mixed).
      const L4 g = (reinterpret_cast<L4>(c - p) & down) | (reinterpret_cast<L4>(p - c) & ~down);
      const L4 reached = reinterpret_cast<V4>(g) >= V4{};
      const L4 to_hi = active & reached, to_lo = active & ~reached;
      const L4 m = reinterpret_cast<L4>(mid);
      hi = reinterpret_cast<V4>((m & to_hi) | (reinterpret_cast<L4>(hi) & ~to_hi));
      lo = reinterpret_cast<V4>((m & to_lo) | (reinterpret_cast<L4>(lo) & ~to_lo));
    }
    for (std::size_t l = 0; l < lanes; ++l) {
      HermiteRoot& r = *group[l].root;
      r.theta = std::min(r.theta, hi[l]);
    }
    lanes = 0;
  };
  for (std::size_t k = 0; k < count; ++k) {
    HermiteRoot& r = roots[k];
    if (r.brackets == 0) continue;
    r.theta = 2.0;  // the smaller of its brackets' roots (times h below)
    for (int b = 0; b < r.brackets; ++b) {
      group[lanes++] = {&r, b};
      if (lanes == 4) bisect_group();
    }
  }
  if (lanes > 0) bisect_group();
  for (std::size_t k = 0; k < count; ++k)
    if (roots[k].brackets > 0) roots[k].theta *= roots[k].h;
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
