// Normal-mode decomposition of a chain state in the sine basis of the paper, Sec. Model:
// k_n = (n + 1/2) pi / (N + 1/2), Omega_n = 2 sin(k_n / 2), n = 0 .. N-1, orthogonal as
// 4/(2N+1) sum_j sin(k_n j) sin(k_m j) = delta_nm.
//
//   a_n  = 4/(2N+1) sum_j psi_j  sin(k_n j)     (the mode's displacement)
//   a_n' = 4/(2N+1) sum_j psi_j' sin(k_n j)     (its velocity)
//   A_n  = sqrt(a_n'^2 + Omega_n^2 a_n^2)       (its amplitude: for a free mode a_n oscillates
//                                                as (A_n / Omega_n) sin(Omega_n tau + const))
//
// A_n^2 measures the mode's energy: for an intact chain, sum_j (psi_j'^2 + phi_j^2) / 2 =
// (2N+1)/8 sum_n A_n^2 exactly (the basis diagonalises Eq. (dimless)'s coupling with
// eigenvalues Omega_n^2). After a break it is still the projection of the state on these
// modes, but they are no longer the broken chain's own.
//
// A chain of unequal beads or springs (issue #21) has its own modes, from LAPACK
// (exact/chain_modes.h): shapes s_n with sum_j m_j s_n[j] s_m[j] = delta_nm, and
//   a_n = sum_j m_j s_n[j] psi_j,  a_n' likewise,  A_n = sqrt(a_n'^2 + Omega_n^2 a_n^2),
// so that sum_j (m_j psi_j'^2 + K_j phi_j^2) / 2 = sum_n A_n^2 / 2 for the intact chain.
#pragma once

#include <vector>

#include "exact/chain_modes.h"
#include "physics/chain.h"

namespace cb {

// Unequal chains longer than this get no mode bars: the lowest modes' shapes take
// 8 N count bytes (32 MB at this N and 16 modes).
inline constexpr int kModeBasisMaxBeads = 1 << 18;

// The chain's own lowest `count` modes: the sine basis (mode_amplitudes below) for the
// uniform chain, LAPACK's for any other.
class ModeBasis {
 public:
  ModeBasis() = default;
  ModeBasis(const ChainParams& chain, int count);
  int count() const { return count_; }
  // A_n for n = 0 .. count-1 into `out` (empty for an unequal chain over kModeBasisMaxBeads).
  void amplitudes(const ChainState& state, std::vector<double>& out) const;

 private:
  int count_ = 0;
  bool uniform_ = true;
  ChainModes modes_;
  std::vector<double> mass_;  // m_j, index j-1
};

// A_n for n = 0 .. count-1 (count <= N) into `out`. O(N count): each sine runs by the
// two-term recurrence sin(k(j+1)) = 2 cos k sin(kj) - sin(k(j-1)), restarted from exact values
// every 1024 beads so that rounding cannot build up at large N.
void mode_amplitudes(const ChainState& state, int count, std::vector<double>& out);

}  // namespace cb
