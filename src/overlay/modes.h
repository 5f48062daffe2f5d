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
#pragma once

#include <vector>

#include "physics/chain.h"

namespace cb {

// A_n for n = 0 .. count-1 (count <= N) into `out`. O(N count): each sine runs by the
// two-term recurrence sin(k(j+1)) = 2 cos k sin(kj) - sin(k(j-1)), restarted from exact values
// every 1024 beads so that rounding cannot build up at large N.
void mode_amplitudes(const ChainState& state, int count, std::vector<double>& out);

}  // namespace cb
