#include "physics/rk4_chain.h"

#include "physics/rk4_segments.h"
#include "physics/simd.h"

namespace cb::detail {

// The baseline has no wavefront kernel: two doubles a register and 16 registers, the
// wavefront's ~30 live vectors spill, and the tiled kernel is faster (N = 30: 294-342 against
// 413-423 ns a step, measured).
Rk4Chain rk4_chain_kernel(SimdPath path) {
  return by_simd<Rk4Chain>(path, nullptr, avx2::rk4_chain, avx512::rk4_chain);
}

Rk4Chain rk4_chain_for(SimdPath path, const StepInput& in) {
  using For = Rk4Chain (*)(const StepInput&);
  const For pick = by_simd<For>(path, nullptr, avx2::rk4_chain_for, avx512::rk4_chain_for);
  return pick ? pick(in) : nullptr;
}

Rk4Window rk4_window_kernel(SimdPath path) {
  return by_simd<Rk4Window>(path, nullptr, avx2::rk4_window, avx512::rk4_window);
}

SegmentsKernel rk4_segments_kernel(SimdPath path) {
  constexpr int kSegmentsBeads = 32 * kTile;  // all lanes' (rk4_segments.h)
  return by_simd<SegmentsKernel>(path, {},
                                 {avx2::rk4_segments, 4, kSegmentsBeads / 4, kSegmentsBeads / 8,
                                  avx2::interleave, avx2::deinterleave},
                                 {avx512::rk4_segments, 8, kSegmentsBeads / 8, kSegmentsBeads / 16,
                                  avx512::interleave, avx512::deinterleave});
}

}  // namespace cb::detail
