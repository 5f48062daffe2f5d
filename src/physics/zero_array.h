// Internal: the chain's large arrays (psi, vel and their next-step copies), zeroed.
//
// Design note: at N = 1e7 each array is 80 MB, and first touching it in 4 KiB pages cost
// ~20k page faults an array, most of `chainbreak run`'s fixed cost at that size (issue #13:
// ~1 s of the run's 2.3 s with 4 such arrays). An array this large asks the kernel for
// transparent huge pages (madvise, Linux; elsewhere a plain vector), so it faults in 2 MiB at
// a time. The values are the same zeros either way: only the page size changes.
#pragma once

#include <cstddef>
#include <vector>

namespace cb::detail {

// n zeros; from kHugeArrayBytes on, backed by huge pages where the kernel allows them.
std::vector<double> zero_array(std::size_t n);

inline constexpr std::size_t kHugeArrayBytes = std::size_t{4} << 20;  // two huge pages

}  // namespace cb::detail
