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
  double *xn = nullptr, *vn = nullptr;  // the new state
  // Per lane: 2 gamma, the interval's length h, h/2, h/6, the force at its start, middle and
  // end, the Hermite slack (4/27) h, the nearest breaking bound of any spring (+inf: no
  // checks; ChainCoefficients::nearest_bound), and the largest |phi_j|
  // and |dphi_j/dtau| over the springs at the start (+inf when unknown, e.g. after a kick).
  const double *g2 = nullptr, *h = nullptr, *h2 = nullptr, *h6 = nullptr;
  const double *f0 = nullptr, *f1 = nullptr, *f2 = nullptr;
  const double *slack = nullptr, *threshold = nullptr, *p_start = nullptr, *m_start = nullptr;
  // The PerBead policy's coefficients (stencil.inc), rows as the state's: 1/m_j at row j, K_j
  // at row j, K_{N+1} = 0 at row N + 1; a Uniform lane of a PerBead call holds ones. Null: the
  // Uniform policy for every lane.
  const double *inv_mass = nullptr, *stiffness = nullptr;
  // Per lane, 1 when a proof (lane_far.h) says the lane stays far from its bounds and finite
  // over this interval, with p_far, m_far bounds on its end's largest |phi_j|, |dphi_j/dtau|. A
  // block whose lanes are all far skips its bounds and reports those. Null: no lane is far.
  const int* far = nullptr;
  const double *p_far = nullptr, *m_far = nullptr;
  // Out, per lane: 1 if a new value may not be finite; 1 if a spring may reach its threshold
  // (then the springs are tested one by one); the largest |phi_j|, |dphi_j/dtau| at the end.
  int *bad = nullptr, *near = nullptr;
  double *p_end = nullptr, *m_end = nullptr;
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
