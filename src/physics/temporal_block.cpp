#include "physics/temporal_block.h"

#include <algorithm>
#include <cassert>

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

}  // namespace

int rk4_blocked(Rk4Beads kernel, Rk4Window window, const StepInput& in,
                const std::vector<PlainStep>& steps, int first, int last, TileScratch& scratch,
                BlockScratch& bs, std::atomic<bool>& abort) {
  const int n = in.beads;
  const int count = static_cast<int>(steps.size());
  assert(count >= 2 && first % kTile == 0);
  const int reach = kHalo * count;  // how far the first step's window reaches past the block
  bs.steps.resize(count);
  for (StepOutput& o : bs.steps) o.reset();
  for (int a = first; a < last; a += kBlockTiles * kTile) {
    if (abort.load(std::memory_order_relaxed)) return count;
    const int b = std::min(last, a + kBlockTiles * kTile);
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
      if (window &&
          window_is_intact(*in.broken, std::max(0, lo - kHalo), std::min(n, hi + kHalo))) {
        window(s, lo, hi, a, b, sum);
        if (!tile_is_plain(s, sum)) {
          abort.store(true, std::memory_order_relaxed);
          return k;
        }
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
        if (!tile_is_plain(s, bs.tile)) {
          abort.store(true, std::memory_order_relaxed);
          return k;
        }
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
  }
  return -1;
}

}  // namespace cb::detail
