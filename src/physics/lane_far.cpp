#include "physics/lane_far.h"

#include <immintrin.h>  // stencil.inc's fmadd

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>

#include "physics/crossing.h"

namespace cb::detail {

// The kernels' crossing bound (bound_reaches), here on doubles only.
#include "physics/stencil.inc"

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// The map's own rounding (a few dozen roundings of nonnegative terms: < 10^-13 relative).
constexpr double kMapRounding = 1e-10;
// Bounds past this are no proof (their sums in the kernel must stay far from overflow).
constexpr double kLargest = 1e100;

struct Pm {
  double p, m;
};

// One RK4 step's bound (lane_far.h) from P, M and F in exact arithmetic.
Pm rk4_step_bound(Pm s, double f, double h, double cp, double g2, double cf) {
  auto a = [&](Pm q) { return cp * q.p + g2 * q.m + cf * f; };
  const Pm s1 = {s.p + 0.5 * h * s.m, s.m + 0.5 * h * a(s)};
  const Pm s2 = {s.p + 0.5 * h * s1.m, s.m + 0.5 * h * a(s1)};
  const Pm s3 = {s.p + h * s2.m, s.m + h * a(s2)};
  return {s.p + h / 6.0 * (s.m + 2.0 * s1.m + 2.0 * s2.m + s3.m),
          s.m + h / 6.0 * (a(s) + 2.0 * a(s1) + 2.0 * a(s2) + a(s3))};
}

}  // namespace

FarMap::FarMap(const ChainCoefficients& c, double gamma, double dt) {
  if (c.anharmonic || c.weighted() || !(dt > 0.0) || !(gamma >= 0.0)) return;
  const int n = c.beads;
  double cp = 4.0, cf = 1.0;
  if (c.per_bead) {
    cp = 0.0;
    for (int j = 0; j < n; ++j)  // stiffness[n] is K_{N+1} = 0
      cp = std::max(cp, 2.0 * c.inv_mass[j] * (c.stiffness[j] + c.stiffness[j + 1]));
    cf = c.inv_mass[n - 1];
  }
  const double g2 = 2.0 * gamma;
  // The largest step the proof covers: the run's steps are dt up to the rounding of their ends.
  h_ = dt * (1.0 + 1e-6);
  if (!(h_ * (cp + g2 + cf) <= 1.0)) return;
  // The kernel's rounding per step, per unit of P + M + F (lane_far.h).
  const double e = 1e-9 * 16.0 * (n + 1) * (1.0 + cp + g2 + cf);
  const Pm from_p = rk4_step_bound({1.0, 0.0}, 0.0, h_, cp, g2, cf);
  const Pm from_m = rk4_step_bound({0.0, 1.0}, 0.0, h_, cp, g2, cf);
  const Pm from_f = rk4_step_bound({0.0, 0.0}, 1.0, h_, cp, g2, cf);
  const double up = 1.0 + kMapRounding;
  const std::array<double, 4> t = {from_p.p * up + 2.0 * e, from_m.p * up + 2.0 * e,
                                   from_p.m * up + 2.0 * e, from_m.m * up + 2.0 * e};
  const std::array<double, 2> b = {from_f.p * up + 2.0 * e, from_f.m * up + 2.0 * e};
  // T^(r+1) = T T^r and c_(r+1) = T c_r + b, each product of nonnegative numbers inflated once.
  power_[0] = t;
  force_[0] = b;
  for (int r = 1; r < kMaxFarSteps; ++r) {
    const auto& q = power_[r - 1];
    const auto& g = force_[r - 1];
    power_[r] = {(t[0] * q[0] + t[1] * q[2]) * up, (t[0] * q[1] + t[1] * q[3]) * up,
                 (t[2] * q[0] + t[3] * q[2]) * up, (t[2] * q[1] + t[3] * q[3]) * up};
    force_[r] = {(t[0] * g[0] + t[1] * g[1] + b[0]) * up, (t[2] * g[0] + t[3] * g[1] + b[1]) * up};
  }
  valid_ = std::isfinite(power_.back()[0] + power_.back()[3] + force_.back()[0]);
}

FarMap::Bounds FarMap::after(int steps, double p0, double m0, double f_max) const {
  if (!valid_ || steps < 1 || steps > kMaxFarSteps) return {kInf, kInf};
  const auto& q = power_[static_cast<std::size_t>(steps - 1)];
  const auto& g = force_[static_cast<std::size_t>(steps - 1)];
  // p0, m0 are the kernel's rounded maxima of |phi| and |dphi/dtau| (within 2^-53 of the true
  // ones), f_max a rounded |f|: the inflation covers them and this sum's own rounding.
  const double up = 1.0 + kMapRounding;
  return {(q[0] * p0 + q[1] * m0 + g[0] * f_max) * up, (q[2] * p0 + q[3] * m0 + g[1] * f_max) * up};
}

double largest_magnitude(const double* v, int n) {
  // Two running maxima: one is a chain of dependent maxsd (it was 16 % of the lanes driver).
  double a = 0.0, b = 0.0;
  bool nan = false;
  int i = 0;
  for (; i + 1 < n; i += 2) {
    const double x = std::abs(v[i]), y = std::abs(v[i + 1]);
    a = std::max(a, x), b = std::max(b, y);
    nan = nan || std::isnan(x) || std::isnan(y);
  }
  if (i < n) {
    a = std::max(a, std::abs(v[i]));
    nan = nan || std::isnan(v[i]);
  }
  return nan ? std::numeric_limits<double>::quiet_NaN() : std::max(a, b);
}

bool proven_far(FarMap::Bounds b, double h, double threshold) {
  if (!(b.p < kLargest && b.m < kLargest)) return false;  // also false for NaN
  // The kernel's test with larger arguments: rounding is monotone, so its own is false too.
  return !bound_reaches(b.p, b.m, b.m, hermite_slack(h), threshold);
}

}  // namespace cb::detail
