// First breaks of an ensemble of chains that differ only in their thresholds (issue #23: flawed
// chains by seed), from one RK4 run.
//
// Design note: before its first break a chain's trajectory does not depend on its thresholds;
// they only decide when a spring is tested (the crossing bound) and whether it crosses (the
// Hermite rule). So one run that never breaks hands every interval it integrates, the state at
// both ends (Integrator::tap_intervals), to the members' tests, which take them in windows: per
// window each spring's reach (stencil.inc's bound) and its running largest; a member near a
// bound, some spring's largest reach at or above its phi_c,j, is then tested interval by
// interval from the first where a reach gets there, as `run` would test it: the same bound with
// its own thresholds, the same earliest-crossing search (crossing.h). Each member's spring, tau
// and step are then Integrator's on that member alone, bit for bit
// (tests/test_threshold_ensemble.cpp). The exact solver shares one run across thresholds the
// same way (exact/first_break.cpp).
// Which members are near is asked of 15-bit levels of their thresholds (monotone in them, one cache
// line a member), and only of those that have joined the tests: a member joins once, in some group
// of 8 springs, its lowest level is passed by the group's highest reach's (the members in order of
// it, per group). A window so costs its near members, not all 10^4. A window is open() / 4
// intervals, so the passes cost a fraction of the run and the run ends within a few steps of the
// last member's break. A member settles as soon as it is known to cross; its crossing time is
// bisected later with 255 others (crossing.h, finish_hermite_roots: 64 at a time on AVX-512).
// Members drawn by seed (`drawn`: a sweep's Weibull seeds) are not drawn beforehand: their levels
// are those of their u (threshold_levels.h: the hash's top bits, monotone in the draw), and a
// threshold is drawn only when a member's level flags its spring as near, ~1 of a member's 30 at
// beta = 0.02, in lanes, kept in a few slots a member. 10^4 seeds of a 30-bead chain, drawn so,
// draws included, cost 1.26 x one run for a slow pull (beta = 0.001), 4.1 x at beta = 0.02 and
// 71 x for a jerk on one thread; 1.2, 2.8 and 32 x on two (each seed's own bit-exact crossing
// time; handed the drawn thresholds instead: 1.18, 3.4 and 61 x, the draws' 2.8 x at beta =
// 0.02 not counted; tests/bench/README.md, sessions 31, 32, 36 and 37).
#pragma once

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "physics/chain.h"
#include "physics/forcing.h"
#include "physics/lanes.h"  // LaneEnd

namespace cb {

struct ThresholdEnsemble {
  ChainParams chain;  // what every member shares; its thresholds are ignored
  Forcing forcing;
  double dt = 0.01;
  std::int64_t last_step = 0;  // stop after this step (t_end on the step grid)
  // phi_c,j of member m, spring j (1..N), at index m N + j - 1 (ChainParams::threshold_of); the
  // caller's, read in place (a sweep's 10^4 seeds are 2.4 MB: a copy cost a tenth of the run).
  std::span<const double> thresholds;
  // Or, where `thresholds` is empty, member m's drawn by seed: phi_c,j = scale x Weibull(shape)
  // of u(seeds[m], j), draw_threshold_rows' bits (threshold_draw.h), each drawn only when a
  // test needs it (the scale and shape must pass weibull_draws_positive_finite).
  struct WeibullSeeds {
    double scale = 1.0, shape = 1.0;
    std::span<const std::uint64_t> seeds;
    // How many drawn thresholds a member keeps in place (at most 8) before it moves them to a
    // row of N of its own: ~1 is drawn a member at beta = 0.02 (tests set fewer, to move more).
    std::size_t slots = 4;
  } drawn;

  std::size_t members() const;
};

// Whether `a` and `b` differ at most in their thresholds, and an ensemble can run them: no pull
// string (its threshold is the chain's scale, which the members do not share), every threshold
// above zero.
bool ensemble_can_share(const ChainParams& a, const ChainParams& b);
bool ensemble_can_run(const ChainParams& member);
// The same for `chain` with thresholds phi_c,j = thresholds[j - 1] (j = 1..N) instead of its own.
bool ensemble_can_run(const ChainParams& chain, const double* thresholds);

// Each member's first break (LaneEnd::Broke), none by last_step (Reached), or Failed when the
// shared state stopped being finite before it broke (rerun it alone for Integrator's message).
// When *stop becomes true the members not yet settled are returned as Reached: the caller checks
// `stop`.
//
// With workers > 1 the members are shared out in contiguous parts (at least
// kEnsembleMembersPerWorker each), one thread a part, each with its own run of the shared chain:
// the runs are the same run, so each member's end is the same bits however many parts there are;
// a sweep over one beta then keeps every core busy (the members' tests cost several runs).
inline constexpr std::size_t kEnsembleMembersPerWorker = 1024;
std::vector<LaneEnd> ensemble_first_breaks(const ThresholdEnsemble& ensemble,
                                           const std::atomic<bool>* stop = nullptr,
                                           int workers = 1);

}  // namespace cb
