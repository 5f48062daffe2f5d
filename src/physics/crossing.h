// Internal: where inside a step a spring or the pull string reaches its threshold, and the one
// rule every kernel uses to decide that a spring may reach it (kernels, lanes, Integrator).
#pragma once

#include <cmath>
#include <cstddef>
#include <functional>
#include <vector>

namespace cb {
struct ChainCoefficients;
}

namespace cb::detail {

// A spring's Hermite cubic on a step of h is bounded by the larger end value plus
// kHermiteSlack h (|m0| + |m1|) (the extremes of the derivative basis functions 4/27 and
// -4/27): a spring that stays below that bound cannot cross inside the step. The one place
// this constant is written.
inline constexpr double kHermiteSlack = 4.0 / 27.0;
inline double hermite_slack(double h) {
  return kHermiteSlack * h;
}

// A spring whose Hermite cubic over the step may reach its bounds (phi and dphi/dtau at both
// ends of the step).
struct Candidate {
  int spring;
  double p0, p1, m0, m1;
};

// First theta in [0, h] at which the cubic Hermite interpolant of phi through
// (0, p0, m0) and (h, p1, m1) reaches a bound: phi >= upper or phi <= lower (lower = -inf:
// only tension breaks; the paper's |phi| >= c is upper = c, lower = -c); a negative value
// when it does not. The interpolant's error is O(h^4), so the crossing time is too wherever
// phi crosses with a nonzero slope.
//
// The search in two parts, for callers with many (an ensemble settles up to 10^4 members'
// crossings, threshold_ensemble.cpp): hermite_root() finds whether and in which bracket the
// cubic first reaches a bound (cheap), finish_hermite_roots() bisects the brackets of many such
// roots together, a group of SIMD lanes at a time (crossing_bisect.inc: 64 on AVX-512, 32 on
// AVX2, 16 on SSE2): each is the one bisection, step for step, and independent of the others,
// so their chains of dependent operations overlap in the core.
struct HermiteRoot {
  double a = 0.0, b = 0.0, q = 0.0, d = 0.0;  // p(s) = a + b s + q s^2 + d s^3, s = theta / h
  double h = 0.0, upper = 0.0, lower = 0.0;
  // Where the crossing is: up to two brackets of s (one piece of [0, 1] where p is monotone;
  // the upper and the lower bound may both be reached in it), each with g(lo) < 0 <= g(hi) for
  // g = p - upper, or lower - p when `down`.
  int brackets = 0;
  double lo[2] = {0.0, 0.0}, hi[2] = {0.0, 0.0};
  bool down[2] = {false, false};
  // The answer: -1 (no crossing) or 0 (at the start) at once, otherwise set by
  // finish_hermite_roots from the brackets' bisections.
  double theta = -1.0;
  // Whether phi reaches a bound in [0, h] (known before the bisections).
  bool crosses() const { return theta >= 0.0 || brackets > 0; }
};
HermiteRoot hermite_root(double p0, double p1, double m0, double m1, double h, double upper,
                         double lower);
// Where p' = C + B s + A s^2 vanishes inside (0, 1), as hermite_root cuts [0, 1]: the stable
// roots of the quadratic (or -C / B where A is negligible), ascending into `zeros` (room for 2);
// their count.
int slope_zeros_inside(double A, double B, double C, double* zeros);
// hermite_root's shortcut: where |C| >= 4 (|A| + |B|), p' keeps C's sign on [-1, 1], and the
// roots slope_zeros_inside would round lie beyond 1 in size (|r| >= sqrt |C / A| or |C / B| or
// |C| / |t| with |t| <= 3/4 |C|, a few ulps aside): it would find none, so the sqrt and the
// divisions are skipped. The usual case: over one step the slope changes little.
inline bool slope_keeps_sign(double A, double B, double C) {
  return std::abs(C) >= 4.0 * (std::abs(A) + std::abs(B));
}
void finish_hermite_roots(HermiteRoot* roots, std::size_t count);
// The same for the x86-64 baseline (crossing.cpp), the AVX2 and the AVX-512 paths
// (crossing_avx2.cpp, crossing_avx512.cpp), which finish_hermite_roots picks by active_simd()
// (one root alone: the baseline's narrower group); each path's bits are the others'.
namespace sse2 {
void finish_hermite_roots(HermiteRoot* roots, std::size_t count);
}
namespace avx2 {
void finish_hermite_roots(HermiteRoot* roots, std::size_t count);
}
namespace avx512 {
void finish_hermite_roots(HermiteRoot* roots, std::size_t count);
}

inline double hermite_first_crossing(double p0, double p1, double m0, double m1, double h,
                                     double upper, double lower) {
  HermiteRoot root = hermite_root(p0, p1, m0, m1, h, upper, lower);
  finish_hermite_roots(&root, 1);
  return root.theta;
}

// The earliest crossing rule: a crossing at ta + theta (theta < 0: none) of `spring` replaces
// the one kept (*first, *kept) if earlier; ties go to the lower spring.
inline void keep_earliest(int spring, double ta, double theta, int* kept, double* first) {
  if (theta >= 0.0 && (ta + theta < *first || (ta + theta == *first && spring < *kept))) {
    *first = ta + theta;
    *kept = spring;
  }
}

// The earliest crossing among `candidates` inside [ta, tb], each spring against its own bounds
// (coef's upper_of / lower_of); ties go to the lower spring. Returns the spring and sets
// *first to its time, or -1 (*first = tb + 1) when none crosses.
int earliest_crossing(const std::vector<Candidate>& candidates, const ChainCoefficients& coef,
                      double ta, double tb, double* first);

// The same search with each spring's bounds from bounds(spring, &upper, &lower): the one search
// for Integrator, the lanes and ensembles over thresholds (threshold_ensemble.h).
template <class Bounds>
int earliest_crossing_within(const std::vector<Candidate>& candidates, const Bounds& bounds,
                             double ta, double tb, double* first) {
  *first = tb + 1.0;
  int spring = -1;
  for (const Candidate& c : candidates) {
    double upper = 0.0, lower = 0.0;
    bounds(c.spring, &upper, &lower);
    keep_earliest(c.spring, ta,
                  hermite_first_crossing(c.p0, c.p1, c.m0, c.m1, tb - ta, upper, lower), &spring,
                  first);
  }
  return spring;
}

// First t in [ta, tb] with f(t) >= c, by sampling and bisection; negative when none.
// f is evaluated at tb only through f_end (its left limit there).
double first_time_at_least(const std::function<double(double)>& f, double f_end, double ta,
                           double tb, double c);

}  // namespace cb::detail
