// The external force on bead N as the integrator sees it: a plain function plus the
// times where the step must be split. Built by src/drive from a DriveDesc; the physics
// core knows nothing of how (muParser, CSV tables).
#pragma once

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
};

}  // namespace cb
