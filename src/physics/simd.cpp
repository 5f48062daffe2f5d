#include "physics/simd.h"

#include <cstdlib>
#include <string_view>

namespace cb {

const char* simd_name(SimdPath path) {
  switch (path) {
    case SimdPath::Sse2:
      return "sse2";
    case SimdPath::Avx2:
      return "avx2";
    case SimdPath::Avx512:
      return "avx512";
  }
  return "sse2";
}

bool simd_supported(SimdPath path) {
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
  // __builtin_cpu_supports also checks that the OS saves the wider registers (XCR0).
  switch (path) {
    case SimdPath::Sse2:
      return true;
    case SimdPath::Avx2:
      // The AVX2 kernels use FMA3 too (stencil.inc's fmadd); every AVX2 CPU has it.
      return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
    case SimdPath::Avx512:
      return __builtin_cpu_supports("avx512f");
  }
#endif
  return path == SimdPath::Sse2;
}

SimdPath widest_simd() {
  for (SimdPath p : {SimdPath::Avx512, SimdPath::Avx2})
    if (simd_supported(p)) return p;
  return SimdPath::Sse2;
}

SimdPath simd_from_setting(const char* value) {
  const std::string_view v = value ? value : "";
  if (v.empty() || v == "auto") return widest_simd();
  for (SimdPath p : {SimdPath::Sse2, SimdPath::Avx2, SimdPath::Avx512}) {
    if (v != simd_name(p)) continue;
    if (!simd_supported(p))
      throw SimdChoiceError("CHAINBREAK_SIMD=" + std::string(v) + ": this CPU has no " +
                            std::string(v) + "; use auto (here: " + simd_name(widest_simd()) +
                            ") or a narrower one");
    return p;
  }
  throw SimdChoiceError("CHAINBREAK_SIMD=" + std::string(v) +
                        ": expected auto, sse2, avx2 or avx512");
}

SimdPath active_simd() {
  static const SimdPath path = simd_from_setting(std::getenv("CHAINBREAK_SIMD"));
  return path;
}

}  // namespace cb
