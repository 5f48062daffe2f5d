// Weibull thresholds drawn 8 at a time (threshold_draw_lanes.inc) compiled for AVX-512F: each
// lane's bits are threshold_draw.cpp's weibull_quantile.
#include <array>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>

#include "physics/threshold_draw.h"

// See portable_math.cpp.
#ifdef __clang__
#pragma STDC FP_CONTRACT OFF
#endif
// portable_lanes.inc's functions take and return vectors; GCC warns that their ABI differs
// without the instruction set. They are this file's own (an anonymous namespace), never called
// from code built for another.
#ifndef __clang__
#pragma GCC diagnostic ignored "-Wpsabi"
#endif

#include "physics/target_avx512_begin.inc"

namespace cb::detail::avx512 {
namespace {
#include "physics/portable_lanes.inc"
#include "physics/threshold_draw_lanes.inc"
}  // namespace

void weibull_quantiles(const double* u, std::size_t n, double shape, double* out) {
  weibull_lanes<8>(u, n, shape, out);
}
}  // namespace cb::detail::avx512

#include "physics/target_end.inc"
