// The data behind the two maps of which part breaks: first breaks by the exact solution and by
// RK4 over a range of a parameter, and where the first-breaking spring switches between the
// pulled one (N) and the others.
#pragma once

#include <atomic>
#include <functional>
#include <vector>

#include "drive/drive.h"
#include "exact/first_break.h"
#include "physics/chain.h"

namespace cb {

// The first break found by RK4 with breaking (cb::Integrator, step dt), stopping there; none
// before t_end (or before *stop became true): broke = false. Throws std::runtime_error when the
// state stops being finite.
FirstBreak simulated_first_break(const ChainParams& chain, const DriveDesc& drive, double t_end,
                                 double dt, const std::atomic<bool>* stop = nullptr);

// fn(0) .. fn(count - 1) on `jobs` threads (0: all cores); results in index order.
std::vector<FirstBreak> parallel_first_breaks(int count, int jobs,
                                              const std::function<FirstBreak(int)>& fn);

// A switch of the ramp's breaking map (Eq. (rescale2), unit ramp, threshold zeta_c) between
// spring N breaking first and another spring breaking first, located by bisection on the
// exact first break to `tolerance` in zeta_c. Each sample is an exact solve (~2 ms at N = 30):
// when `stop` is set and becomes true, the search returns the switches found so far.
struct MapBoundary {
  double zeta = 0;
  int below = 0, above = 0;  // the first-breaking spring just below and just above zeta
};
std::vector<MapBoundary> spring_n_boundaries(int beads, double gamma, double zeta_lo,
                                             double zeta_hi, int samples, double tolerance = 1e-9,
                                             const std::atomic<bool>* stop = nullptr);

// The exact first break of the unit ramp with threshold zeta_c (Eq. (rescale2)); the search
// runs to 4 zeta_c + 8 N, past the time phi_N alone would reach the threshold.
FirstBreak ramp_first_break(int beads, double gamma, double zeta_c);

// The continuum prediction of Eq. (phij) for the unit ramp at gamma = 0: spring N breaks
// first when zeta_c lies in (4m N, (4m + 2) N); otherwise springs 1 .. last_spring break
// together, last_spring = (2m + 2) N - zeta_c / 2 for zeta_c in ((4m + 2) N, (4m + 4) N).
struct ContinuumBreak {
  bool pulled_end = true;  // spring N
  double last_spring = 0;  // else springs 1 .. last_spring (not an integer in general)
};
ContinuumBreak continuum_ramp_break(int beads, double zeta_c);

}  // namespace cb
