// Internal: a proof, before a run of plain steps of the lanes kernel, that a lane stays far from
// its breaking bounds and finite for the run's steps but its last, so that the kernel may skip
// the bounds of its new states there (lanes_interval.h's `far`): the bounds pass was 13 % of
// the AVX2 kernel (tests/bench/README.md, session 16).
//
// Design note: for the harmonic chain one RK4 step bounds the largest spring extension P and
// rate M of its new state by a linear map of those of its start and of the force's size F. With
// phi_j = psi_j - psi_{j-1} and mu_j its rate, the difference of two neighbours' accelerations
// (Eq. (general), the wall at rest) is at most
//     A(P, M, F) = cP P + 2 gamma M + cF F,  cP = 2 max_j (K_j + K_{j+1}) / m_j,  cF = 1 / m_N,
// (4 P + 2 gamma M + F for the paper's chain), so stage by stage (Y2 = Y0 + h/2 K1, ...):
//     P1 = P + h/2 M,   M1 = M + h/2 A(P, M),     P2 = P + h/2 M1,  M2 = M + h/2 A(P1, M1),
//     P3 = P + h M2,    M3 = M + h A(P2, M2),
//     P' = P + h/6 (M + 2 M1 + 2 M2 + M3),        M' = M + h/6 (A + 2 A1 + 2 A2 + A3),
// a map (P', M') <= T (P, M) + b F with nonnegative T and b. To it are added, per step, twice a
// bound on the rounding of the kernel's own arithmetic (each value of a step is a few dozen
// roundings of numbers no larger than 16 (N + 1) (1 + cP + 2 gamma + cF) (P + M + F) while
// h (cP + 2 gamma + cF) <= 1; the bound taken is 10^-9 times that, 10^4 times the worst case),
// and a relative 10^-10 for the map's own rounding. r steps then give T^r (P0, M0) + c_r F with
// F the largest |f| of the run; every bound grows with the step, so the state after the run's
// second last step bounds all the earlier ones. If its P + (4/27) h 2 M stays below the lane's
// nearest bound, the lanes kernel's own test (bound_reaches) would have found no step of the
// run but the last near, and no value not finite: skipping it changes no bit, only work.
// The proven bounds stand in for the skipped ones (larger, so every later test stays safe).
#pragma once

#include <array>

#include "physics/coefficients.h"

namespace cb::detail {

// The most steps a proof covers (the lanes driver's longest run, less its last step).
inline constexpr int kMaxFarSteps = 15;

// One lane job's map, built once when a lane takes the job.
class FarMap {
 public:
  FarMap() = default;
  // No proof (every run tests its bounds) when the map's premises fail: a step larger than
  // 1 / (cP + 2 gamma + cF), or an anharmonic or weighted chain (not a linear map).
  FarMap(const ChainCoefficients& c, double gamma, double dt);
  // Bounds on P and M after `steps` (1 .. kMaxFarSteps) steps of length <= step_bound() from a
  // state of bounds p0, m0, with |f| <= f_max all along. +inf when there is no proof.
  struct Bounds {
    double p, m;
  };
  Bounds after(int steps, double p0, double m0, double f_max) const;
  double step_bound() const { return h_; }  // every step of a proven run must be <= this

 private:
  bool valid_ = false;
  double h_ = 0.0;
  // power_[r - 1]: T^r, row-major; force_[r - 1]: c_r (both inflated for rounding).
  std::array<std::array<double, 4>, kMaxFarSteps> power_{};
  std::array<std::array<double, 2>, kMaxFarSteps> force_{};
};

// max_i |v_i| of n values (the run's drive: FarMap::after's f_max), NaN if any is NaN (which
// std::max would pass over, and a NaN force makes no state finite).
double largest_magnitude(const double* v, int n);

// Whether bounds p, m (FarMap::after) keep a lane's steps of length <= h from its nearest
// bound `threshold` by the kernel's own test, and keep every value finite.
bool proven_far(FarMap::Bounds b, double h, double threshold);

}  // namespace cb::detail
