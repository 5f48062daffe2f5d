// The one-chain RK4 kernel (rk4_chain_kernel.inc) compiled for the x86-64 baseline: no pragma,
// every x86-64 CPU runs it.
#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>
#include <vector>

#include "physics/rk4_chain.h"

namespace cb::detail::sse2 {
constexpr int kVec = 2;  // doubles a register
#include "physics/rk4_chain_kernel.inc"
}  // namespace cb::detail::sse2
