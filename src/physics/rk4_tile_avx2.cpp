// The fused RK4 kernel (rk4_tile_kernel.inc) compiled for AVX2 (4 doubles a vector).
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "physics/rk4_tile.h"

#if defined(__clang__)
#pragma clang attribute push(__attribute__((target("avx2"))), apply_to = function)
#else
#pragma GCC push_options
#pragma GCC target("avx2")
#endif

namespace cb::detail::avx2 {
#include "physics/rk4_tile_kernel.inc"
}  // namespace cb::detail::avx2

#if defined(__clang__)
#pragma clang attribute pop
#else
#pragma GCC pop_options
#endif
