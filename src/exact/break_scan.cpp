#include "exact/break_scan.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <utility>

namespace cb::detail {

namespace {

constexpr double kNone = std::numeric_limits<double>::infinity();
constexpr int kMaxDepth = 48;        // 0.25 / 2^48 is far below kMinWidth
constexpr double kMinWidth = 1e-10;  // narrower: phi can overshoot its samples by <= M h^2 / 8
constexpr double kTol = 1e-12;       // crossing times
constexpr double kRound = 1e-13;     // relative rounding allowance in x_n'' from the mode equation

// Upper bound of phi on [0, h] from phi(0) = p0, phi(h) = p1, phi'(0+) = m0, phi'(h-) = m1 and
// |phi''| <= M: phi <= min(qa, qb) with qa(u) = p0 + m0 u + M u^2/2 and
// qb(u) = p1 - m1 (h - u) + M (h - u)^2 / 2. Both are convex and qa - qb is linear in u, so
// max min(qa, qb) is at u = 0, u = h or where they meet.
// `allowance`: what the computed samples may be off by beyond their rounding (0 for closed-form
// modes; the eigen-solver's error otherwise, see break_scan.h).
double interval_upper(double p0, double p1, double m0, double m1, double h, double M,
                      double allowance) {
  double bound = std::max(p0, p1);
  const double slope = m0 - m1 + M * h;  // >= 0 whenever M really bounds |phi''|
  if (slope > 0.0) {
    const double u = -(p0 - p1 + m1 * h - 0.5 * M * h * h) / slope;
    if (u > 0.0 && u < h) {
      const double qa = p0 + m0 * u + 0.5 * M * u * u;
      const double qb = p1 - m1 * (h - u) + 0.5 * M * (h - u) * (h - u);
      bound = std::max(bound, std::max(qa, qb));
    }
  }
  return bound + 1e-12 * (std::abs(p0) + std::abs(p1)) + allowance;  // the samples' rounding
}

}  // namespace

BreakScan::BreakScan(const ExactChain& chain, BreakMode mode, double t_end, double step,
                     std::vector<double> ratio)
    : chain_(chain),
      n_(chain.beads()),
      abs_(mode == BreakMode::Abs),
      t_end_(t_end),
      step_(step),
      ratio_(std::move(ratio)),
      pool_(kMaxDepth) {
  assert(step > 0.0 && std::isfinite(t_end));
  assert(ratio_.empty() || ratio_.size() == static_cast<std::size_t>(n_));
  for (double t : chain.drive_terms().breakpoints())
    if (t > 0.0 && t < t_end) breakpoints_.push_back(t);
  bound_up_.resize(n_);
  bound_down_.resize(n_);
  if (t_end > 0.0) {
    sample(0.0, b_);
    have_interval_ = advance();
  }
}

void BreakScan::sample(double tau, Node& node) const {
  Probe& p = node.probe;
  p.tau = tau;
  chain_.modal(tau, p.x, p.v);
  node.phi.resize(n_);
  node.rate.resize(n_);
  node.rate_before.resize(n_);
  for (int j = 1; j <= n_; ++j) evaluate(j, p, node.phi[j - 1], node.rate[j - 1]);
  std::vector<double> errors;  // stays empty (no allocation) for closed-form modes
  mode_errors(p, errors);
  node.error.clear();
  if (!errors.empty())
    for (int j = 1; j <= n_; ++j) node.error.push_back(spring_error(j, errors));
  node.rate_before = node.rate;
  for (const Kick& k : chain_.drive_terms().kicks)
    if (k.tau == tau) {
      Probe before;
      chain_.modal_before(tau, before.x, before.v);
      double unused;
      for (int j = 1; j <= n_; ++j) evaluate(j, before, unused, node.rate_before[j - 1]);
      break;
    }
}

bool BreakScan::advance() {
  if (b_.probe.tau >= t_end_) return false;
  std::swap(a_, b_);
  const double a = a_.probe.tau;
  double t = std::min(a + step_, t_end_);
  while (next_break_ < breakpoints_.size() && breakpoints_[next_break_] <= a) ++next_break_;
  if (next_break_ < breakpoints_.size()) t = std::min(t, breakpoints_[next_break_]);
  sample(t, b_);
  const double h = t - a;
  mode_bounds(a_.probe, h, scratch_);
  bound_max_ = -kNone;
  for (int i = 0; i < n_; ++i) {
    const double M = accel_bound(i + 1, scratch_);
    const double pa = a_.phi[i], pb = b_.phi[i], ma = a_.rate[i], mb = b_.rate_before[i];
    const double e = a_.error.empty() ? 0.0 : std::max(a_.error[i], b_.error[i]);
    bound_up_[i] = interval_upper(pa, pb, ma, mb, h, M, e);
    bound_down_[i] = abs_ ? interval_upper(-pa, -pb, -ma, -mb, h, M, e) : -kNone;
    bound_max_ = std::max({bound_max_, bound_up_[i] / ratio(i + 1), bound_down_[i] / ratio(i + 1)});
  }
  return true;
}

// max |x_n''| on [a, a + h]. y = x_n'' obeys y'' + 2 gamma y' + Omega^2 y = f'' inside the
// interval, so A = sqrt(y'^2 + Omega^2 y^2) satisfies A' <= |f''|: |y| <= A / Omega, and
// also |y(t) - y(a)| <= int |y'| <= h A(a) + h^2 max|f''| / 2 (tighter for slow modes).
void BreakScan::mode_bounds(const Probe& a, double h, std::vector<double>& out) const {
  const DriveTerms& drive = chain_.drive_terms();
  const double f = drive.value(a.tau), fdot = drive.slope(a.tau), f2 = drive.curvature_bound();
  const double two_gamma = 2.0 * chain_.gamma();
  out.resize(n_);
  for (int n = 0; n < n_; ++n) {
    const double omega = chain_.frequency(n), omega2 = omega * omega;
    const double x = a.x[n], v = a.v[n];
    // x'' and x''' just after a, from the mode equation, with an allowance for its rounding.
    const double acc = f - two_gamma * v - omega2 * x;
    const double acc_err = kRound * (std::abs(f) + two_gamma * std::abs(v) + omega2 * std::abs(x));
    const double jerk = fdot - two_gamma * acc - omega2 * v;
    const double jerk_err =
        kRound * (std::abs(fdot) + two_gamma * std::abs(acc) + omega2 * std::abs(v)) +
        two_gamma * acc_err;
    const double y = std::abs(acc) + acc_err;
    const double amp = std::hypot(std::abs(jerk) + jerk_err, omega * y);
    out[n] = std::min((amp + h * f2) / omega, y + h * amp + 0.5 * h * h * f2);
  }
}

// |phi_j''| <= sum_n |w_jn| max|x_n''|.
double BreakScan::accel_bound(int spring, const std::vector<double>& mode_bound) const {
  const double* w = chain_.phi_weights(spring);
  double sum = 0.0;
  for (int n = 0; n < n_; ++n) sum += std::abs(w[n]) * mode_bound[n];
  return sum;
}

void BreakScan::mode_errors(const Probe& p, std::vector<double>& out) const {
  out.clear();
  if (chain_.uniform()) return;
  out.resize(n_);
  for (int n = 0; n < n_; ++n)
    out[n] =
        chain_.mode_error(n, p.tau) * (std::abs(p.x[n]) + std::abs(p.v[n]) / chain_.frequency(n));
}

double BreakScan::spring_error(int spring, const std::vector<double>& mode_error) const {
  if (mode_error.empty()) return 0.0;
  const double* w = chain_.phi_weights(spring);
  double sum = 0.0;
  for (int n = 0; n < n_; ++n) sum += std::abs(w[n]) * mode_error[n];
  return sum;
}

void BreakScan::evaluate(int spring, const Probe& p, double& value, double& rate) const {
  const double* w = chain_.phi_weights(spring);
  double phi = 0.0, phidot = 0.0;
  for (int n = 0; n < n_; ++n) {
    phi += w[n] * p.x[n];
    phidot += w[n] * p.v[n];
  }
  value = phi;
  rate = phidot;
}

FirstBreak BreakScan::first(double c, double limit) {
  assert(c > 0.0);
  const int signs = abs_ ? 2 : 1;
  while (have_interval_ && a_.probe.tau < limit) {
    if (bound_max_ >= c) {
      double best = kNone;
      int spring = -1;
      for (int i = 0; i < n_; ++i)
        for (int k = 0; k < signs; ++k) {
          const double s = k == 0 ? 1.0 : -1.0, ci = c * ratio(i + 1);
          if ((k == 0 ? bound_up_[i] : bound_down_[i]) < ci) continue;
          const double ea = a_.error.empty() ? 0.0 : a_.error[i];
          const double eb = b_.error.empty() ? 0.0 : b_.error[i];
          const double t =
              crossing(i + 1, s, ci, a_.probe, s * a_.phi[i], s * a_.rate[i], ea, b_.probe,
                       s * b_.phi[i], s * b_.rate_before[i], eb, 0, std::min(best, limit));
          if (t < best) {  // strict: a tie goes to the lower spring
            best = t;
            spring = i + 1;
          }
        }
      if (spring > 0 && best <= limit) return {true, spring, best};
    }
    have_interval_ = advance();
  }
  return {};
}

// The first tau in [a, b] with s phi_j >= c, or kNone; values and rates are already times s.
// Requires pa < c (the sweep stopped at the previous crossing).
double BreakScan::crossing(int spring, double s, double c, const Probe& a, double pa, double ma,
                           double ea, const Probe& b, double pb, double mb, double eb, int depth,
                           double limit) {
  if (a.tau >= limit) return kNone;
  if (pa >= c) return a.tau;
  const double h = b.tau - a.tau;
  mode_bounds(a, h, scratch_);
  const double M = accel_bound(spring, scratch_);
  if (interval_upper(pa, pb, ma, mb, h, M, std::max(ea, eb)) < c) return kNone;
  // phi' >= m0 - M (t - a) and phi' >= m1 - M (b - t): either positive throughout => rising.
  if (ma + M * h < 0.0 || mb + M * h < 0.0) return kNone;  // falling: its max is pa < c
  if (ma - M * h > 0.0 || mb - M * h > 0.0 || h < kMinWidth || depth + 1 >= kMaxDepth)
    return pb >= c ? polish(spring, s, c, a.tau, b.tau) : kNone;
  Probe& m = pool_[depth];
  m.tau = 0.5 * (a.tau + b.tau);
  chain_.modal(m.tau, m.x, m.v);
  double pm, mm;
  evaluate(spring, m, pm, mm);
  pm *= s;
  mm *= s;
  mode_errors(m, error_scratch_);
  const double em = spring_error(spring, error_scratch_);
  const double t = crossing(spring, s, c, a, pa, ma, ea, m, pm, mm, em, depth + 1, limit);
  if (t < kNone) return t;
  return crossing(spring, s, c, m, pm, mm, em, b, pb, mb, eb, depth + 1, limit);
}

// s phi_j - c rises through 0 once in [lo, hi]: Newton on the exact phi_j and phi_j',
// falling back to bisection whenever a step would leave the bracket.
double BreakScan::polish(int spring, double s, double c, double lo, double hi) {
  double t = hi;
  for (int it = 0; it < 100 && hi - lo > kTol; ++it) {
    eval_.tau = t;
    chain_.modal(t, eval_.x, eval_.v);
    double value, rate;
    evaluate(spring, eval_, value, rate);
    const double residual = s * value - c, slope = s * rate;
    (residual >= 0.0 ? hi : lo) = t;
    double next = slope > 0.0 ? t - residual / slope : 0.5 * (lo + hi);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (std::abs(next - t) <= kTol) return next;
    t = next;
  }
  return hi;
}

}  // namespace cb::detail
