// The ensemble kernel (lanes_kernel.inc) compiled for AVX-512F with 512-bit vectors (one register a
// row of lanes).
#include <algorithm>
#include <cmath>
#include <limits>

#include "physics/lanes_interval.h"

#if defined(__clang__)
#pragma clang attribute push(__attribute__((target("avx512f"))), apply_to = function)
#else
#pragma GCC push_options
#pragma GCC target("avx512f", "prefer-vector-width=512")
#endif

namespace cb::detail::avx512 {
constexpr int kVec = 8;  // doubles a register
#include "physics/lanes_kernel.inc"
}  // namespace cb::detail::avx512

#if defined(__clang__)
#pragma clang attribute pop
#else
#pragma GCC pop_options
#endif
