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
#include "physics/target_avx512_begin.inc"

namespace cb::detail::avx512 {
constexpr int kVec = 8;  // doubles a register
#include "physics/stencil.inc"
// What the wavefront kernels share.
#include "physics/wavefront.inc"
// The kernels, written on the stencil above.
#include "physics/rk4_chain_kernel.inc"
#include "physics/rk4_window_kernel.inc"
}  // namespace cb::detail::avx512

#include "physics/target_end.inc"
