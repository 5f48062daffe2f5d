// The ensemble's reaches (threshold_ensemble_reach.inc) compiled for AVX-512.
#include <immintrin.h>

#include <cmath>
#include <cstddef>
#include <cstring>
#include <limits>
#include <type_traits>

#include "physics/threshold_ensemble_reach.h"
#include "physics/threshold_levels.h"

// The target from here on, after the declarations: their callers are built for the baseline.
#include "physics/target_avx512_begin.inc"

namespace cb::detail::avx512 {
#include "physics/stencil.inc"
#include "physics/threshold_ensemble_reach.inc"
}  // namespace cb::detail::avx512

#include "physics/target_end.inc"
