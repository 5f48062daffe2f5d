// How a spring's strain maps to the colour map, one rule for every picture that colours
// strain (the chain panel and its ribbon, the overlay's space-time picture): s_j = phi_j /
// phi_c,j, how close spring j is to its own threshold (issue #21). Header only, on
// physics/chain.h alone, so the overlay's physics side uses it without linking the snapshot.
#pragma once

#include <algorithm>
#include <cmath>

#include "physics/chain.h"

namespace cb {

// The springs have thresholds of their own (not all equal): colour by phi_j / phi_c,j. A
// chain with one threshold (or an array of equal ones) is coloured by phi / frame_scale as
// the paper's chain always was, and keeps its bits.
inline bool strain_per_spring(const ChainParams& params) {
  const std::vector<double>& c = params.thresholds;
  return params.breakable() &&
         std::any_of(c.begin(), c.end(), [&](double v) { return v != c.front(); });
}

// The scale of spring j (1..N) when strain_per_spring: phi_c,j, or the frame's scale for a
// spring that cannot break (phi_c,j = inf), whose strain is then shown as the frame shows it.
inline double spring_strain_scale(const ChainParams& params, int spring, double frame_scale) {
  const double c = std::abs(params.threshold_of(spring));
  return std::isfinite(c) && c > 0.0 ? c : frame_scale;
}

}  // namespace cb
