// The batched bisection of Hermite roots (physics/crossing_bisect.inc, through crossing.h's
// finish_hermite_roots) against a plain scalar loop written here from the rule: every compiled
// path the CPU runs (the x86-64 baseline, AVX2, AVX-512, and the one-root group), in batches
// that leave groups partly filled, gives each root's theta bit for bit.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "physics/crossing.h"
#include "physics/simd.h"

namespace {

using cb::detail::HermiteRoot;

// The rule, one bracket at a time: g = p - upper (or lower - p for a bracket of the lower
// bound), p(s) = a + s (b + s (q + s d)) in that order; at most 80 steps; a step stops the
// bracket when hi - lo is not above 1e-17 or when mid rounds to lo or hi, else moves hi to mid
// where g(mid) >= 0 and lo otherwise. theta: the smallest hi of the root's brackets, times h.
double reference_theta(const HermiteRoot& r) {
  if (r.brackets == 0) return r.theta;
  double theta = 2.0;
  for (int k = 0; k < r.brackets; ++k) {
    double lo = r.lo[k], hi = r.hi[k];
    for (int i = 0; i < 80; ++i) {
      if (!(hi - lo > 1e-17)) break;
      const double mid = 0.5 * (lo + hi);
      if (mid == lo || mid == hi) break;
      const double p = r.a + mid * (r.b + mid * (r.q + mid * r.d));
      const double g = r.down[k] ? r.lower - p : p - r.upper;
      if (g >= 0.0)
        hi = mid;
      else
        lo = mid;
    }
    theta = std::min(theta, hi);
  }
  return theta * r.h;
}

// What hermite_root is given.
struct RootInputs {
  double p0, p1, m0, m1, h, upper, lower;
};

// Random roots of every kind the bisection meets, and the nasty ones: roots at s = 0 and 1,
// cubics that only just touch a bound, rises of a few ulps through it, slopes that only just
// keep p' from vanishing in the step, exact hits of the bound at a midpoint (dyadic lines), tiny
// h, magnitudes from 2^-1000 to 2^1000 (products near the subnormals and near overflow),
// stretch-only chains (lower = -inf) and both bounds in reach.
class RootMaker {
 public:
  explicit RootMaker(std::uint64_t seed) : rng_(seed) {}

  HermiteRoot next() {
    const RootInputs in = next_inputs();
    return cb::detail::hermite_root(in.p0, in.p1, in.m0, in.m1, in.h, in.upper, in.lower);
  }

