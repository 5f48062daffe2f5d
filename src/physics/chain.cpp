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

void ChainParams::normalize() {
  if (all_equal(mass, 1.0)) mass.clear();
  if (all_equal(stiffness, 1.0)) stiffness.clear();
  if (all_equal(thresholds, threshold)) thresholds.clear();
}

}  // namespace cb
