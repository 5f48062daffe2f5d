// The segments RK4 kernel (rk4_segments_kernel.inc) compiled for AVX-512F with 512-bit vectors (8
// doubles).
#include <immintrin.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>
#include <utility>
#include <vector>

#include "physics/crossing.h"
#include "physics/rk4_segments.h"
#include "physics/target_avx512_begin.inc"

namespace cb::detail::avx512 {
constexpr int kVec = 8;  // doubles a register
#include "physics/stencil.inc"
// What the wavefront kernels share.
#include "physics/wavefront.inc"
// The kernel.
#include "physics/rk4_segments_kernel.inc"
}  // namespace cb::detail::avx512

#include "physics/target_end.inc"
