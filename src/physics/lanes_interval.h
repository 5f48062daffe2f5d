// Internal: the ensemble kernel's interface (lanes_kernel.inc), one interval for kLanes chains.
#pragma once

#include "physics/simd.h"

namespace cb::detail {

// Chains integrated side by side: 8 doubles, one AVX-512 register, two AVX2 or four SSE2 ones.
inline constexpr int kLanes = 8;

// Arrays are (beads + 2) rows of kLanes doubles, bead j of lane k at [j * kLanes + k]; rows 0
// and beads + 1 hold +0 in every array the kernel reads. Per-lane values are kLanes doubles.
struct LaneInterval {
  int beads = 0;
  const double* x0 = nullptr;  // the state at the interval's start
  const double* v0 = nullptr;
  double *xa = nullptr, *va = nullptr, *xb = nullptr, *vb = nullptr;  // stage states
  double *sx = nullptr, *sv = nullptr;                                // K1 + 2 K2 + 2 K3
  double *xn = nullptr, *vn = nullptr;                                // the new state
  // Per lane: 2 gamma, the interval's length h, h/2, h/6, the force at its start, middle and
  // end, the Hermite slack (4/27) h, the threshold and the break rule (1: stretch only).
  const double *g2 = nullptr, *h = nullptr, *h2 = nullptr, *h6 = nullptr;
  const double *f0 = nullptr, *f1 = nullptr, *f2 = nullptr;
  const double *slack = nullptr, *threshold = nullptr, *stretch_only = nullptr;
  // Out, per lane: 1 if a new value is not finite; 1 if a spring may cross its threshold.
  int *bad = nullptr, *near = nullptr;
};

using LanesKernel = void (*)(const LaneInterval& in);
namespace sse2 {
void lanes_interval(const LaneInterval& in);
}
namespace avx2 {
void lanes_interval(const LaneInterval& in);
}
namespace avx512 {
void lanes_interval(const LaneInterval& in);
}
LanesKernel lanes_kernel(SimdPath path);

}  // namespace cb::detail