  RootInputs next_inputs() {
    const int kind = static_cast<int>(rng_() % 11);
    const double upper = std::ldexp(uniform(0.1, 2.0), -static_cast<int>(rng_() % 4));
    double lower = lower_for(upper);
    double h = std::exp(uniform(std::log(1e-4), std::log(1.0)));
    double p0 = uniform(-1.5, 1.0) * upper, p1 = uniform(-1.5, 2.0) * upper;
    double m0 = uniform(-20.0, 20.0) * upper / h, m1 = uniform(-20.0, 20.0) * upper / h;
    switch (kind) {
      case 0:  // the general case above
        break;
      case 1:  // a root at s = 0: p0 just below the bound, rising
        p0 = std::nextafter(upper, 0.0) - (rng_() % 2 ? 0.0 : std::ldexp(upper, -40));
        m0 = std::abs(m0);
        break;
      case 2:  // a root at s = 1: p1 on the bound, or just above
        p1 = rng_() % 2 ? upper : std::nextafter(upper, 10.0);
        p0 = uniform(-1.0, 0.9) * upper;
        break;
      case 3: {  // near-tangent: the cubic's top within a hair of the bound
        p0 = uniform(-1.0, 0.5) * upper, p1 = p0;
        const double top = upper * (1.0 + std::ldexp(uniform(-1.0, 1.0), -30 - rng_() % 20));
        m0 = 4.0 * (top - p0) / h, m1 = -m0;  // p = p0 + h m0 (s - s^2): top at s = 1/2
        break;
      }
      case 4: {  // a dyadic line through the bound at a midpoint: g(mid) == 0 exactly
        const double c = std::ldexp(static_cast<double>(1 + rng_() % 64), -5);
        const double delta = std::ldexp(1.0, -static_cast<int>(rng_() % 20));
        h = std::ldexp(1.0, -static_cast<int>(rng_() % 12));
        const double s = std::ldexp(static_cast<double>(1 + rng_() % 15), -4);  // in (0, 1)
        p0 = c - s * delta, p1 = p0 + delta;
        m0 = m1 = delta / h;
        return {p0, p1, m0, m1, h, c, rng_() % 2 ? -c : -kInf};
      }
      case 5:  // tiny h with steep slopes
        h = std::ldexp(1.0, -static_cast<int>(30 + rng_() % 60));
        m0 = uniform(-20.0, 20.0) * upper / h, m1 = uniform(-20.0, 20.0) * upper / h;
        break;
      case 6: {  // everything scaled by 2^k: huge and tiny magnitudes, subnormal-ish products
        const int k = static_cast<int>(rng_() % 2001) - 1000;
        const double scale = std::ldexp(1.0, k);
        return {p0 * scale, p1 * scale, m0 * scale, m1 * scale, h, upper * scale, lower * scale};
      }
      case 7:  // values next to the subnormals, unscaled bounds
        p0 = std::ldexp(uniform(-1.0, 1.0), -1020), p1 = upper * uniform(0.5, 2.0);
        m0 = std::ldexp(uniform(-1.0, 1.0), -1030), m1 = uniform(-4.0, 4.0) * upper / h;
        break;
      case 8:  // falling towards the lower bound
        p0 = uniform(-0.5, 0.9) * upper, p1 = lower == -kInf ? -upper : 1.5 * lower;
        break;
      case 9: {  // a rise of a few ulps through the bound: where g(mid) >= 0 is rounding's call
        // over much of [0, 1] (the bisection's skip ahead must see it cannot decide those)
        const double ulps = std::ldexp(upper, -52 + static_cast<int>(rng_() % 12));
        p0 = upper - uniform(0.0, 8.0) * ulps, p1 = upper + uniform(0.0, 8.0) * ulps;
        m0 = (p1 - p0) / h * uniform(0.5, 1.5), m1 = (p1 - p0) / h * uniform(0.5, 1.5);
        break;
      }
      case 10: {  // p = a + b s + q s^2 + d s^3 with |b| near 4 (3 |d| + 2 |q|), where
        // hermite_root stops looking for p' = 0 in the step; p' = 0 within [-1.5, 1.5] or not
        const double b = uniform(-1.0, 1.0) * upper, share = uniform(0.0, 1.0);
        const double near =
            0.25 * (1.0 + std::ldexp(uniform(-1.0, 1.0), -static_cast<int>(rng_() % 53)));
        const double q = (rng_() % 2 ? 1.0 : -1.0) * std::abs(b) * near * share / 2.0;
        const double d = (rng_() % 2 ? 1.0 : -1.0) * std::abs(b) * near * (1.0 - share) / 3.0;
        p0 = upper * uniform(-1.0, 0.99), p1 = p0 + b + q + d;
        m0 = b / h, m1 = (d - 2.0 * p0 - b + 2.0 * p1) / h;
        break;
      }
    }
    return {p0, p1, m0, m1, h, upper, lower};
  }

 private:
  static constexpr double kInf = std::numeric_limits<double>::infinity();

  double uniform(double lo, double hi) { return std::uniform_real_distribution<>(lo, hi)(rng_); }

  double lower_for(double upper) {
    switch (rng_() % 3) {
      case 0:
        return -upper;  // the paper's |phi| >= c
      case 1:
        return -kInf;  // stretch-only
      default:
        return -upper * uniform(0.01, 3.0);
    }
  }

  std::mt19937_64 rng_;
};

struct Path {
  std::string name;
  void (*finish)(HermiteRoot*, std::size_t);
};

}  // namespace

