// The exact discrete solution of the unbroken chain, Eqs. (exactpsi), (exactgreen),
// (exactconv), by normal modes: k_n = (n + 1/2) pi / (N + 1/2), Omega_n = 2 sin(k_n / 2),
// psi_j(tau) = sum_n c_n sin(k_n j) x_n(tau) with c_n = 4/(2N+1) sin(k_n N) and
// x_n'' + 2 gamma x_n' + Omega_n^2 x_n = f(tau), x_n(0) = x_n'(0) = 0.
// x_n has closed forms for step, ramp, sine, impulses and tables (piecewise-linear =
// a sum of ramps), for under-, critically and over-damped modes; an Expr drive is
// convolved numerically with the modal Green's function.
#pragma once

#include <vector>

#include "drive/drive.h"

namespace cb {

class ExactChain {
 public:
  ExactChain(int beads, double gamma, DriveDesc drive);

  int beads() const { return n_; }
  double gamma() const { return gamma_; }
  double wavenumber(int n) const;  // k_n
  double frequency(int n) const;   // Omega_n

  // Whole-chain values at tau, index j-1 (phi: spring j).
  void psi(double tau, std::vector<double>& out) const;
  void velocity(double tau, std::vector<double>& out) const;
  void phi(double tau, std::vector<double>& out) const;
  void phi_rate(double tau, std::vector<double>& out) const;  // d phi_j / d tau

  double psi(int bead, double tau) const;
  double phi(int spring, double tau) const;
  // Eq. (exactgreen): G_j(tau) = d psi_j / d tau for a unit step = response to delta(tau).
  double green(int bead, double tau) const;

  // Modal amplitudes x_n(tau) and x_n'(tau) of the drive.
  void modal(double tau, std::vector<double>& x, std::vector<double>& xdot) const;

 private:
  int n_;
  double gamma_;
  DriveDesc drive_;
  std::vector<double> k_, omega_, c_;
  // ... implementation detail members allowed
};

}  // namespace cb
