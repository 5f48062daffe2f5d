#include "physics/zero_array.h"

#include <cstdint>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace cb::detail {

namespace {

// Asks for huge pages on the whole 2 MiB pages inside [data, data + bytes), before anything
// touches them (a page already faulted in stays small). Only a hint: if the kernel says no
// (transparent_hugepage = never, or not Linux), the array is the same, in small pages.
void advise_huge_pages([[maybe_unused]] void* data, [[maybe_unused]] std::size_t bytes) {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  constexpr std::uintptr_t kHuge = std::uintptr_t{2} << 20;
  const auto begin = reinterpret_cast<std::uintptr_t>(data);
  const std::uintptr_t first = (begin + kHuge - 1) & ~(kHuge - 1);
  const std::uintptr_t last = (begin + bytes) & ~(kHuge - 1);
  if (last > first) madvise(reinterpret_cast<void*>(first), last - first, MADV_HUGEPAGE);
#endif
}

}  // namespace

std::vector<double> zero_array(std::size_t n) {
  std::vector<double> v;
  if (n * sizeof(double) >= kHugeArrayBytes) {
    v.reserve(n);  // allocated, not yet touched
    advise_huge_pages(v.data(), n * sizeof(double));
  }
  v.assign(n, 0.0);
  return v;
}

}  // namespace cb::detail
