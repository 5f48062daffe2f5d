// The one-chain RK4 kernel (rk4_chain_kernel.inc) and its window variant (rk4_window_kernel.inc)
// compiled for AVX-512F with 512-bit vectors (8 doubles; GCC would otherwise prefer 256-bit ones).
#include <immintrin.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>
#include <utility>
#include <vector>

#include "physics/rk4_chain.h"

#if defined(__clang__)
#pragma clang attribute push(__attribute__((target("avx512f"))), apply_to = function)
#else
#pragma GCC push_options
#pragma GCC target("avx512f", "prefer-vector-width=512")
#endif

namespace cb::detail::avx512 {
constexpr int kVec = 8;  // doubles a register
#include "physics/rk4_chain_kernel.inc"
#include "physics/rk4_window_kernel.inc"
}  // namespace cb::detail::avx512

#if defined(__clang__)
#pragma clang attribute pop
#else
#pragma GCC pop_options
#endif
