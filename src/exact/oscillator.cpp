#include "exact/oscillator.h"

#include <cassert>
#include <cmath>

namespace cb::detail {

double phi1(double z) {
  return z == 0.0 ? 1.0 : std::expm1(z) / z;
}

double phi2(double z) {
  // (e^z - 1 - z) / z^2 cancels for small |z|: sum its series z^k / (k + 2)! there;
  // 20 terms leave less than 0.5^20 / 22! of the sum for |z| < 0.5.
  if (std::abs(z) < 0.5) {
    double term = 0.5, sum = 0.0;
    for (int k = 0; k < 20; ++k) {
      sum += term;
      term *= z / (k + 3);
    }
    return sum;
  }
  return (std::expm1(z) - z) / (z * z);
}

std::complex<double> phi1(std::complex<double> z) {
  if (z == 0.0) return 1.0;
  // e^{x+iy} - 1 without cancellation: (e^x - 1) cos y + (cos y - 1) + i e^x sin y.
  const double x = z.real(), y = z.imag();
  const double half = std::sin(0.5 * y);
  const std::complex<double> em1(std::expm1(x) * std::cos(y) - 2.0 * half * half,
                                 std::exp(x) * std::sin(y));
  return em1 / z;
}

Oscillator::Oscillator(double omega, double gamma)
    : omega_(omega), omega2_(omega * omega), gamma_(gamma) {
  assert(omega > 0.0 && gamma >= 0.0);
  const double w2 = (omega - gamma) * (omega + gamma);  // omega^2 - gamma^2 without cancellation
  regime_ = w2 > 0.0 ? Regime::Under : w2 < 0.0 ? Regime::Over : Regime::Critical;
  w_ = std::sqrt(std::abs(w2));
  if (regime_ == Regime::Over) mu_slow_ = -omega2_ / (gamma + w_);
}

ModeResponse Oscillator::response(double t) const {
  ModeResponse r;
  if (t < 0.0) return r;
  if (t == 0.0) {
    r.gdot = 1.0;
    return r;
  }
  const double gm = gamma_;
  if (regime_ == Regime::Over) {
    const double lambda = w_, sum = gm + lambda;  // sum = -mu-
    const double e = std::exp(mu_slow_ * t);
    const double em = -std::expm1(-2.0 * lambda * t);  // 1 - e^{-2 lambda t}
    const double q = 1.0 - em;
    r.g = e * em / (2.0 * lambda);
    // g' = (mu+ e^{mu+ t} - mu- e^{mu- t}) / (2 lambda): the plain form cancels for
    // lambda -> 0, the rearranged one for lambda -> gamma; use each where it does not.
    r.gdot = lambda >= 0.5 * gm ? e * (mu_slow_ + sum * q) / (2.0 * lambda)
                                : e * (0.5 * (1.0 + q) - gm * em / (2.0 * lambda));
    // Integrals of g: int_0^t g = (t phi1(mu+ t) - g) / (gamma + lambda), and once more.
    r.step = (t * phi1(mu_slow_ * t) - r.g) / sum;
    r.ramp = (t * t * phi2(mu_slow_ * t) - r.step) / sum;
    return r;
  }
  const double decay = gm > 0.0 ? std::exp(-gm * t) : 1.0;
  double ec, one_minus_ec;  // e^{-gamma t} cos(omega t) and 1 minus it
  if (regime_ == Regime::Under) {
    const double c = std::cos(w_ * t), s = std::sin(w_ * t);
    ec = decay * c;
    r.g = decay * s / w_;
    // 1 - cos = sin^2 / (1 + cos) avoids cancellation where cos ~ 1.
    const double one_minus_c = c > 0.0 ? s * s / (1.0 + c) : 1.0 - c;
    one_minus_ec = -std::expm1(-gm * t) + decay * one_minus_c;
  } else {
    ec = decay;
    r.g = t * decay;
    one_minus_ec = -std::expm1(-gm * t);
  }
  r.gdot = ec - gm * r.g;
  // The mode equation itself: step'' + 2 gamma step' + Omega^2 step = 1 with step' = g,
  // step'' = g'; likewise for the ramp with ramp' = step, ramp'' = g.
  r.step = (one_minus_ec - gm * r.g) / omega2_;
  r.ramp = (t - 2.0 * gm * r.step - r.g) / omega2_;
  return r;
}

void Oscillator::harmonic(double t, double nu, std::complex<double> carrier,
                          std::complex<double>& x, std::complex<double>& xdot) const {
  using namespace std::complex_literals;
  if (t <= 0.0) {
    x = xdot = 0.0;
    return;
  }
  if (regime_ == Regime::Under && 2.0 * gamma_ < omega_) {
    // Eq. (exactconv) with g = (e^{mu t} - e^{mu* t}) / (2 i omega): each exponential
    // convolved with e^{i nu t} is e^{i nu t} t phi1((mu - i nu) t), finite at resonance.
    // omega > (sqrt 3 / 2) Omega here, so the division by 2 i omega cancels nothing.
    const std::complex<double> mu(-gamma_, w_), mub(-gamma_, -w_);
    const std::complex<double> ep = carrier * t * phi1((mu - 1i * nu) * t);
    const std::complex<double> em = carrier * t * phi1((mub - 1i * nu) * t);
    x = (ep - em) / (2i * w_);
    xdot = (mu * ep - mub * em) / (2i * w_);
    return;
  }
  // gamma >= Omega / 2: |D|^2 >= 3 Omega^4 / 4, no resonance. Particular solution e^{i nu t} / D
  // minus the free motion with the same initial values, written with g and g'.
  const std::complex<double> d(omega2_ - nu * nu, 2.0 * gamma_ * nu);
  const std::complex<double> x0 = 1.0 / d, v0 = 1i * nu / d;
  const ModeResponse r = response(t);
  x = carrier * x0 - (x0 * r.gdot + (v0 + 2.0 * gamma_ * x0) * r.g);
  xdot = 1i * nu * carrier * x0 - (v0 * r.gdot - omega2_ * x0 * r.g);
}

}  // namespace cb::detail
