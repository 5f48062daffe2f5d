#include "exact/chain_modes.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

// Reference LAPACK (liblapack-dev) through its Fortran symbol; gfortran passes the lengths of
// character arguments as trailing hidden size_t arguments.
extern "C" void dstevr_(const char* jobz, const char* range, const int* n, double* d, double* e,
                        const double* vl, const double* vu, const int* il, const int* iu,
                        const double* abstol, int* m, double* w, double* z, const int* ldz,
                        int* isuppz, double* work, const int* lwork, int* iwork, const int* liwork,
                        int* info, std::size_t jobz_len, std::size_t range_len);

namespace cb {

ChainModes chain_modes(const ChainParams& chain, int count) {
  const int n = chain.beads;
  assert(n >= 1 && count >= 1 && count <= n);
  const std::size_t size = static_cast<std::size_t>(n);
  // A = M^{-1/2} K M^{-1/2}: diagonal and the N-1 off-diagonal entries (E(N) is workspace).
  std::vector<double> diag(size), off(size, 0.0), root_mass(size);
  for (int j = 1; j <= n; ++j) {
    assert(chain.mass_of(j) > 0.0 && chain.stiffness_of(j) > 0.0);
    root_mass[j - 1] = std::sqrt(chain.mass_of(j));
  }
  double norm = 0.0;  // ||A||_1 = ||A||_inf (symmetric): the largest absolute row sum
  for (int j = 1; j <= n; ++j) {
    const double right = j < n ? chain.stiffness_of(j + 1) : 0.0;  // K_{N+1} = 0: free end
    diag[j - 1] = (chain.stiffness_of(j) + right) / chain.mass_of(j);
    if (j < n) off[j - 1] = -right / (root_mass[j - 1] * root_mass[j]);
  }
  for (int j = 0; j < n; ++j) {
    const double row = std::abs(diag[j]) + std::abs(off[j]) + (j > 0 ? std::abs(off[j - 1]) : 0.0);
    norm = std::max(norm, row);
  }

  const char jobz = 'V', range = count == n ? 'A' : 'I';
  const double unused = 0.0, abstol = 0.0;  // 0: LAPACK's default tolerance
  const int first = 1, last = count, ldz = n;
  const int lwork = std::max(1, 20 * n), liwork = std::max(1, 10 * n);
  int found = 0, info = 0;
  std::vector<double> w(size), z(size * static_cast<std::size_t>(count)), work(lwork);
  std::vector<int> isuppz(2 * size), iwork(liwork);
  dstevr_(&jobz, &range, &n, diag.data(), off.data(), &unused, &unused, &first, &last, &abstol,
          &found, w.data(), z.data(), &ldz, isuppz.data(), work.data(), &lwork, iwork.data(),
          &liwork, &info, 1, 1);
  if (info != 0 || found != count)
    throw std::runtime_error("LAPACK dstevr failed on the chain's modes (N = " + std::to_string(n) +
                             ", info = " + std::to_string(info) + ")");

  ChainModes modes;
  modes.beads = n;
  modes.count = count;
  modes.omega2.assign(w.begin(), w.begin() + count);
  // Z holds v_n as column n (leading dimension N): the layout of `shape`, so s_n = M^{-1/2} v_n
  // is made in place (no second N x count copy).
  for (int m = 0; m < count; ++m) {
    double* s = &z[static_cast<std::size_t>(m) * size];
    // The sign of an eigenvector is arbitrary and the solution (products s_n[j] s_n[N]) does
    // not depend on it; s_n[N] >= 0 makes the tables the same whatever LAPACK returns.
    const double sign = s[n - 1] < 0.0 ? -1.0 : 1.0;
    for (int j = 0; j < n; ++j) s[j] = sign * s[j] / root_mass[j];
  }
  modes.shape = std::move(z);
  modes.omega2_error =
      4.0 * std::sqrt(static_cast<double>(n)) * std::numeric_limits<double>::epsilon() * norm;
  modes.min_gap = std::numeric_limits<double>::infinity();
  for (int m = 1; m < count; ++m)
    modes.min_gap = std::min(modes.min_gap, modes.omega2[m] - modes.omega2[m - 1]);
  return modes;
}

}  // namespace cb
