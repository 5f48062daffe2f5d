// The ensemble kernel (lanes_kernel.inc) compiled for AVX-512F with 512-bit vectors (one register a
// row of lanes).
#include <immintrin.h>  // stencil.inc's fmadd

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>

#include "physics/lanes_interval.h"
#include "physics/target_avx512_begin.inc"

namespace cb::detail::avx512 {
constexpr int kVec = 8;  // doubles a register
#include "physics/stencil.inc"
// The kernel, written on the stencil above.
#include "physics/lanes_kernel.inc"
}  // namespace cb::detail::avx512

#include "physics/target_end.inc"
