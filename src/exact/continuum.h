// The paper's continuum (N >> 1) approximations, gamma = 0 unless stated.
#pragma once

#include <functional>

namespace cb {

// H_N(r) = sum_n (-1)^n / N sin(kappa_n r) in closed form: (-1)^(N-1) sin(pi r) / (2N cos(pi r /
// 2N)).
double continuum_H(int N, double r);

// Eq. (sum): phi_j(tau) ~ sum_nu (-1)^nu f[tau + j - (2nu+1)N] + sum_nu (-1)^nu f[tau - j -
// (2nu+1)N], terms with a positive argument only. xi may be fractional.
double continuum_phi_sum(int N, double xi, double tau, const std::function<double(double)>& f);

// Eq. (example): psi(xi, tau) for a ramp beta*tau, the series truncated after `terms` terms.
double continuum_psi_series(int N, double beta, double xi, double tau, int terms);
// Eq. (extension): phi(xi, tau) for a ramp, truncated after `terms` terms.
double continuum_phi_series(int N, double beta, double xi, double tau, int terms);

// Eqs. (phi1), (phij), (phiN): the piecewise-linear extensions for a ramp beta*tau.
double continuum_phi1(int N, double beta, double tau);
double continuum_phij(int N, double beta, int j, double tau);
double continuum_phiN(double beta, double tau);

// Eqs. (green) and (conv) for a unit step f = u(tau) with friction gamma: the N-term sum
// psi(xi, tau) = sum_n (-1)^n / (N s_n) [(e^{eta+ tau} - 1) / eta+ - (e^{eta- tau} - 1) / eta-]
// sin(kappa_n xi), s_n = sqrt(gamma^2 - kappa_n^2), eta+- = -gamma +- s_n (Fig. 3(a)). As
// tau -> infinity it tends to the particular solution xi (a quarter-wave sine series of xi).
double continuum_psi_step(int N, double gamma, double xi, double tau);

}  // namespace cb
