#include "physics/rk4_tile.h"

#include "physics/simd.h"

namespace cb::detail {

TileScratch::TileScratch() {
  const std::size_t n = kTile + 2 * kHalo;
  for (auto* a : {&x0, &v0, &xs, &vs, &xt, &vt, &sx, &sv, &kl, &kr, &fw, &im, &wm, &q})
    a->assign(n, 0.0);
}

Rk4Beads rk4_kernel(SimdPath path) {
  return by_simd<Rk4Beads>(path, sse2::rk4_beads, avx2::rk4_beads, avx512::rk4_beads);
}

}  // namespace cb::detail
