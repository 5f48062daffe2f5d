// The exact first break of an unbroken chain: which spring first reaches the threshold and
// when, by root finding on the exact solution. The scan cannot miss a crossing inside a
// scan interval: it bounds each phi_j between samples by its Hermite cubic plus a bound on
// the interpolation error, and refines every interval that might reach the threshold.
#pragma once

#include <atomic>
#include <vector>

#include "drive/drive.h"
#include "physics/chain.h"

namespace cb {

struct FirstBreak {
  bool broke = false;
  int spring = -1;  // 1..N, 0 = the pull string
  double tau = 0.0;
};

// Drives of every type but Expr. t_end bounds the search. Any linear chain (chain.mass,
// chain.stiffness) with per-spring thresholds phi_c,j (chain.threshold_of); the pull string
// breaks at chain.threshold.
FirstBreak exact_first_break(const ChainParams& chain, const DriveDesc& drive, double t_end);

// The breaking map of Fig. 4(c): first-breaking spring against zeta_c = phi_c / beta for a
// ramp, one entry per zeta value. Once *stop is true the remaining entries stay "no break"
// (an interrupted `figures` throws the map away).
std::vector<FirstBreak> breaking_map(int beads, double gamma, BreakMode mode,
                                     const std::vector<double>& zeta_c, double t_end,
                                     const std::atomic<bool>* stop = nullptr);
// The same for any linear chain (masses, stiffnesses, gamma, break_on of `chain`): zeta_c is
// min_j phi_c,j / beta, and every threshold scales with it (phi_c,j / min_j phi_c,j fixed).
// chain.threshold and the pull string play no part.
std::vector<FirstBreak> breaking_map(const ChainParams& chain, const std::vector<double>& zeta_c,
                                     double t_end, const std::atomic<bool>* stop = nullptr);

// One body, two strings (N = 1 with the pull string, ramp beta tau, phi_c = 1): the lower
// string breaks first exactly when sin(1/beta) > 0, i.e. beta in (1/((2m+1) pi), 1/(2 m pi)).
// Returns the first `count` windows [lo, hi] of beta, m = 0, 1, ... (m = 0: hi = infinity).
struct BetaWindow {
  double lo, hi;
};
std::vector<BetaWindow> one_body_jerk_windows(int count);

}  // namespace cb
