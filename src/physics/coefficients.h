// The constants of a chain as the kernels read them: arrays indexed by bead or spring, built
// once per Integrator or lane job and shared read-only by every thread, block and lane
// (MuJoCo's mjModel).
//
// Design note: ChainParams says what a chain is (empty arrays for the paper's uniform chain);
// ChainCoefficients says how the stencil computes it. A chain whose masses and stiffnesses are
// all 1 and whose thresholds are all equal takes the Uniform coefficient policy (stencil.inc):
// today's expressions, no arrays, the paper's bits. Any other chain takes the PerBead policy,
// which reads 1/m_j, K_j and K_{j+1} at every bead and each spring's two breaking bounds.
// With unit arrays the PerBead expressions give the Uniform bits too (1 * a == a), which the
// tests use to check one against the other.
//
// Each spring has an upper and a lower bound: it breaks when phi_j >= upper_j or phi_j <=
// lower_j. The paper's |phi_j| >= phi_c,j is (phi_c,j, -phi_c,j); break_on = "stretch" is
// (phi_c,j, -inf). A static load (gravity, issue #22) shifts both bounds of each spring by
// its equilibrium extension, with no change to the kernels (linear springs only; see `weight`).
#pragma once

#include <limits>
#include <vector>

#include "physics/chain.h"

namespace cb {

// Zeros (1/m, K, m) and +-inf (bounds) past bead N, so that a kernel may load whole vectors of
// a partial last block, and K_{N+1} one past it, without masks.
inline constexpr int kCoefficientPad = 16;

// The lower bound of a spring of threshold phi_c: -phi_c (|phi| >= phi_c breaks), or -inf
// when only stretch breaks it; its upper bound is phi_c. The one place the rule is written.
inline double lower_bound_of(double phi_c, bool stretch_only) {
  return stretch_only ? -std::numeric_limits<double>::infinity() : -phi_c;
}

struct ChainCoefficients {
  int beads = 0;
  bool per_bead = false;  // false: the Uniform policy (no arrays)
  // Anharmonic springs (issue #24): the Anharmonic<Uniform or PerBead> policy, whose tension is
  // K_j (phi + a phi^2 + b phi^3) with a = fput_alpha, b = fput_beta.
  bool anharmonic = false;
  double fput_alpha = 0.0, fput_beta = 0.0;
  // Springs can break: the kernels collect candidates (some finite bound).
  bool checks = false;
  // The Uniform policy's rule: |phi_j| >= threshold (phi_j >= threshold when stretch_only).
  double threshold = std::numeric_limits<double>::infinity();
  bool stretch_only = false;
  // PerBead (bead j / spring j at index j - 1, beads + kCoefficientPad values each):
  std::vector<double> inv_mass;   // 1 / m_j
  std::vector<double> mass;       // m_j (friction's power 2 gamma m_j v_j^2)
  std::vector<double> stiffness;  // K_j; K_{N+1} = 0 at index N (the free end)
  std::vector<double> upper;      // spring j breaks at phi_j >= upper[j - 1] ...
  std::vector<double> lower;      // ... or phi_j <= lower[j - 1]
  // A hanging chain (issue #22) is integrated about its equilibrium, u = psi - psi_eq
  // (ChainParams::equilibrium_extensions): Eq. (general) for u is the chain without weight, and
  // spring j's bounds are phi_c,j - phi_eq,j and -phi_c,j - phi_eq,j. What the equilibrium leaves
  // over is a broken spring s's tension K_s phi_eq,s: once s breaks, bead s feels + K_s phi_eq,s
  // (its weight share no longer held) and bead s - 1 feels - K_s phi_eq,s. The tiled kernel adds
  // these loads at the ends of broken springs, which its general stencil already visits; the
  // other kernels run only where no spring is broken. Empty unless the chain hangs; spring j at
  // index j - 1, zeros past N.
  std::vector<double> tension;  // K_j phi_eq,j
  // A hanging chain of anharmonic springs (issue #24 with #22) is NOT integrated about its
  // equilibrium: T(phi_eq + w) - T(phi_eq) is no longer the tension of w, so the weight does not
  // cancel and a broken spring's leftover load is not a constant. Two designs were weighed:
  //   (A) per-spring coefficients about the equilibrium, K'_j = K_j T'(phi_eq,j), a'_j = a +
  //       3 b phi_eq,j, b'_j = b: the Anharmonic policy would read a and b per spring (left and
  //       right separately), so ChainCoefficients, BeadCoef and every kernel family (tile,
  //       wavefront, window, lanes) would load two more arrays, and the broken-spring loads
  //       would stay;
  //   (B) the chain in psi itself, starting at psi_eq at rest, with its weight as a force: m_j G
  //       is the acceleration G at every bead, one scalar like a and b, added by the Weighted
  //       policy (stencil.inc) in the tiled kernel only.
  // (B) is taken: no arrays, one policy of two lines, one more instantiation of the tiled kernel;
  // the bounds are the springs' own (no shift), a broken spring leaves nothing behind (its beads
  // simply lose it, and a loose piece falls at G), and the state is already psi. The Integrator
  // sends such a chain to the tiled kernel on every instruction set (no wavefront, no window
  // kernel). Harmonic hanging chains keep the equilibrium frame and its bits.
  // weight: G for such a chain (then per_bead, anharmonic, tension empty), else 0.
  double weight = 0.0;

  double mass_of(int bead) const { return per_bead ? mass[bead - 1] : 1.0; }                // 1..N
  double stiffness_of(int spring) const { return per_bead ? stiffness[spring - 1] : 1.0; }  // 1..N
  // Spring 1..N's bounds; also for a Uniform chain.
  double upper_of(int spring) const { return per_bead ? upper[spring - 1] : threshold; }
  double lower_of(int spring) const {
    if (per_bead) return lower[spring - 1];
    return lower_bound_of(threshold, stretch_only);
  }
  // Integrated about the hanging equilibrium (a harmonic hanging chain): u = psi - psi_eq.
  bool hanging() const { return !tension.empty(); }
  // A hanging anharmonic chain, integrated in psi with its weight (the Weighted policy).
  bool weighted() const { return weight > 0.0; }
  // The constant load on bead i (0-based) from the broken springs among `broken` (sorted, 1..N)
  // at its two ends; 0 unless the chain hangs.
  double broken_load(int bead, const std::vector<int>& broken) const;
  // The smallest |bound| of any spring: no spring breaks while every |phi_j| stays below it
  // (a lane's test whether any spring may cross, before the springs are tested one by one).
  double nearest_bound() const;
};

// The coefficients of `params`. per_bead_always: the PerBead policy even for a uniform chain
// (its arrays of ones then give the Uniform bits; tests compare the two).
// anharmonic_always: the Anharmonic policy even for a = b = 0 (which then gives the harmonic
// bits; tests compare the two).
ChainCoefficients chain_coefficients(const ChainParams& params, bool per_bead_always = false,
                                     bool anharmonic_always = false);

}  // namespace cb
