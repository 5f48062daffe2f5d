// Levels of thresholds and reaches for an ensemble's tests (threshold_ensemble.cpp): 15-bit
// numbers monotone in what they stand for, compared 16 at a time where doubles would be 8.
#pragma once

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

#include "physics/threshold_draw.h"

namespace cb::detail {

// A threshold or reach as a 15-bit level, monotone in it: x <= y gives level(x) <= level(y), so
// a member none of whose levels reaches its spring's level cannot reach its bound. The level is
// the exponent and first 11 bits of the mantissa of x as a float (rounding is monotone), from
// 2^-8 times `base` up, clamped. A member's levels go in words of 32 (threshold_ensemble.cpp: 64
// bytes, one cache line where 30 thresholds fill four).
using Level = std::int16_t;
inline constexpr Level kTopLevel = 32767;
inline std::int32_t level_base(double scale) {
  return (std::bit_cast<std::int32_t>(static_cast<float>(scale)) >> 12) - (8 << 11);
}
// x >= 0 (+0 for a reach at rest); +inf and NaN come out at the top.
inline Level level_of(double x, std::int32_t base) {
  const std::int32_t bits = std::bit_cast<std::int32_t>(static_cast<float>(x)) >> 12;
  return static_cast<Level>(std::clamp(bits - base, 0, std::int32_t{kTopLevel}));
}
// A member drawn by seed (ThresholdEnsemble::drawn) has the levels of its u instead, the top 15
// of uniform_bits' 53 (monotone in u, so in its draws) without drawing it; a reach, the level of
// F(reach / scale) (weibull_cdf) with room for rounding: a draw at or below the reach has a level
// at or below the reach's (tests/test_threshold_ensemble.cpp). Finer than the float levels for
// all but the lowest percent of u.
inline constexpr int kDrawnLevelShift = 53 - 15;
inline Level drawn_level(std::uint64_t bits) {
  return static_cast<Level>(bits >> kDrawnLevelShift);
}
inline Level drawn_level_of_reach(double reach, double scale, double shape) {
  if (!(reach < std::numeric_limits<double>::infinity())) return kTopLevel;  // +inf, NaN
  if (!(reach > 0.0)) return 0;
  // A draw x = scale W(u) <= reach: W(u) lies within a few ulps of the quantile at u, so the
  // quantile is below reach (1 + 2^-40) / scale, and u below F of that (F's own rounding is
  // ~1e-16, far below one level, 2^-15): u's level is at most F's, plus one where F lies just
  // below a level's edge.
  const double f = weibull_cdf(reach / scale * (1.0 + 0x1p-40), shape);
  return static_cast<Level>(std::min(double{kTopLevel}, std::floor(f * 32768.0) + 1.0));
}

}  // namespace cb::detail
