// The ensemble kernel (lanes_kernel.inc) compiled for AVX2 (two registers a row of lanes).
#include <algorithm>
#include <cmath>
#include <limits>

#include "physics/lanes_interval.h"

#if defined(__clang__)
#pragma clang attribute push(__attribute__((target("avx2"))), apply_to = function)
#else
#pragma GCC push_options
#pragma GCC target("avx2")
#endif

namespace cb::detail::avx2 {
constexpr int kVec = 4;  // doubles a register
#include "physics/lanes_kernel.inc"
}  // namespace cb::detail::avx2

#if defined(__clang__)
#pragma clang attribute pop
#else
#pragma GCC pop_options
#endif
