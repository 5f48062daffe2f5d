// Many Hermite roots bisected at once (crossing_bisect.inc) compiled for AVX2: groups of 32
// brackets, eight registers of four lanes (more spill the 16 registers; fewer leave the ports
// idle).
#include <algorithm>
#include <cstddef>
#include <cstring>
#include <type_traits>

#include "physics/crossing.h"
#include "physics/target_avx2_begin.inc"

namespace cb::detail::avx2 {
#include "physics/crossing_bisect.inc"

void finish_hermite_roots(HermiteRoot* roots, std::size_t count) {
  finish_roots<4, 8>(roots, count);
}
}  // namespace cb::detail::avx2

#include "physics/target_end.inc"