TEST_CASE("every bisection path gives the scalar loop's theta bit for bit", "[crossing]") {
  std::vector<Path> paths = {{"baseline", cb::detail::sse2::finish_hermite_roots},
                             {"dispatched", cb::detail::finish_hermite_roots}};
  if (cb::simd_supported(cb::SimdPath::Avx2))  // __builtin_cpu_supports("avx2") and "fma"
    paths.push_back({"avx2", cb::detail::avx2::finish_hermite_roots});
  else
    WARN("this CPU has no AVX2: its path is not checked");
  if (cb::simd_supported(cb::SimdPath::Avx512))  // __builtin_cpu_supports("avx512f")
    paths.push_back({"avx512", cb::detail::avx512::finish_hermite_roots});
  else
    WARN("this CPU has no AVX-512: its path is not checked");

  // 6 x 10^5 roots with brackets (and the ones without, whose theta must not move), in batches
  // of 1 (the dispatcher's one-root group), 2, 7, 33 and 1000: groups partly filled.
  RootMaker maker(20261129);
  std::vector<HermiteRoot> roots;
  std::size_t bracketed = 0, down = 0;
  while (bracketed < 600000) {
    roots.push_back(maker.next());
    const HermiteRoot& r = roots.back();
    bracketed += r.brackets > 0;
    for (int k = 0; k < r.brackets; ++k) down += r.down[k];
  }
  std::vector<double> expected(roots.size());
  for (std::size_t k = 0; k < roots.size(); ++k) expected[k] = reference_theta(roots[k]);
  std::size_t at_zero = 0, at_one = 0;
  for (std::size_t k = 0; k < roots.size(); ++k) {
    if (roots[k].brackets == 0) continue;
    at_zero += expected[k] / roots[k].h < 1e-15;
    at_one += expected[k] == roots[k].h;
  }
  INFO(roots.size() << " roots, " << bracketed << " bisected, " << down << " lower-bound brackets, "
                    << at_zero << " at s ~ 0, " << at_one << " at s = 1");
  CHECK(down > 10000);
  CHECK(at_zero > 1000);
  CHECK(at_one > 1000);

  const std::size_t batches[] = {1, 2, 7, 33, 1000};
  for (const Path& path : paths) {
    std::vector<HermiteRoot> work = roots;
    std::size_t begin = 0;
    for (int b = 0; begin < work.size(); ++b) {
      const std::size_t size = std::min(batches[b % 5], work.size() - begin);
      path.finish(work.data() + begin, size);
      begin += size;
    }
    std::size_t differ = 0, first = work.size();
    for (std::size_t k = 0; k < work.size(); ++k)
      if (std::memcmp(&work[k].theta, &expected[k], sizeof(double)) != 0) {
        if (differ++ == 0) first = k;
      }
    INFO(path.name << ": " << differ << " of " << work.size() << " thetas differ"
                   << (differ ? ", the first: root " + std::to_string(first) : std::string()));
    CHECK(differ == 0);
  }
}

TEST_CASE("where hermite_root skips the quadratic, it has no root inside the step", "[crossing]") {
  // slope_keeps_sign (the shortcut) against slope_zeros_inside (the quadratic solved, as
  // hermite_root solves it otherwise) on the slopes of 10^6 cubics of every kind above: where
  // the one says p' keeps its sign, the other must find no cut, or hermite_root's brackets would
  // change.
  RootMaker maker(20261130);
  std::size_t wrong = 0, skipped = 0, near_edge = 0, with_zeros = 0;
  int first = -1;
  for (int i = 0; i < 1000000; ++i) {
    const RootInputs in = maker.next_inputs();
    const HermiteRoot r =
        cb::detail::hermite_root(in.p0, in.p1, in.m0, in.m1, in.h, in.upper, in.lower);
    const double A = 3.0 * r.d, B = 2.0 * r.q, C = r.b;
    double zeros[2];
    const int found = cb::detail::slope_zeros_inside(A, B, C, zeros);
    with_zeros += found > 0;
    const double edge = std::abs(C) / (std::abs(A) + std::abs(B));
    near_edge += edge >= 3.0 && edge <= 5.0;
    if (!cb::detail::slope_keeps_sign(A, B, C)) continue;
    ++skipped;
    if (found > 0 && wrong++ == 0) first = i;
  }
  INFO(skipped << " cubics skip the quadratic, " << near_edge << " near where they start to, "
               << with_zeros << " have p' = 0 inside the step; " << wrong
               << " skipped a zero, the first: cubic " << first);
  CHECK(skipped > 100000);
  CHECK(near_edge > 50000);
  CHECK(with_zeros > 50000);
  CHECK(wrong == 0);
}
