// The fused RK4 kernel (rk4_tile_kernel.inc) compiled for the x86-64 baseline: no pragma, every
// x86-64 CPU runs it.
#include <immintrin.h>  // stencil.inc's fmadd

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>
#include <vector>

#include "physics/rk4_tile.h"

namespace cb::detail::sse2 {
#include "physics/stencil.inc"
// The kernel, written on the stencil above.
#include "physics/rk4_tile_kernel.inc"
}  // namespace cb::detail::sse2
