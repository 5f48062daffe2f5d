// The drive f(tau) as the exact solution sees it: the chain is at rest at tau = 0, so only
// f on tau >= 0 matters, written as a sum of terms whose modal responses have closed forms.
//
// Design note: step, ramp and table drives are all piecewise linear, so each is a list of
// kinks "jump u(tau - tau_k) + slope (tau - tau_k) u(tau - tau_k)" and its response is a sum
// of step and ramp responses: exact, with no quadrature. A drive that started before
// tau = 0 (t0 < 0) enters as its value and slope at tau = 0. Kicks before tau = 0 are
// ignored, like the integrator, which starts at tau = 0.
#pragma once

#include <vector>

#include "drive/drive.h"

namespace cb::detail {

struct Kink {
  double tau = 0.0;
  double jump = 0.0;   // f jumps by this at tau
  double slope = 0.0;  // and its slope changes by this
};

// f += amplitude sin(nu (tau - start) + phase) for tau >= start.
struct SineTerm {
  double start = 0.0;
  double amplitude = 0.0;
  double nu = 0.0;
  double phase = 0.0;
};

struct DriveTerms {
  std::vector<Kink> kinks;  // sorted by tau, all >= 0
  bool has_sine = false;
  SineTerm sine;
  std::vector<Kick> kicks;  // sorted by tau, all >= 0
  bool is_expr = false;     // no closed form: expr is convolved numerically from expr_start
  Forcing expr;
  double expr_start = 0.0;

  // For closed-form drives: f just after tau, its slope there, and a bound on |f''|
  // between breakpoints (zero for piecewise-linear drives).
  double value(double tau) const;
  double slope(double tau) const;
  double curvature_bound() const;
  // Times where f jumps or kinks, the sine or expression starts, or a kick lands; sorted.
  std::vector<double> breakpoints() const;
  // The first tau >= 0 with f(tau) >= c > 0 (the pull string breaks), infinity if none.
  double first_time_at_least(double c) const;
};

DriveTerms decompose_drive(const DriveDesc& drive);

}  // namespace cb::detail
