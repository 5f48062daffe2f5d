// The external force on bead N as the integrator sees it: a plain function plus the
// times where the step must be split. Built by src/drive from a DriveDesc; the physics
// core knows nothing of how (muParser, CSV tables).
#pragma once

#include <bit>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

namespace cb {

struct Kick {
  double tau = 0.0;       // bead N's velocity jumps by `strength` at exactly this time
  double strength = 1.0;  // a delta impulse of that weight, Eq. (dimless) with f = s delta
};

struct Forcing {
  // f(tau), right-continuous at jumps. Zero when empty.
  std::function<double(double)> f;
  // Jumps and kinks of f, sorted: an RK4 step that straddles one is split there so that
  // the fourth-order accuracy survives a step drive starting between grid points.
  std::vector<double> breakpoints;
  std::vector<Kick> kicks;  // sorted by tau

  double operator()(double tau) const { return f ? f(tau) : 0.0; }

  // f at many times: f_many when set (make_forcing sets it for the closed-form drives: one call
  // where the ensemble lanes made one per value, a twentieth of a sweep's time), f one by one
  // otherwise. The same values as f, as f_many computes each one as f does.
  std::function<void(const double* tau, double* out, std::size_t count)> f_many;
  void values(const double* tau, double* out, std::size_t count) const {
    if (f_many) return f_many(tau, out, count);
    for (std::size_t i = 0; i < count; ++i) out[i] = (*this)(tau[i]);
  }

  // Whether the step [t0, t1] is one plain interval: no breakpoint in (t0 + snap, t1 + 2 snap]
  // (none cuts it, its end is not one, with a margin for the rounding of |b - t1| <= snap) and
  // no kick left before t1 - snap (none is due at t0, none cuts it). `next_breakpoint` is a
  // cursor into the sorted breakpoints that only moves forward with the clock; `next_kick` the
  // first kick not yet applied. Integrator::step and the ensemble lanes (lanes.cpp) both ask.
  bool plain_step(std::size_t& next_breakpoint, std::size_t next_kick, double t0, double t1,
                  double snap) const {
    pass_breakpoints(next_breakpoint, t0, snap);
    const bool no_breakpoint =
        next_breakpoint == breakpoints.size() || breakpoints[next_breakpoint] > t1 + 2.0 * snap;
    const bool no_kick = next_kick == kicks.size() || kicks[next_kick].tau >= t1 - snap;
    return no_breakpoint && no_kick;
  }
  // The cursor moved past the breakpoints at or before t0 (+ snap).
  void pass_breakpoints(std::size_t& next_breakpoint, double t0, double snap) const {
    while (next_breakpoint < breakpoints.size() && breakpoints[next_breakpoint] <= t0 + snap)
      ++next_breakpoint;
  }
  // Whether every step from t0 on is plain: no breakpoint after t0 (+ snap), no kick left.
  bool plain_from(std::size_t next_breakpoint, std::size_t next_kick, double t0,
                  double snap) const {
    pass_breakpoints(next_breakpoint, t0, snap);
    return next_breakpoint == breakpoints.size() && next_kick == kicks.size();
  }
};

// The drive's last value: a step's end is the next step's start, so a step asks for two new
// values instead of three (f is a function of tau alone).
class DriveCache {
 public:
  double operator()(const Forcing& forcing, double tau) {
    const std::uint64_t bits = std::bit_cast<std::uint64_t>(tau);
    if (bits != tau_) {
      value_ = forcing(tau);
      tau_ = bits;
    }
    return value_;
  }
  // What the cache would hold after asking for tau: `value` = forcing(tau), found elsewhere.
  void remember(double tau, double value) {
    tau_ = std::bit_cast<std::uint64_t>(tau);
    value_ = value;
  }

 private:
  std::uint64_t tau_ = 0x7ff8dead00000000ull;  // a NaN: no tau equals it
  double value_ = 0.0;
};

}  // namespace cb
