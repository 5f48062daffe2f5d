// Weibull thresholds drawn 4 at a time (threshold_draw_lanes.inc) compiled for AVX2: each
// lane's bits are threshold_draw.cpp's weibull_quantile.
#include "physics/target_avx2_begin.inc"
#include "physics/threshold_draw_simd.h"

namespace cb::detail::avx2 {
#include "physics/threshold_draw_lanes.inc"

void weibull_quantiles(const double* u, std::size_t n, double shape, double* out) {
  weibull_lanes<4>(u, n, shape, out);
}
}  // namespace cb::detail::avx2

#include "physics/target_end.inc"
