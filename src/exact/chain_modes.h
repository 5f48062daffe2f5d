// The normal modes of a general linear chain (issue #21):
//   M psi'' = -K psi,  M = diag(m_j),  K tridiagonal with K_jj = K_j + K_{j+1} (K_{N+1} = 0)
//   and K_{j,j+1} = -K_{j+1}.
// With u = M^{1/2} psi the problem is the symmetric tridiagonal eigenproblem
//   A v_n = Omega_n^2 v_n,   A = M^{-1/2} K M^{-1/2},
//   A_jj = (K_j + K_{j+1}) / m_j,   A_{j,j+1} = -K_{j+1} / sqrt(m_j m_{j+1}),
// and the mode shapes in psi are s_n = M^{-1/2} v_n, orthonormal in the mass inner product
// (sum_j m_j s_n[j] s_m[j] = delta_nm). A force f on bead N drives mode n as
// y_n'' + 2 gamma y_n' + Omega_n^2 y_n = s_n[N] f (the Nth component of v_n over sqrt(m_N)),
// and psi_j = sum_n s_n[j] y_n. Friction proportional to mass keeps the modes uncoupled.
//
// Design note: LAPACK's dstevr (MRRR, reference LAPACK 3.11 via its Fortran symbol) solves the
// eigenproblem in O(N^2) with eigenvectors: 0.06 s at N = 1000 (../shared/PLATFORM-NOTES.md).
// Its eigenvalues are accurate to p(N) eps ||A|| absolutely, not relatively: the lowest mode,
// Omega_0^2 ~ (pi / 2N)^2 min(K/m), carries a relative error up to ~ eps ||A|| / Omega_0^2
// (2.5e-10 measured at N = 1000 on the uniform chain). dpteqr (relative accuracy, 7.3e-13) costs
// 20x more at N = 1000 and 65x at N = 4000. The slow part of a ramp's response is dominated by
// the lowest modes, so that relative error is what the solution carries: 1e-10 to 1e-9 for the
// chains this program runs exactly (N <= a few thousand), far below the 1e-7 at which RK4 is
// compared and far below anything a picture or a breaking map can show. dstevr is therefore
// the choice; ChainModes::omega2_error states the bound that the first-break search widens
// its allowance by.
#pragma once

#include <vector>

#include "physics/chain.h"

namespace cb {

struct ChainModes {
  int beads = 0;
  int count = 0;               // modes computed: the lowest `count`
  std::vector<double> omega2;  // Omega_n^2, ascending
  std::vector<double> shape;   // s_n[j-1] = v_n[j] / sqrt(m_j): row n, `beads` entries
  // Bound on |computed - true Omega_n^2| for every n: p(N) eps ||A||_1 with p(N) = 4 N^{1/2}
  // (LAPACK's working bound for MRRR is O(N eps ||A||); measured errors are ~eps ||A||).
  double omega2_error = 0.0;
  // The smallest distance between two computed Omega_n^2 (infinity for one mode): the
  // eigenvectors are accurate to ~ omega2_error / gap in angle.
  double min_gap = 0.0;

  const double* mode(int n) const { return &shape[static_cast<std::size_t>(n) * beads]; }
};

// The lowest `count` (1..N) modes of the chain's masses and stiffnesses (the arrays of
// ChainParams; empty arrays are ones). Throws std::runtime_error if LAPACK reports a failure.
ChainModes chain_modes(const ChainParams& chain, int count);

}  // namespace cb
