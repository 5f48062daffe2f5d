// The ensemble kernel (lanes_kernel.inc) compiled for AVX2 (two registers a row of lanes).
#include <immintrin.h>  // stencil.inc's fmadd

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>

#include "physics/lanes_interval.h"
#include "physics/target_avx2_begin.inc"

namespace cb::detail::avx2 {
constexpr int kVec = 4;  // doubles a register
#include "physics/stencil.inc"
// The kernel, written on the stencil above.
#include "physics/lanes_kernel.inc"
}  // namespace cb::detail::avx2

#include "physics/target_end.inc"
