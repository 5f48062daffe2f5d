// Internal: one RK4 step of Eq. (dimless) for a whole chain with every spring intact, without
// tiles: the small-chain path of issue #13.
//
// Design note: at N = 30 .. a few thousand the tiled kernel (rk4_tile.h) spends most of a step
// on fixed costs: copying the window in and out, finding special beads, and four passes of
// stage arrays through memory. rk4_chain runs the four stages as a register wavefront along
// the chain (rk4_chain_kernel.inc), reading the old state and writing the new one in place of
// the copies, and gives the same bits as rk4_tile on every instruction set. It covers one
// worker's whole chain and no broken spring; everything else stays on the tiled path. Built
// for AVX2 and AVX-512 only (rk4_chain_kernel()).
#pragma once

#include "physics/rk4_tile.h"

namespace cb::detail {

// One step of the whole chain [0, in.beads), *in.broken empty; `out` as rk4_beads fills it.
using Rk4Chain = void (*)(const StepInput& in, StepOutput& out);
namespace avx2 {
void rk4_chain(const StepInput& in, StepOutput& out);
}
namespace avx512 {
void rk4_chain(const StepInput& in, StepOutput& out);
}
// The kernel for the path, or null where the tiled kernel is the faster one (SSE2).
Rk4Chain rk4_chain_kernel(SimdPath path);
// The copy of that kernel rk4_chain calls for a chain like `in`'s (its length, whether it has
// friction and crossing checks), found once for many steps of the chain (Integrator's runs of
// small-chain steps): the same function, without the choice per call. Null where
// rk4_chain_kernel(path) is.
Rk4Chain rk4_chain_for(SimdPath path, const StepInput& in);
namespace avx2 {
Rk4Chain rk4_chain_for(const StepInput& in);
}
namespace avx512 {
Rk4Chain rk4_chain_for(const StepInput& in);
}

// One step of beads [first, last) of a window of the chain (rk4_window_kernel.inc), for
// temporal blocks: reads old values of beads [first - kHalo, last + kHalo) only (clipped to
// the chain; in.base / in.out_base place the arrays), and keeps the books of the owned beads
// [own_first, own_last) in `out` as rk4_beads's calls over those tiles would: own_first a
// multiple of kTile, own_last one or in.beads, first <= own_first <= own_last <= last. No
// broken spring may touch the beads read (window_is_intact, temporal_block.cpp).
using Rk4Window = void (*)(const StepInput& in, int first, int last, int own_first, int own_last,
                           StepOutput& out);
namespace avx2 {
void rk4_window(const StepInput& in, int first, int last, int own_first, int own_last,
                StepOutput& out);
}
namespace avx512 {
void rk4_window(const StepInput& in, int first, int last, int own_first, int own_last,
                StepOutput& out);
}
// The kernel for the path, or null (SSE2: the tiled kernel, as for rk4_chain).
Rk4Window rk4_window_kernel(SimdPath path);

}  // namespace cb::detail
