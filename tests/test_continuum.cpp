// The paper's large-N formulas (Sec. II-III): H_N, Eq. (sum), the Fourier series
// Eqs. (example) and (extension), and the piecewise-linear Eqs. (phi1), (phij), (phiN),
// checked against each other, and the exact discrete chain approaching them as N grows.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <vector>

#include "drive/drive.h"
#include "exact/continuum.h"
#include "exact/exact_chain.h"

namespace {

constexpr double kPi = std::numbers::pi;

// The defining sum of H_N, term by term.
double direct_H(int N, double r) {
  double sum = 0.0;
  for (int n = 0; n < N; ++n) sum += (n % 2 ? -1.0 : 1.0) / N * std::sin((n + 0.5) * kPi / N * r);
  return sum;
}

// Rigorous bound on the tail of Eq. (extension) after M terms:
// (8 beta N / pi^2) sum_{n >= M} 1/(2n+1)^2 <= (8 beta N / pi^2) / (2 (2M - 1)).
double extension_tail(int N, double beta, int M) {
  return 8.0 * beta * N / (kPi * kPi) / (2.0 * (2.0 * M - 1.0));
}

}  // namespace

TEST_CASE("H_N in closed form equals its defining sum", "[continuum]") {
  for (int N : {1, 2, 5, 30, 101}) {
    for (double r : {0.0, 0.37, 1.0, 2.5, 7.25, 1.0 * N, 3.0 * N, 5.0 * N, N + 1e-9, 3.0 * N - 0.5,
                     4.0 * N + 0.1, 11.3 * N}) {
      INFO("N " << N << " r " << r);
      // Both are O(1) sums of N terms: 1e-12 absolute (the closed form is finite at the
      // impulses r = (2p+1) N where the paper's form is 0/0).
      CHECK(std::abs(cb::continuum_H(N, r) - direct_H(N, r)) <= 1e-12);
    }
    // The impulse train alternates: H_N((2p+1) N) = (-1)^p exactly.
    CHECK(cb::continuum_H(N, 1.0 * N) == 1.0);
    CHECK(cb::continuum_H(N, 3.0 * N) == -1.0);
  }
}

TEST_CASE("Eq. (extension) converges to Eqs. (phi1), (phij), (phiN)", "[continuum]") {
  // The Fourier series is the triangle-wave expansion of the piecewise-linear solution;
  // truncated after M terms it is within extension_tail(M) ~ 1/M of it everywhere.
  const int N = 200;
  const double beta = 0.7;
  for (int M : {1000, 20000}) {
    const double tol = extension_tail(N, beta, M);
    for (double tau = 0.0; tau <= 13.0 * N; tau += 0.37 * N) {
      INFO("M " << M << " tau " << tau);
      CHECK(std::abs(cb::continuum_phi_series(N, beta, 0.0, tau, M) -
                     cb::continuum_phi1(N, beta, tau)) <= tol);
      CHECK(std::abs(cb::continuum_phi_series(N, beta, N, tau, M) -
                     cb::continuum_phiN(beta, tau)) <= tol);
      for (int j : {1, 50, 137, 199})
        CHECK(std::abs(cb::continuum_phi_series(N, beta, j, tau, M) -
                       cb::continuum_phij(N, beta, j, tau)) <= tol);
    }
  }
  // The 1/M rate at a kink of phi_1 (tau = 3N): 20x the terms, at least 10x closer.
  const double e1 = std::abs(cb::continuum_phi_series(N, beta, 0.0, 3.0 * N, 1000) - 4 * beta * N);
  const double e2 = std::abs(cb::continuum_phi_series(N, beta, 0.0, 3.0 * N, 20000) - 4 * beta * N);
  CHECK(e2 < e1 / 10.0);
}

TEST_CASE("Eq. (phij) is Eq. (sum) for a ramp, and reduces to (phi1) and (phiN)", "[continuum]") {
  const int N = 40;
  const double beta = 1.3;
  auto ramp = [&](double t) { return beta * t; };
  for (double tau = 0.0; tau < 14.0 * N; tau += 0.83) {
    for (int j = 1; j <= N; ++j) {
      INFO("tau " << tau << " j " << j);
      // The same piecewise-linear function summed two ways: rounding only, 1e-12 of beta N.
      CHECK(std::abs(cb::continuum_phij(N, beta, j, tau) -
                     cb::continuum_phi_sum(N, j, tau, ramp)) <= 1e-12 * beta * N * (1 + tau / N));
    }
    CHECK(cb::continuum_phij(N, beta, N, tau) ==
          Approx(cb::continuum_phiN(beta, tau)).margin(1e-9));
    CHECK(cb::continuum_phij(N, beta, 0, tau) ==
          Approx(cb::continuum_phi1(N, beta, tau)).margin(1e-9));
  }
}

TEST_CASE("Eq. (extension) is the xi-derivative of Eq. (example)", "[continuum]") {
  const int N = 50, M = 400;
  const double beta = 2.0, h = 1e-4;
  for (double tau : {10.0, 77.0, 160.0})
    for (double xi : {3.0, 25.0, 49.0}) {
      const double d = (cb::continuum_psi_series(N, beta, xi + h, tau, M) -
                        cb::continuum_psi_series(N, beta, xi - h, tau, M)) /
                       (2 * h);
      // Central difference: O(h^2 psi''') ~ 1e-8 plus rounding of psi ~ 1e4 / h * 1e-16.
      CHECK(d == Approx(cb::continuum_phi_series(N, beta, xi, tau, M)).margin(1e-6));
    }
  CHECK(cb::continuum_psi_series(N, beta, 0.0, 42.0, M) == 0.0);  // the wall, psi(0) = 0
}

TEST_CASE("The exact chain approaches the piecewise-linear phi_j as N grows", "[continuum]") {
  // Ramp beta = 1, gamma = 0. phi ~ beta N, so compare phi / N over tau in [0, 8N] at springs
  // j = N/4, N/2, 3N/4, N. The exact chain differs by O(1) plus rounded wave fronts of
  // width ~N^(1/3) (paper_comparison in reference A), so the scaled error must shrink.
  cb::DriveDesc ramp;
  ramp.type = cb::DriveType::Ramp;
  std::vector<double> error;
  for (int N : {30, 120, 480}) {
    const cb::ExactChain chain(N, 0.0, ramp);
    std::vector<double> phi;
    double worst = 0.0;
    for (int k = 0; k <= 400; ++k) {
      const double tau = 8.0 * N * k / 400.0;
      chain.phi(tau, phi);
      for (int j : {N / 4, N / 2, 3 * N / 4, N})
        worst = std::max(worst, std::abs(phi[j - 1] - cb::continuum_phij(N, 1.0, j, tau)) / N);
    }
    error.push_back(worst);
  }
  INFO("max |phi_exact - phi_pl| / N: " << error[0] << ", " << error[1] << ", " << error[2]);
  CHECK(error[1] < 0.75 * error[0]);
  CHECK(error[2] < 0.75 * error[1]);
  CHECK(error[2] < 0.05);
}
