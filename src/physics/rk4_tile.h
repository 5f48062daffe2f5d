// Internal: one fused RK4 step of Eq. (dimless) over a tile of beads.
//
// Design note: a 3-point stencil lets every stage of RK4 be computed on a shrinking
// window, so a tile of T beads with a halo of 5 on each side yields the new state of its
// T beads (and of one bead either side, used for the spring checks) from the old state
// alone. All stages then live in L1/L2 and the step reads psi, vel and writes them once:
// about 32 bytes per bead-step instead of ~200 for a k1..k4 array formulation. Every value
// is computed by the same operations whatever the tiling, so results do not depend on the
// tile size or the number of threads.
#pragma once

#include <cstdint>
#include <vector>

#include "physics/coefficients.h"
#include "physics/crossing.h"
#include "physics/simd.h"

namespace cb::detail {

inline constexpr int kHalo = 5;
inline constexpr int kTile = 512;

// Everything one RK4 step needs besides the arrays.
struct StepInput {
  const double* psi = nullptr;  // old state: bead i (0-based) at psi[i - base]
  const double* vel = nullptr;
  double* psi_out = nullptr;  // new state: bead i at psi_out[i - out_base]
  double* vel_out = nullptr;
  // Where the arrays start in the chain: 0 for whole-chain arrays; a temporal block
  // (temporal_block.h) passes a window of the chain held in cache.
  int base = 0;
  int out_base = 0;
  int beads = 0;
  double gamma = 0.0;
  double h = 0.0;
  double force[3] = {0, 0, 0};               // f at the start, middle and end of the step
  const std::vector<int>* broken = nullptr;  // sorted broken springs
  // The chain's constants (coefficients.h): the stencil's policy, the arrays of the PerBead
  // one, the breaking bounds (no checks when coef->checks is false).
  const ChainCoefficients* coef = nullptr;
};

// What one worker accumulates over its tiles.
struct StepOutput {
  double dissipation_rate[4] = {0, 0, 0, 0};  // 2 gamma sum v^2 at each stage
  double end_velocity[4] = {0, 0, 0, 0};      // v_N at each stage (for the drive's work)
  bool finite = true;                         // false if any new value is inf or NaN
  std::vector<Candidate> candidates;
  void reset() {
    for (int s = 0; s < 4; ++s) dissipation_rate[s] = end_velocity[s] = 0.0;
    finite = true;
    candidates.clear();  // keeps its capacity: no allocation per step
  }
};

// Scratch buffers for one worker.
struct TileScratch {
  std::vector<double> x0, v0, xs, vs, xt, vt, sx, sv, kl, kr, fw;
  std::vector<double> im, wm;     // the window's 1/m and m (PerBead path)
  std::vector<int> specials;      // local indices that need the general stencil, sorted
  const double* x_new = nullptr;  // where the last tile's new state is (xs/vs or xt/vt)
  const double* v_new = nullptr;
  int zeroed_origin = 0, zeroed_len = -1;  // the window whose outside beads xs..vt hold +0
  TileScratch();
};

// Integrates beads [first, last) (0-based) for one step: the same kernel compiled for each
// instruction set (rk4_tile_kernel.inc); rk4_kernel() picks one.
using Rk4Beads = void (*)(const StepInput& in, int first, int last, TileScratch& scratch,
                          StepOutput& out);
namespace sse2 {
void rk4_beads(const StepInput& in, int first, int last, TileScratch& scratch, StepOutput& out);
}
namespace avx2 {
void rk4_beads(const StepInput& in, int first, int last, TileScratch& scratch, StepOutput& out);
}
namespace avx512 {
void rk4_beads(const StepInput& in, int first, int last, TileScratch& scratch, StepOutput& out);
}
Rk4Beads rk4_kernel(SimdPath path);

}  // namespace cb::detail
