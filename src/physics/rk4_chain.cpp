#include "physics/rk4_chain.h"

namespace cb::detail {

Rk4Chain rk4_chain_kernel(SimdPath path) {
  switch (path) {
    case SimdPath::Avx512:
      return avx512::rk4_chain;
    case SimdPath::Avx2:
      return avx2::rk4_chain;
    case SimdPath::Sse2:
      break;
  }
  return sse2::rk4_chain;
}

}  // namespace cb::detail
