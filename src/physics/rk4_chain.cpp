#include "physics/rk4_chain.h"

#include "physics/rk4_segments.h"

namespace cb::detail {

Rk4Chain rk4_chain_kernel(SimdPath path) {
  switch (path) {
    case SimdPath::Avx512:
      return avx512::rk4_chain;
    case SimdPath::Avx2:
      return avx2::rk4_chain;
    case SimdPath::Sse2:
      break;
  }
  // Two doubles a register and 16 registers: the wavefront's ~30 live vectors spill, and the
  // tiled kernel is faster (N = 30: 294-342 against 413-423 ns a step, measured).
  return nullptr;
}

Rk4Chain rk4_chain_for(SimdPath path, const StepInput& in) {
  switch (path) {
    case SimdPath::Avx512:
      return avx512::rk4_chain_for(in);
    case SimdPath::Avx2:
      return avx2::rk4_chain_for(in);
    case SimdPath::Sse2:
      break;
  }
  return nullptr;
}

Rk4Window rk4_window_kernel(SimdPath path) {
  switch (path) {
    case SimdPath::Avx512:
      return avx512::rk4_window;
    case SimdPath::Avx2:
      return avx2::rk4_window;
    case SimdPath::Sse2:
      break;
  }
  return nullptr;
}

SegmentsKernel rk4_segments_kernel(SimdPath path) {
  constexpr int kSegmentsBeads = 32 * kTile;  // all lanes' (rk4_segments.h)
  switch (path) {
    case SimdPath::Avx512:
      return {avx512::rk4_segments, 8, kSegmentsBeads / 8, kSegmentsBeads / 16, avx512::interleave,
              avx512::deinterleave};
    case SimdPath::Avx2:
      return {avx2::rk4_segments, 4, kSegmentsBeads / 4, kSegmentsBeads / 8, avx2::interleave,
              avx2::deinterleave};
    case SimdPath::Sse2:
      break;
  }
  return {};
}

}  // namespace cb::detail
