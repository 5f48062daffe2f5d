// The fused RK4 kernel (rk4_tile_kernel.inc) compiled for AVX2 (4 doubles a vector).
#include <immintrin.h>  // stencil.inc's fmadd

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>
#include <vector>

#include "physics/rk4_tile.h"
#include "physics/target_avx2_begin.inc"

namespace cb::detail::avx2 {
#include "physics/stencil.inc"
// The kernel, written on the stencil above.
#include "physics/rk4_tile_kernel.inc"
}  // namespace cb::detail::avx2

#include "physics/target_end.inc"
