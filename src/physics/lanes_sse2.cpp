// The ensemble kernel (lanes_kernel.inc) compiled for the x86-64 baseline: no pragma, every x86-64
// CPU runs it.
#include <immintrin.h>  // stencil.inc's fmadd

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>

#include "physics/lanes_interval.h"

namespace cb::detail::sse2 {
constexpr int kVec = 2;  // doubles a register
#include "physics/stencil.inc"
// The kernel, written on the stencil above.
#include "physics/lanes_kernel.inc"
}  // namespace cb::detail::sse2
