// Internal (threshold_ensemble.cpp): each spring's reach in one interval of the shared run, the
// loop of the ensemble's windows, compiled for the x86-64 baseline, AVX2 and AVX-512
// (threshold_ensemble_reach.inc): the same bits on every path.
#pragma once

#include <cstddef>

namespace cb::detail {

// reach[j] for springs j + 1 = 1..n from the state at both ends of an interval (psi_0 = 0) and
// (4/27) h: stencil.inc's bound, max(|phi_0|, |phi_1|) + slack (|dphi_0| + |dphi_1|); then
// top[j], the largest so far, raised to it.
using SpringReaches = void (*)(const double* psi0, const double* vel0, const double* psi1,
                               const double* vel1, std::size_t n, double slack, double* reach,
                               double* top);
SpringReaches spring_reaches_for_cpu();

namespace sse2 {
void spring_reaches(const double* psi0, const double* vel0, const double* psi1, const double* vel1,
                    std::size_t n, double slack, double* reach, double* top);
}
namespace avx2 {
void spring_reaches(const double* psi0, const double* vel0, const double* psi1, const double* vel1,
                    std::size_t n, double slack, double* reach, double* top);
}
namespace avx512 {
void spring_reaches(const double* psi0, const double* vel0, const double* psi1, const double* vel1,
                    std::size_t n, double slack, double* reach, double* top);
}

}  // namespace cb::detail
