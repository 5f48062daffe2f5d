// Many Hermite roots bisected at once (crossing_bisect.inc) compiled for AVX-512F: groups of 64
// brackets, eight registers of eight lanes (ten or twelve were no faster).
#include <algorithm>
#include <cstddef>
#include <cstring>
#include <type_traits>

#include "physics/crossing.h"
#include "physics/target_avx512_begin.inc"

namespace cb::detail::avx512 {
#include "physics/crossing_bisect.inc"

void finish_hermite_roots(HermiteRoot* roots, std::size_t count) {
  finish_roots<8, 8>(roots, count);
}
}  // namespace cb::detail::avx512

#include "physics/target_end.inc"
