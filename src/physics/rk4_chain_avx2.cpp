// The one-chain RK4 kernel (rk4_chain_kernel.inc) and its window variant (rk4_window_kernel.inc)
// compiled for AVX2 (4 doubles a vector).
#include <immintrin.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>
#include <utility>
#include <vector>

#include "physics/rk4_chain.h"
#include "physics/target_avx2_begin.inc"

namespace cb::detail::avx2 {
constexpr int kVec = 4;  // doubles a register
#include "physics/stencil.inc"
// What the wavefront kernels share.
#include "physics/wavefront.inc"
// The kernels, written on the stencil above.
#include "physics/rk4_chain_kernel.inc"
#include "physics/rk4_window_kernel.inc"
}  // namespace cb::detail::avx2

#include "physics/target_end.inc"
