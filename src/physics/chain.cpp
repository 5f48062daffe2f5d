// ChainParams' helpers (chain.h): what a chain's arrays say about it as a whole.
#include "physics/chain.h"

#include <algorithm>
#include <cmath>

namespace cb {

namespace {
bool all_equal(const std::vector<double>& values, double to) {
  return std::all_of(values.begin(), values.end(), [to](double v) { return v == to; });
}
}  // namespace

bool ChainParams::breakable() const {
  return min_threshold() < std::numeric_limits<double>::infinity();
}

double ChainParams::min_threshold() const {
  if (thresholds.empty()) return threshold;
  return *std::min_element(thresholds.begin(), thresholds.end());
}

std::vector<double> ChainParams::equilibrium_extensions() const {
  std::vector<double> phi(static_cast<std::size_t>(beads), 0.0);
  if (!hanging()) return phi;
  double below = 0.0;  // G sum_{i>=j} m_i, summed from the free end up
  for (int j = beads; j >= 1; --j) {
    below += gravity * mass_of(j);
    // The linear chain keeps its division's bits; anharmonic springs solve T(phi) = load / K.
    phi[j - 1] = anharmonic() ? fput_extension(below / stiffness_of(j), fput_alpha, fput_beta)
                              : below / stiffness_of(j);
  }
  return phi;
}

std::vector<double> ChainParams::equilibrium_positions() const {
  std::vector<double> psi = equilibrium_extensions();
  for (std::size_t j = 1; j < psi.size(); ++j) psi[j] += psi[j - 1];
  return psi;
}

void ChainParams::normalize() {
  if (all_equal(mass, 1.0)) mass.clear();
  if (all_equal(stiffness, 1.0)) stiffness.clear();
  if (all_equal(thresholds, threshold)) thresholds.clear();
}

double fput_stiffest_slope(double phi_c, double a, double b) {
  if (!std::isfinite(phi_c)) return 1.0;
  // A parabola in phi: its largest value on [-phi_c, phi_c] is at an end, or at its vertex
  // -a / (3 b) when b < 0 and the vertex lies inside.
  double s = std::max(fput_slope(phi_c, a, b), fput_slope(-phi_c, a, b));
  if (b < 0.0 && std::abs(a / (3.0 * b)) < phi_c) s = std::max(s, fput_slope(-a / (3.0 * b), a, b));
  return std::max(s, 1.0);
}

double fput_first_flat(double a, double b) {
  // Roots of 3 b phi^2 + 2 a phi + 1 = 0.
  constexpr double kInf = std::numeric_limits<double>::infinity();
  if (b == 0.0) return a == 0.0 ? kInf : 1.0 / (2.0 * std::abs(a));
  const double disc = a * a - 3.0 * b;
  if (disc < 0.0) return kInf;
  const double r = std::sqrt(disc);
  const double p1 = (-a + r) / (3.0 * b), p2 = (-a - r) / (3.0 * b);
  return std::min(std::abs(p1), std::abs(p2));
}

double fput_stretch_flat(double a, double b) {
  // Positive roots of 3 b phi^2 + 2 a phi + 1 = 0 (its value at 0 is 1 > 0).
  constexpr double kInf = std::numeric_limits<double>::infinity();
  if (b == 0.0) return a < 0.0 ? -1.0 / (2.0 * a) : kInf;
  const double disc = a * a - 3.0 * b;
  if (disc < 0.0) return kInf;
  const double r = std::sqrt(disc);
  double flat = kInf;
  for (double root : {(-a + r) / (3.0 * b), (-a - r) / (3.0 * b)})
    if (root > 0.0) flat = std::min(flat, root);
  return flat;
}

double fput_extension(double t, double a, double b) {
  if (t == 0.0 || (a == 0.0 && b == 0.0)) return t;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  if (!(t > 0.0) || !std::isfinite(t)) return nan;
  // Bracket [lo, hi] with T(lo) < t <= T(hi) on the rising branch.
  double lo = 0.0, hi = fput_stretch_flat(a, b);
  if (std::isfinite(hi)) {
    if (fput_tension(hi, a, b) < t) return nan;  // beyond the largest tension
  } else {
    hi = t;  // T grows without bound on [0, inf): double until it passes t
    while (fput_tension(hi, a, b) < t) hi *= 2.0;
  }
  double phi = std::min(t, hi);
  for (int k = 0; k < 200; ++k) {
    const double r = fput_tension(phi, a, b) - t;
    if (r == 0.0) break;
    (r < 0.0 ? lo : hi) = phi;
    const double slope = fput_slope(phi, a, b);
    double next = slope > 0.0 ? phi - r / slope : 0.5 * (lo + hi);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);  // the safeguard
    if (next == phi || hi - lo <= 4.0 * std::numeric_limits<double>::epsilon() * hi) {
      phi = next;
      break;
    }
    phi = next;
  }
  // Checked: the tension matches the load to rounding (the residual of a double root is the
  // only way to miss, and there the chain has no stable equilibrium anyway).
  return std::abs(fput_tension(phi, a, b) - t) <= 1e-14 * t ? phi : nan;
}

}  // namespace cb
