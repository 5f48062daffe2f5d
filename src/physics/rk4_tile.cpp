#include "physics/rk4_tile.h"

namespace cb::detail {

TileScratch::TileScratch() {
  const std::size_t n = kTile + 2 * kHalo;
  for (auto* a : {&x0, &v0, &xs, &vs, &xt, &vt, &sx, &sv, &kl, &kr, &fw, &im, &wm}) a->assign(n, 0.0);
}

Rk4Beads rk4_kernel(SimdPath path) {
  switch (path) {
    case SimdPath::Avx512:
      return avx512::rk4_beads;
    case SimdPath::Avx2:
      return avx2::rk4_beads;
    case SimdPath::Sse2:
      break;
  }
  return sse2::rk4_beads;
}

}  // namespace cb::detail
