#include "physics/temporal_block.h"

#include <algorithm>
#include <cassert>
#include <cstdint>
#include <utility>

#include "physics/crossing.h"

namespace cb::detail {

namespace {

// Is a tile's step plain: every value finite and no candidate spring reaching the threshold
// inside the step (the test Integrator::advance_interval applies to the same candidates).
bool tile_is_plain(const StepInput& in, const StepOutput& out) {
  if (!out.finite) return false;
  double first = 0.0;
  return earliest_crossing(out.candidates, *in.coef, 0.0, in.h, &first) < 0;
}

// Whether no broken spring touches beads [lo, hi): spring j joins beads j - 2 and j - 1, and
// the candidates of bead i are spring i + 1.
bool window_is_intact(const std::vector<int>& broken, int lo, int hi) {
  const auto it = std::lower_bound(broken.begin(), broken.end(), lo + 1);
  return it == broken.end() || *it > hi + 1;
}

// The steps of one block [a, b) on the window kernel or the tiled one, as described in
// temporal_block.h. Returns -1, or the step found not plain.
int block_steps(Rk4Beads kernel, Rk4Window window, const StepInput& in,
                const std::vector<PlainStep>& steps, int a, int b, TileScratch& scratch,
                BlockScratch& bs) {
  const int n = in.beads;
  const int count = static_cast<int>(steps.size());
  const int reach = kHalo * count;  // how far the first step's window reaches past the block
  const int lo0 = std::max(0, a - reach), hi0 = std::min(n, b + reach);
  for (int i = 0; i < 2; ++i)
    if (bs.psi[i].size() < static_cast<std::size_t>(hi0 - lo0)) {
      bs.psi[i].resize(hi0 - lo0);
      bs.vel[i].resize(hi0 - lo0);
    }
  StepInput s = in;  // step 0 reads the chain's arrays
  for (int k = 0; k < count; ++k) {
    s.h = steps[k].h;
    std::copy(steps[k].force, steps[k].force + 3, s.force);
    const int r = kHalo * (count - 1 - k);  // what later steps still read past the block
    const int lo = std::max(0, a - r), hi = std::min(n, b + r);
    if (k == count - 1) {
      s.psi_out = in.psi_out;
      s.vel_out = in.vel_out;
      s.out_base = in.out_base;
    } else {
      s.psi_out = bs.psi[k % 2].data();
      s.vel_out = bs.vel[k % 2].data();
      s.out_base = lo0;
    }
    StepOutput& sum = bs.steps[k];
    // The wavefront kernel, where no broken spring is near: the halo and the block in one
    // call, the block's books added straight into this step's sums (tile by tile, as
    // below); the candidates are only looked at, as tile_is_plain does.
    if (window && window_is_intact(*in.broken, std::max(0, lo - kHalo), std::min(n, hi + kHalo))) {
      window(s, lo, hi, a, b, sum);
      if (!tile_is_plain(s, sum)) return k;
      sum.candidates.clear();
      s.psi = s.psi_out;
      s.vel = s.vel_out;
      s.base = s.out_base;
      continue;
    }
    // The halo: values the neighbouring block computes (and checks) too.
    if (lo < a) {
      bs.halo.reset();
      kernel(s, lo, a, scratch, bs.halo);
    }
    if (b < hi) {
      bs.halo.reset();
      kernel(s, b, hi, scratch, bs.halo);
    }
    // The block's own tiles, one kernel call each: the same tiles, and the same sums in
    // the same order, as the one-step path's call over the worker's range.
    for (int t = a; t < b; t += kTile) {
      bs.tile.reset();
      kernel(s, t, std::min(b, t + kTile), scratch, bs.tile);
      if (!tile_is_plain(s, bs.tile)) return k;
      for (int st = 0; st < 4; ++st) {
        sum.dissipation_rate[st] += bs.tile.dissipation_rate[st];
        // Set by the one tile that holds bead N, zero from the others.
        if (t <= n - 1 && n - 1 < t + kTile) sum.end_velocity[st] = bs.tile.end_velocity[st];
      }
    }
    s.psi = s.psi_out;
    s.vel = s.vel_out;
    s.base = s.out_base;
  }
  return -1;
}

// A 64-byte aligned view of `buffer` with room for `size` doubles.
double* aligned_room(std::vector<double>& buffer, std::size_t size) {
  if (buffer.size() < size + 8) buffer.resize(size + 8);
  const auto address = reinterpret_cast<std::uintptr_t>(buffer.data());
  return buffer.data() + ((64 - address % 64) % 64) / sizeof(double);
}

// The steps of the beads [a, a + lanes * seg) as `lanes` segments of seg beads side by side
// (rk4_segments.h), each in a window reach beads wider a side, which must lie in the chain and
// touch no broken spring. Returns -1, or the step found not plain.
int segment_steps(SegmentsKernel segments, const StepInput& in, const std::vector<PlainStep>& steps,
                  int a, int seg, int next, BlockScratch& bs) {
  const int count = static_cast<int>(steps.size());
  const int lanes = segments.lanes;
  const int reach = kHalo * count;
  const int len = seg + 2 * reach;  // vectors of each lane's window: bead a + k seg - reach + i
  const std::size_t size = static_cast<std::size_t>(len) * lanes;
  double* x[2] = {aligned_room(bs.lanes_psi[0], size), aligned_room(bs.lanes_psi[1], size)};
  double* v[2] = {aligned_room(bs.lanes_vel[0], size), aligned_room(bs.lanes_vel[1], size)};
  // Interleaved: lane k of vector i.
  segments.interleave(in.psi + (a - reach - in.base), seg, len, x[0]);
  segments.interleave(in.vel + (a - reach - in.base), seg, len, v[0]);
  StepInput s_in = in;  // for the crossing test: the step's h
  SegmentStep s;
  s.origin = a - reach;
  s.stride = seg;
  s.gamma = in.gamma;
  s.coef = in.coef;
  s.own_lo = reach;
  s.own_hi = reach + seg;
  // The PerBead arrays (1/m, K with one more for the last vector's right spring, m, the bounds
  // when springs are checked), interleaved once for every step.
  const ChainCoefficients& coef = *in.coef;
  const double* arrays[5] = {};
  if (coef.per_bead) {
    const double* chain[5] = {coef.inv_mass.data(), coef.stiffness.data(), coef.mass.data(),
                              coef.upper.data(), coef.lower.data()};
    for (int i = 0; i < (coef.checks ? 5 : 3); ++i) {
      const int extra = i == 1 ? 1 : 0;
      double* to = aligned_room(bs.lanes_coef[i], size + extra * lanes);
      segments.interleave(chain[i] + (a - reach), seg, len + extra, to);
      arrays[i] = to;
    }
  }
  s.inv_mass = arrays[0], s.stiffness = arrays[1], s.mass = arrays[2];
  s.upper = arrays[3], s.lower = arrays[4];
  // What the caller touches next, in cache lines: the next stretch's old state and arrays
  // (`next` beads from a + lanes seg - reach) and this one's new state; a count-th of each a
  // step.
  const auto lines = [](int beads) { return (beads * 8 + 63) / 64; };
  const int from = a + lanes * seg - reach;
  const int more = coef.per_bead ? next : 0;
  const SegmentStep::Ahead touch[SegmentStep::kAhead] = {
      {in.psi + (from - in.base), lines(next)},
      {in.vel + (from - in.base), lines(next)},
      {in.psi_out + (a - in.out_base), lines(lanes * seg)},
      {in.vel_out + (a - in.out_base), lines(lanes * seg)},
      {coef.per_bead ? coef.inv_mass.data() + from : nullptr, lines(more)},
      {coef.per_bead ? coef.stiffness.data() + from : nullptr, lines(more)},
      {coef.per_bead ? coef.mass.data() + from : nullptr, lines(more)},
      {}};
  for (int k = 0; k < count; ++k) {
    for (int i = 0; i < SegmentStep::kAhead; ++i) {
      const int share = (touch[i].lines + count - 1) / count;
      const int first = std::min(touch[i].lines, k * share);
      s.ahead[i] = {touch[i].first + first * 8, std::min(touch[i].lines, first + share) - first};
    }
    s.h = s_in.h = steps[k].h;
    const int r = kHalo * (count - 1 - k);  // what later steps still read past the segment
    s.write_lo = reach - r;
    s.write_hi = reach + seg + r;
    s.read_lo = s.write_lo - kHalo;
    s.read_hi = s.write_hi + kHalo;
    s.x = x[k % 2];
    s.v = v[k % 2];
    s.x_out = x[(k + 1) % 2];
    s.v_out = v[(k + 1) % 2];
    segments.step(s, bs.lanes_books);
    StepOutput& sum = bs.steps[k];
    std::swap(sum.candidates, bs.lanes_books.candidates);
    if (!tile_is_plain(s_in, sum)) return k;
    sum.candidates.clear();
    // Each tile's friction in chain order, as the window kernel adds them.
    if (in.gamma > 0.0)
      for (int st = 0; st < 4; ++st)
        for (double rate : bs.lanes_books.tile_rates[st]) sum.dissipation_rate[st] += rate;
  }
  // The finite test of every step, on the last one (SegmentBooks says why).
  const double* xn = x[count % 2];
  const double* vn = v[count % 2];
  const bool x_finite =
      segments.deinterleave(xn + reach * lanes, seg, in.psi_out + (a - in.out_base), seg);
  const bool v_finite =
      segments.deinterleave(vn + reach * lanes, seg, in.vel_out + (a - in.out_base), seg);
  return x_finite && v_finite ? -1 : count - 1;
}

}  // namespace

int rk4_blocked(Rk4Beads kernel, Rk4Window window, SegmentsKernel segments, const StepInput& in,
                const std::vector<PlainStep>& steps, int first, int last, TileScratch& scratch,
                BlockScratch& bs, std::atomic<bool>& abort) {
  const int n = in.beads;
  const int count = static_cast<int>(steps.size());
  assert(count >= 2 && first % kTile == 0);
  const int reach = kHalo * count;
  bs.steps.resize(count);
  for (StepOutput& o : bs.steps) o.reset();
  // Segments: where the window kernel would run on every lane's window (not the weighted chain,
  // which takes the tiled kernel everywhere).
  const bool plain_policy = in.coef->weight == 0.0;
  const int seg = in.coef->per_bead ? segments.segment_per_bead : segments.segment;
  const int group = segments.lanes * seg;
  for (int a = first; a < last;) {
    if (abort.load(std::memory_order_relaxed)) return count;
    int failed;
    if (window && segments.step && plain_policy && a + group <= last && a - reach >= 0 &&
        a + group + reach <= n && window_is_intact(*in.broken, a - reach, a + group + reach)) {
      // The next stretch's window, as far as it lies in the chain (for the prefetches).
      const int next = std::max(0, std::min(group + 2 * reach, n - (a + group - reach)));
      failed = segment_steps(segments, in, steps, a, seg, next, bs);
      a += group;
    } else {
      const int b = std::min(last, a + kBlockTiles * kTile);
      failed = block_steps(kernel, window, in, steps, a, b, scratch, bs);
      a = b;
    }
    if (failed >= 0) {
      abort.store(true, std::memory_order_relaxed);
      return failed;
    }
  }
  return -1;
}

}  // namespace cb::detail
