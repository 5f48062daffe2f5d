// The page has no x86 kernels (rk4_*_avx2.cpp, *_avx512.cpp, lanes_*.cpp, crossing_*.cpp,
// threshold_draw_*.cpp, threshold_ensemble_reach_*.cpp: x86 intrinsics and target pragmas), but the
// dispatch files that name them (rk4_tile.cpp, rk4_chain.cpp (with rk4_segments.h), lanes.cpp,
// crossing.cpp, threshold_draw.cpp) are the program's own. On WebAssembly simd_supported() is true
// for the portable path only (physics/simd.cpp), so active_simd() is SimdPath::Sse2 and these are
// never called: the page runs the generic kernel, the one whose bits every x86 path reproduces.
// They trap if that ever changes rather than compute anything.
#include "physics/crossing.h"
#include "physics/lanes_interval.h"
#include "physics/rk4_chain.h"
#include "physics/rk4_segments.h"
#include "physics/rk4_tile.h"
#include "physics/threshold_draw.h"
#include "physics/threshold_ensemble_reach.h"

namespace cb::detail {

// Every kernel an instruction set's files define, once for both namespaces.
#define CB_NOT_IN_THE_PAGE(isa)                                                                \
  namespace isa {                                                                              \
  void rk4_beads(const StepInput&, int, int, TileScratch&, StepOutput&) {                      \
    __builtin_trap();                                                                          \
  }                                                                                            \
  void rk4_chain(const StepInput&, StepOutput&) {                                              \
    __builtin_trap();                                                                          \
  }                                                                                            \
  Rk4Chain rk4_chain_for(const StepInput&) {                                                   \
    __builtin_trap();                                                                          \
  }                                                                                            \
  void rk4_window(const StepInput&, int, int, int, int, StepOutput&) {                         \
    __builtin_trap();                                                                          \
  }                                                                                            \
  void rk4_segments(const SegmentStep&, SegmentBooks&) {                                       \
    __builtin_trap();                                                                          \
  }                                                                                            \
  void interleave(const double*, std::ptrdiff_t, int, double*) {                               \
    __builtin_trap();                                                                          \
  }                                                                                            \
  bool deinterleave(const double*, int, double*, std::ptrdiff_t) {                             \
    __builtin_trap();                                                                          \
  }                                                                                            \
  void lanes_interval(const LaneInterval&) {                                                   \
    __builtin_trap();                                                                          \
  }                                                                                            \
  void finish_hermite_roots(HermiteRoot*, std::size_t) {                                       \
    __builtin_trap();                                                                          \
  }                                                                                            \
  void weibull_quantiles(const double*, std::size_t, double, double*) {                        \
    __builtin_trap();                                                                          \
  }                                                                                            \
  void spring_reaches(const double*, const double*, const double*, const double*, std::size_t, \
                      double, double*, double*) {                                              \
    __builtin_trap();                                                                          \
  }                                                                                            \
  }

CB_NOT_IN_THE_PAGE(avx2)
CB_NOT_IN_THE_PAGE(avx512)

#undef CB_NOT_IN_THE_PAGE

}  // namespace cb::detail
