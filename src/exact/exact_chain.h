// The exact discrete solution of the unbroken chain, Eqs. (exactpsi), (exactgreen),
// (exactconv), by normal modes: k_n = (n + 1/2) pi / (N + 1/2), Omega_n = 2 sin(k_n / 2),
// psi_j(tau) = sum_n c_n sin(k_n j) x_n(tau) with c_n = 4/(2N+1) sin(k_n N) and
// x_n'' + 2 gamma x_n' + Omega_n^2 x_n = f(tau), x_n(0) = x_n'(0) = 0.
// x_n has closed forms for step, ramp, sine, impulses and tables (piecewise-linear =
// a sum of ramps), for under-, critically and over-damped modes; an Expr drive is
// convolved numerically with the modal Green's function.
//
// A general linear chain (unequal masses m_j and stiffnesses K_j, issue #21) has the same
// modal form with the modes of M^{-1/2} K M^{-1/2} from LAPACK (chain_modes.h) in place of the
// sines: Omega_n^2 its eigenvalues, psi_j = sum_n s_n[j] s_n[N] x_n with s_n = M^{-1/2} v_n,
// and the same closed-form x_n. The uniform chain keeps its closed-form modes (and its bits).
//
// Cost: the constructor tabulates c_n sin(k_n j) and the spring weights, 16 N^2 bytes (an
// unequal chain's also runs LAPACK: 0.3 s at N = 1000, 6 s at N = 4000 on a loaded 2-core machine);
// a whole-chain call is O(N^2) with each x_n evaluated once; a one-bead call is O(N).
// An Expr drive costs O(N (tau - t0) / 0.25) per call and is accurate to ~1e-12 relative when
// f is smooth on the scale of one time unit (8-point Gauss-Legendre on panels <= 0.25).
// Not thread-safe for Expr drives (the muParser evaluator holds state); otherwise const
// calls may run concurrently.
#pragma once

#include <vector>

#include "drive/drive.h"
#include "exact/drive_terms.h"
#include "exact/oscillator.h"
#include "physics/chain.h"

namespace cb {

class ExactChain {
 public:
  // The paper's uniform chain of `beads` beads.
  ExactChain(int beads, double gamma, DriveDesc drive);
  // Any linear chain: closed-form modes when chain.uniform_dynamics(), LAPACK's otherwise.
  // Thresholds and breaking play no part (the unbroken chain).
  ExactChain(const ChainParams& chain, DriveDesc drive);

  int beads() const { return n_; }
  double gamma() const { return gamma_; }
  bool uniform() const { return uniform_; }
  double wavenumber(int n) const;  // k_n (the uniform chain only)
  double frequency(int n) const;   // Omega_n

  // First-order estimate of |computed - true| for mode n's contribution to any bead or spring,
  // relative to |weight| (|x_n| + |x_n'| / Omega_n) at time tau: 0 for the closed-form modes.
  // From chain_modes.h's eigenvalue error e: x_n's static part ~ f / Omega_n^2 is off by
  // e / Omega_n^2 relatively, its phase by e tau / (2 Omega_n), the weights by ~ e / gap (the
  // eigenvectors' angle); the modal sums add N eps of rounding.
  double mode_error(int n, double tau) const;

  // Whole-chain values at tau, index j-1 (phi: spring j).
  void psi(double tau, std::vector<double>& out) const;
  void velocity(double tau, std::vector<double>& out) const;
  void phi(double tau, std::vector<double>& out) const;
  void phi_rate(double tau, std::vector<double>& out) const;  // d phi_j / d tau
  // Any of the four at once (null: not wanted), from one evaluation of the modes.
  void evaluate(double tau, std::vector<double>* psi, std::vector<double>* velocity,
                std::vector<double>* phi, std::vector<double>* phi_rate) const;

  double psi(int bead, double tau) const;
  double phi(int spring, double tau) const;
  // Eq. (exactgreen): G_j(tau) = d psi_j / d tau for a unit step = response to delta(tau).
  double green(int bead, double tau) const;

  // Modal amplitudes x_n(tau) and x_n'(tau) of the drive.
  void modal(double tau, std::vector<double>& x, std::vector<double>& xdot) const;

  // For the first-break scan. modal_before: the left limit at tau, i.e. a kick landing
  // exactly at tau not yet applied (x is continuous, x' jumps).
  void modal_before(double tau, std::vector<double>& x, std::vector<double>& xdot) const;
  // phi_j = sum_n w[n] x_n with w[n] = c_n 2 cos(k_n (j - 1/2)) sin(k_n / 2); N entries.
  const double* phi_weights(int spring) const {
    return &phi_w_[static_cast<std::size_t>(spring - 1) * n_];
  }
  const detail::DriveTerms& drive_terms() const { return terms_; }

 private:
  void modal_impl(double tau, bool kicks_at_tau, std::vector<double>& x,
                  std::vector<double>& xdot) const;
  void modal_expr(double tau, std::vector<double>& x, std::vector<double>& xdot) const;

  void init_uniform();
  void init_general(const ChainParams& chain);

  int n_;
  double gamma_;
  bool uniform_ = true;
  double omega2_error_ = 0.0, weight_error_ = 0.0;  // general chains: chain_modes' bounds
  std::vector<double> k_, omega_, c_;
  std::vector<detail::Oscillator> modes_;
  detail::DriveTerms terms_;
  std::vector<double> psi_w_;  // c_n sin(k_n j), row j-1
  std::vector<double> phi_w_;  // c_n 2 cos(k_n (j - 1/2)) sin(k_n / 2), row j-1
};

}  // namespace cb
