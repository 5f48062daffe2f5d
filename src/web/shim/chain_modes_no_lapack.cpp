// The page without LAPACK (CHAINBREAK_WEB_LAPACK off, src/web/wasm/CMakeLists.txt): the modes of
// a chain of unequal beads or springs (exact/chain_modes.cpp) come from LAPACK's dstevr, which
// has no WebAssembly build here. The uniform chain's closed form (ExactChain, the plots' exact
// lines, the breaking map) never calls this; an unequal chain's exact solution says where to
// get it instead.
#include <stdexcept>

#include "exact/chain_modes.h"

namespace cb {

ChainModes chain_modes(const ChainParams&, int) {
  throw std::runtime_error(
      "the exact solution of a chain of unequal beads or springs needs LAPACK, which this page "
      "does not have: run `chainbreak run --solver exact` for it (the page integrates such a "
      "chain with RK4 as the program does)");
}

}  // namespace cb
