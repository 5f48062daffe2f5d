// The sweep behind exact_first_break and breaking_map: walks the exact solution forward in
// time and finds the first tau at which some spring reaches a threshold.
//
// Design note: a crossing must not hide between samples. On each interval [a, b] (never
// straddling a kick, a jump or a kink of f) every phi_j is bounded by
//   phi_j(t) <= min(phi(a) + phi'(a)(t-a) + M (t-a)^2/2,  phi(b) - phi'(b)(b-t) + M (b-t)^2/2),
// where M >= |phi_j''| on [a, b] comes from the modal sum |phi_j''| <= sum_n |w_jn| max|x_n''|.
// max|x_n''| is bounded through the energy of y = x_n'' (which obeys the mode equation with
// force f''): sqrt(y'^2 + Omega^2 y^2) grows by at most int |f''|, for any gamma >= 0.
// Intervals whose bound reaches the threshold are halved until phi_j is provably monotone
// there, and the crossing is then polished by safeguarded Newton on the exact phi_j.
//
// Per-spring thresholds phi_c,j = c r_j (r_j fixed per scan, c per query): the first-crossing
// time of max_j phi_j / r_j is non-decreasing in c, so successive queries with non-decreasing c
// share one sweep: breaking_map costs one trajectory.
//
// Allowance: the bound adds 1e-12 (|phi(a)| + |phi(b)|) for the samples' own rounding and, for
// a chain whose modes come from LAPACK, e_j = sum_n |w_jn| rho_n (|x_n| + |x_n'| / Omega_n) at
// the larger of the two ends, where rho_n is ExactChain::mode_error: the eigen-solver's error
// carried into phi_j. So every interval where the true chain (not only the computed one) might
// reach the threshold is examined down to monotone pieces; the crossing located is that of the
// computed solution, which is off by at most e_j / |phi_j'| in time.
#pragma once

#include <vector>

#include "exact/exact_chain.h"
#include "exact/first_break.h"
#include "physics/chain.h"

namespace cb::detail {

class BreakScan {
 public:
  // step: the sampling interval of the sweep (shortened at breakpoints and at t_end).
  // ratio: r_j of spring j at index j-1 (all > 0), or empty for r_j = 1.
  BreakScan(const ExactChain& chain, BreakMode mode, double t_end, double step,
            std::vector<double> ratio = {});

  // The first tau <= limit at which a spring j reaches c r_j, c > 0. c must not decrease
  // from one call to the next.
  FirstBreak first(double c, double limit);

 private:
  struct Probe {  // modal state just after tau
    double tau = 0.0;
    std::vector<double> x, v;
  };
  struct Node {  // a sample of the sweep
    Probe probe;
    std::vector<double> phi, rate, rate_before;  // rate_before: left limit at a kick
    std::vector<double> error;                   // e_j (empty for closed-form modes)
  };

  void sample(double tau, Node& node) const;
  bool advance();  // moves to the next interval; false after t_end
  void mode_bounds(const Probe& a, double h, std::vector<double>& out) const;
  double accel_bound(int spring, const std::vector<double>& mode_bound) const;
  double crossing(int spring, double sign, double c, const Probe& a, double pa, double ma,
                  double ea, const Probe& b, double pb, double mb, double eb, int depth,
                  double limit);
  double polish(int spring, double sign, double c, double lo, double hi);
  void evaluate(int spring, const Probe& p, double& value, double& rate) const;
  // rho_n (|x_n| + |x_n'| / Omega_n) into out (empty for closed-form modes); e_j from it.
  void mode_errors(const Probe& p, std::vector<double>& out) const;
  double spring_error(int spring, const std::vector<double>& mode_error) const;
  double ratio(int spring) const { return ratio_.empty() ? 1.0 : ratio_[spring - 1]; }

  const ExactChain& chain_;
  const int n_;
  const bool abs_;
  const double t_end_, step_;
  const std::vector<double> ratio_;
  std::vector<double> breakpoints_;
  std::size_t next_break_ = 0;
  Node a_, b_;
  bool have_interval_ = false;
  std::vector<double> bound_up_, bound_down_;  // per spring: bounds of phi_j and -phi_j
  double bound_max_ = 0.0;                     // max_j of the bounds over r_j
  std::vector<Probe> pool_;                    // one midpoint probe per refinement depth
  std::vector<double> scratch_, error_scratch_;
  Probe eval_;
};

}  // namespace cb::detail
