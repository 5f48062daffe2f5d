// Internal (threshold_ensemble.cpp): each spring's reach in one interval of the shared run, the
// loop of the ensemble's windows, compiled for the x86-64 baseline, AVX2 and AVX-512
// (threshold_ensemble_reach.inc): the same bits on every path.
#pragma once

#include <cstddef>
#include <cstdint>

namespace cb::detail {

// reach[j] for springs j + 1 = 1..n from the state at both ends of an interval (psi_0 = 0) and
// (4/27) h: stencil.inc's bound, max(|phi_0|, |phi_1|) + slack (|dphi_0| + |dphi_1|); then
// top[j], the largest so far, raised to it.
using SpringReaches = void (*)(const double* psi0, const double* vel0, const double* psi1,
                               const double* vel1, std::size_t n, double slack, double* reach,
                               double* top);
SpringReaches spring_reaches_for_cpu();

// level[j] for springs j + 1 = 1..n of a member drawn by seed: threshold_levels.h's drawn_level
// of uniform_bits(stream, j + 1), several springs at once (the ensemble takes 3 x 10^5), where
// key[j] = index_key(j + 1).
using DrawnLevels = void (*)(std::uint64_t stream, const std::uint64_t* key, std::size_t n,
                             std::int16_t* level);
DrawnLevels drawn_levels_for_cpu();

namespace sse2 {
void spring_reaches(const double* psi0, const double* vel0, const double* psi1, const double* vel1,
                    std::size_t n, double slack, double* reach, double* top);
void drawn_levels(std::uint64_t stream, const std::uint64_t* key, std::size_t n,
                  std::int16_t* level);
}  // namespace sse2
namespace avx2 {
void spring_reaches(const double* psi0, const double* vel0, const double* psi1, const double* vel1,
                    std::size_t n, double slack, double* reach, double* top);
void drawn_levels(std::uint64_t stream, const std::uint64_t* key, std::size_t n,
                  std::int16_t* level);
}  // namespace avx2
namespace avx512 {
void spring_reaches(const double* psi0, const double* vel0, const double* psi1, const double* vel1,
                    std::size_t n, double slack, double* reach, double* top);
void drawn_levels(std::uint64_t stream, const std::uint64_t* key, std::size_t n,
                  std::int16_t* level);
}  // namespace avx512

}  // namespace cb::detail
