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
    phi[j - 1] = below / stiffness_of(j);
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

}  // namespace cb
