// Internal: one RK4 step of several stretches of the chain at once, one per SIMD lane, for
// temporal blocks (temporal_block.h).
//
// Design note: the wavefront kernels (rk4_chain.h) hold kVec consecutive beads in a register,
// so every stage hands each spring's tension to the neighbouring lane by a shuffle. On AVX2
// those shuffles cross the register's halves and run on one port only: the window kernel at
// N = 1e7 ran at ~50 cycles a block where its arithmetic needs ~25 (tests/bench/README.md,
// session 19). Here the window of a temporal block is kVec segments of the chain held
// interleaved, bead `origin + k * stride + i` at x[i * kVec + k], as the lanes kernel holds
// kVec chains (lanes_kernel.inc): vector i's neighbours are vectors i - 1 and i + 1, and the
// stencil needs no shuffle at all. Each lane is a window of its own with its own halo, as a
// temporal block's is, so every value it writes is the value the window kernel writes for
// that bead (the same operations in the same order, StageForce<P, Interleaved>), and the
// friction books keep their order: each tile's sum is made lane by lane from four partial
// sums, bead l of the tile into s_{l % 4} (wavefront.inc's Squares), and handed back per tile
// for the caller to add in chain order. Every policy the window kernel takes (Uniform and
// PerBead, harmonic or anharmonic; the PerBead arrays interleaved by the caller once a pass),
// and only windows that touch neither the wall's halo nor bead N's (no general stencil):
// temporal_block.cpp keeps the window kernel for those.
#pragma once

#include <cstddef>
#include <vector>

#include "physics/rk4_tile.h"
#include "physics/simd.h"

namespace cb::detail {

// One step of kVec interleaved segments: vectors [read_lo, read_hi) of x and v are read (the
// others taken as +0), vectors [write_lo, write_hi) of x_out and v_out written. The books
// cover the owned vectors [own_lo, own_hi), own_lo the first bead of a tile in every lane and
// own_hi - own_lo a multiple of kTile; read_lo + kHalo <= write_lo <= own_lo and
// own_hi <= write_hi <= read_hi - kHalo.
struct SegmentStep {
  const double* x = nullptr;
  const double* v = nullptr;
  double* x_out = nullptr;
  double* v_out = nullptr;
  int read_lo = 0, read_hi = 0;
  int write_lo = 0, write_hi = 0;
  int own_lo = 0, own_hi = 0;
  int origin = 0, stride = 0;  // vector i, lane k holds bead origin + k * stride + i (0-based)
  double h = 0.0;
  double gamma = 0.0;
  const ChainCoefficients* coef = nullptr;
  // The PerBead policy's arrays (coef->per_bead), interleaved as x is: 1/m_j, K_j (one vector
  // more, for vector read_hi - 1's right spring), m_j and the bounds; null for the Uniform one.
  const double *inv_mass = nullptr, *stiffness = nullptr, *mass = nullptr;
  const double *upper = nullptr, *lower = nullptr;
  // Memory the caller will touch after the step (the next segments' old state and arrays, this
  // one's new state in the chain's arrays): fetched into cache a line at a time between the step's
  // vectors, so that the copies in and out do not wait on the bus while the core idles.
  struct Ahead {
    const double* first = nullptr;
    int lines = 0;  // of 64 bytes
  };
  static constexpr int kAhead = 8;
  Ahead ahead[kAhead];
};

// What a step of segments gives back: per stage, 2 gamma times each owned tile's friction sum,
// lane after lane and tile after tile in each (chain order when the lanes are consecutive
// stretches), to be added to the stage's rate one after another as add_friction adds them; the
// spring candidates (Candidate::spring counts from 1) of the owned beads. No finite test: a
// value that is not finite stays so at its bead in every later step (x + h/6 (...) and
// v + h/6 (...) keep an inf or a NaN), and the owned beads are the same in every step, so the
// caller tests the last step's owned values only, as it copies them out (deinterleave).
struct SegmentBooks {
  std::vector<double> tile_rates[4];
  std::vector<Candidate> candidates;
};

using Rk4Segments = void (*)(const SegmentStep& in, SegmentBooks& out);
// The layout's two copies, lanes = kVec stretches of len doubles (stretch k at src + k stride):
// interleave writes dst[i * lanes + k] = src[k * stride + i]; deinterleave the reverse, and
// says whether every value it copied is finite.
using Interleave = void (*)(const double* src, std::ptrdiff_t stride, int len, double* dst);
using Deinterleave = bool (*)(const double* src, int len, double* dst, std::ptrdiff_t stride);
namespace avx2 {
void rk4_segments(const SegmentStep& in, SegmentBooks& out);
void interleave(const double* src, std::ptrdiff_t stride, int len, double* dst);
bool deinterleave(const double* src, int len, double* dst, std::ptrdiff_t stride);
}  // namespace avx2
namespace avx512 {
void rk4_segments(const SegmentStep& in, SegmentBooks& out);
void interleave(const double* src, std::ptrdiff_t stride, int len, double* dst);
bool deinterleave(const double* src, int len, double* dst, std::ptrdiff_t stride);
}  // namespace avx512
// The kernel for the path, its lanes (doubles a vector) and copies, or null (SSE2); segment:
// the beads of one lane (a multiple of kTile), chosen so that the lanes together are 32 tiles,
// 16384 beads: with 8 steps' halos (40 beads a side) the windows are ~0.54 MB, in L2. Measured
// at N = 1e7 against lanes of half and twice that length, alternated in one process
// (tests/bench/README.md, session 20). segment_per_bead: the same for the PerBead policy, half
// as long, as its three interleaved arrays would take the windows to ~0.95 MB (+2-3 %).
struct SegmentsKernel {
  Rk4Segments step = nullptr;
  int lanes = 0;
  int segment = 0;
  int segment_per_bead = 0;
  Interleave interleave = nullptr;
  Deinterleave deinterleave = nullptr;
};
SegmentsKernel rk4_segments_kernel(SimdPath path);

}  // namespace cb::detail
