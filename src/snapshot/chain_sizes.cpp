// How big beads and springs are drawn from the chain's masses m_j and stiffness K_j.
//
// Design note: the eye reads a disc's size by its area, so a bead's area (not its radius) is
// proportional to its mass; a spring's width (coil amplitude and wire) is proportional to its
// stiffness. Both relative to the chain's median, so that a chain of one heavy bead among
// equal ones draws the equal ones at the usual size, and clamped: a bead 100 times heavier
// would otherwise cover the frame and a very light one vanish. The uniform chain has empty
// ratios and keeps its exact pixels.
#include <algorithm>
#include <cmath>

#include "snapshot/snapshot.h"

namespace cb {

namespace {

// values[i] / median(values), clamped to [1/range, range]; a non-finite or non-positive value
// (a scene's mistake the scene reader refuses) counts as the median.
std::vector<double> median_ratios(const std::vector<double>& values, double range) {
  if (values.empty()) return {};
  std::vector<double> sorted = values;
  // The lower median: for a chain of two materials, half and half, the softer half is 1.
  const auto mid = sorted.begin() + static_cast<std::ptrdiff_t>((sorted.size() - 1) / 2);
  std::nth_element(sorted.begin(), mid, sorted.end());
  const double median = *mid;
  std::vector<double> ratios(values.size(), 1.0);
  if (!(median > 0.0) || !std::isfinite(median)) return ratios;
  for (std::size_t i = 0; i < values.size(); ++i) {
    const double r = values[i] / median;
    ratios[i] = r > 0.0 && std::isfinite(r) ? std::clamp(r, 1.0 / range, range) : 1.0;
  }
  return ratios;
}

}  // namespace

std::vector<double> bead_area_ratios(const ChainParams& params) {
  return median_ratios(params.mass, kBeadAreaRange);
}

std::vector<double> spring_width_ratios(const ChainParams& params) {
  return median_ratios(params.stiffness, kSpringWidthRange);
}

}  // namespace cb
