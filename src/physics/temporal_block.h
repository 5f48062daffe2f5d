// Internal: temporal blocking, several fused RK4 steps over a block of tiles held in cache.
//
// Design note: at large N one step streams psi and vel through memory (32 B a bead) and
// the kernel waits on the bus. A block of B beads (whole tiles) is instead advanced K steps
// in a window that starts kHalo * K beads wider on each side and loses kHalo beads a side
// per step (the kernel reads kHalo beads either side of what it writes: four stages of a
// 3-point stencil and the bead left of each spring check), so the state crosses the bus
// once per K steps. Every step runs the one-step kernel (Rk4Beads) on the same global tiles
// with the same inputs, so every value, every tile's energy sums and their order are those
// of K single steps: per worker and step, the tiles' friction sums are added in tile order
// into a StepOutput as the one-step path adds them. On AVX2 and AVX-512 a step whose window
// no broken spring touches runs the wavefront kernel instead (rk4_window, rk4_chain.h), one
// call for the halo and the block, about 2-5 x the tiled kernel's speed in cache, with the
// same values and sums in the same order; inside the chain, rk4_segments (rk4_segments.h)
// takes several blocks' worth at once as stretches side by side in SIMD lanes, again with the
// same values and sums. A block is kept only if every step is
// plain: the caller gives only steps with no kick, split or pull-string crossing, and a
// step with a spring crossing (the Hermite test the one-step path applies to its
// candidates) or a value that is not finite fails the whole pass, which wrote only to the
// "next" arrays: the caller redoes those steps one at a time.
#pragma once

#include <atomic>
#include <vector>

#include "physics/rk4_chain.h"
#include "physics/rk4_segments.h"
#include "physics/rk4_tile.h"

namespace cb::detail {

inline constexpr int kBlockTiles = 8;  // a block: 4096 beads, ~0.4 MB of windows in L2

// One step of a block: the kernel's inputs that change from step to step.
struct PlainStep {
  double h = 0.0;
  double force[3] = {0, 0, 0};
};

// One worker's buffers for blocked steps.
struct BlockScratch {
  std::vector<double> psi[2], vel[2];              // the block's window, one step after another
  StepOutput tile, halo;                           // one kernel call's output
  std::vector<double> lanes_psi[2], lanes_vel[2];  // segments' windows, interleaved
  std::vector<double> lanes_coef[5];               // and their PerBead arrays
  SegmentBooks lanes_books;                        // one segments step's books
  // Per step of the block: this worker's sums in the one-step path's order (candidates
  // stay empty: a step with a crossing fails the block).
  std::vector<StepOutput> steps;
};

// Advances beads [first, last) (whole tiles, one worker's range) by steps.size() steps
// from in.psi / in.vel into in.psi_out / in.vel_out (in's h and force are ignored: each
// step's are in `steps`). Returns -1, or the index of a step found not plain (then the
// output is to be thrown away); a set `abort` stops between blocks, and a failure sets it.
// `window` (may be null) does each step of a block where no broken spring is near, with the
// same bits as `kernel`'s tiles (rk4_window_kernel.inc); `kernel` does the others. Where
// `window` runs, `segments` (its step may be null) takes the chain's stretches of
// segments.lanes lanes of segments.segment beads (segment_per_bead on the PerBead path) whose
// windows lie inside the chain, with the window kernel's bits (rk4_segments.h).
int rk4_blocked(Rk4Beads kernel, Rk4Window window, SegmentsKernel segments, const StepInput& in,
                const std::vector<PlainStep>& steps, int first, int last, TileScratch& scratch,
                BlockScratch& bs, std::atomic<bool>& abort);

}  // namespace cb::detail
