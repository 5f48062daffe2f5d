#include "exact/continuum.h"

#include <cassert>
#include <cmath>
#include <complex>
#include <numbers>

namespace cb {

namespace {

constexpr double kPi = std::numbers::pi;

double sign_of_power(long long p) {
  return p % 2 == 0 ? 1.0 : -1.0;
}  // (-1)^p

}  // namespace

// H_N(r) = (-1)^(N-1) sin(pi r) / (2N cos(pi r / 2N)) is 0/0 at the impulses r = (2p+1) N,
// and sin(pi r) loses digits for large r. With r = (2p+1) N + eps, p the nearest impulse,
// the same function is (-1)^p sin(pi eps) / (2N sin(pi eps / 2N)), |eps| <= N: finite
// everywhere, equal to (-1)^p at the impulse (the paper's sinc train).
double continuum_H(int N, double r) {
  assert(N >= 1);
  const double p = std::round((r / N - 1.0) / 2.0);
  const double eps = r - (2.0 * p + 1.0) * N;
  const double sign = sign_of_power(static_cast<long long>(p));
  if (eps == 0.0) return sign;
  return sign * std::sin(kPi * eps) / (2.0 * N * std::sin(kPi * eps / (2.0 * N)));
}

// Eq. (sum): the pulse of Eq. (dg) travelling back and forth, flipping sign at the free end.
double continuum_phi_sum(int N, double xi, double tau, const std::function<double(double)>& f) {
  double sum = 0.0;
  for (double side : {1.0, -1.0}) {
    double sign = 1.0;
    for (int nu = 0;; ++nu, sign = -sign) {
      const double arg = tau + side * xi - (2.0 * nu + 1.0) * N;
      if (arg <= 0.0) break;
      sum += sign * f(arg);
    }
  }
  return sum;
}

// Eq. (example).
double continuum_psi_series(int N, double beta, double xi, double tau, int terms) {
  double sum = 0.0;
  for (int n = 0; n < terms; ++n) {
    const double m = 2.0 * n + 1.0, kappa = (n + 0.5) * kPi / N;
    sum += sign_of_power(n) / (m * m * m) * std::sin(kappa * xi) * std::sin(kappa * tau);
  }
  return beta * tau * xi - 16.0 * beta * N * N / (kPi * kPi * kPi) * sum;
}

// Eq. (extension) = d/dxi of Eq. (example).
double continuum_phi_series(int N, double beta, double xi, double tau, int terms) {
  double sum = 0.0;
  for (int n = 0; n < terms; ++n) {
    const double m = 2.0 * n + 1.0, kappa = (n + 0.5) * kPi / N;
    sum += sign_of_power(n) / (m * m) * std::sin(kappa * tau) * std::cos(kappa * xi);
  }
  return beta * tau - 8.0 * beta * N / (kPi * kPi) * sum;
}

// Eq. (phi1), nu = 0, 1, 2, ... (period 4N after the first N).
double continuum_phi1(int N, double beta, double tau) {
  if (tau < N) return 0.0;
  const double nu = std::floor((tau - N) / (4.0 * N));
  const double r = tau - 4.0 * nu * N;  // in [N, 5N)
  if (r < 3.0 * N) return 2.0 * beta * (tau - (2.0 * nu + 1.0) * N);
  return 4.0 * beta * (nu + 1.0) * N;
}

// Eq. (phij); reduces to Eq. (phi1) at j = 0 and to Eq. (phiN) at j = N.
double continuum_phij(int N, double beta, int j, double tau) {
  if (tau < N - j) return 0.0;
  const double nu = std::floor((tau - (N - j)) / (4.0 * N));
  const double r = tau - 4.0 * nu * N;  // in [N - j, 5N - j)
  if (r < N + j) return beta * (tau + j - N);
  if (r < 3.0 * N - j) return 2.0 * beta * (tau - (2.0 * nu + 1.0) * N);
  if (r < 3.0 * N + j) return beta * (tau - j + N);
  return 4.0 * beta * (nu + 1.0) * N;
}

// Eq. (phiN).
double continuum_phiN(double beta, double tau) {
  return tau > 0.0 ? beta * tau : 0.0;
}

// Eqs. (green), (conv): each mode's Green's function integrated from 0 to tau in closed form.
// Complex arithmetic covers under- and over-damped modes alike (s_n imaginary or real).
double continuum_psi_step(int N, double gamma, double xi, double tau) {
  using C = std::complex<double>;
  double sum = 0.0;
  for (int n = 0; n < N; ++n) {
    const double kappa = (n + 0.5) * kPi / N;
    const C s = std::sqrt(C(gamma * gamma - kappa * kappa, 0.0));
    const C up = -gamma + s, down = -gamma - s;
    const C integral = (std::exp(up * tau) - 1.0) / up - (std::exp(down * tau) - 1.0) / down;
    sum += sign_of_power(n) / N * (integral / s).real() * std::sin(kappa * xi);
  }
  return sum;
}

}  // namespace cb
