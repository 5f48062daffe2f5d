// One normal mode of the chain: the damped oscillator x'' + 2 gamma x' + Omega^2 x = f(t),
// at rest at t = 0, whose response to a unit impulse is the modal Green's function of
// Eq. (exactgreen), g(t) = (e^{mu+ t} - e^{mu- t}) / (mu+ - mu-).
//
// Design note: the paper writes g with 1/sqrt(gamma^2 - Omega^2), which is 0/0 at critical
// damping and cancels catastrophically near it and for strong damping. Here every
// response is built from g and g', which are entire functions of
// omega^2 = Omega^2 - gamma^2 = (Omega - gamma)(Omega + gamma) (computed as that product,
// so it is exact to rounding even when gamma ~ Omega):
//   under-damped  g = e^{-gamma t} sin(omega t) / omega   (no cancellation for small omega),
//   critical      g = t e^{-gamma t},
//   over-damped   g = e^{mu+ t} (1 - e^{-2 lambda t}) / (2 lambda) with expm1, and
//                 mu+ = -Omega^2 / (gamma + lambda) instead of -gamma + lambda.
// Near critical damping the formulas therefore pass continuously into the limit without a
// series. Step and ramp responses follow from the mode equation; for over-damped modes they
// use the phi-functions of mu+ t so that the large 1/Omega^4 terms never appear.
#pragma once

#include <complex>

namespace cb::detail {

// Responses at time t after the input was switched on (all zero for t <= 0, except
// gdot(0) = 1: a kick changes the velocity at once).
struct ModeResponse {
  double g = 0.0;     // unit impulse delta(t): x
  double gdot = 0.0;  // unit impulse: x'
  double step = 0.0;  // unit step u(t): x (its x' is g)
  double ramp = 0.0;  // unit ramp t u(t): x (its x' is step)
};

class Oscillator {
 public:
  Oscillator(double omega, double gamma);

  double omega() const { return omega_; }
  ModeResponse response(double t) const;

  // Response to the complex force e^{i nu t} switched on at t = 0 (a sine force is the
  // imaginary part). carrier = e^{i nu t}, passed in because it is shared by all modes.
  // Exact at resonance (gamma = 0, nu = Omega): x = t e^{i nu t} / (2 i nu) + ...
  void harmonic(double t, double nu, std::complex<double> carrier, std::complex<double>& x,
                std::complex<double>& xdot) const;

 private:
  enum class Regime { Under, Critical, Over };
  double omega_, omega2_, gamma_;
  Regime regime_;
  double w_ = 0.0;        // omega (under-damped) or lambda = sqrt(gamma^2 - Omega^2) (over)
  double mu_slow_ = 0.0;  // over-damped: mu+ = -Omega^2 / (gamma + lambda)
};

// phi_1(z) = (e^z - 1) / z and phi_2(z) = (e^z - 1 - z) / z^2, accurate for small |z|.
double phi1(double z);
double phi2(double z);
std::complex<double> phi1(std::complex<double> z);

}  // namespace cb::detail
