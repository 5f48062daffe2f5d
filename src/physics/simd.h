// Which instruction set the fused RK4 kernel runs on: chosen once per process from cpuid, or
// forced with CHAINBREAK_SIMD=auto|sse2|avx2|avx512.
//
// Design note: one binary serves every x86-64 machine. The kernel is compiled once per
// instruction set (rk4_tile_*.cpp) and picked here at run time; all paths give bit-identical
// results (see rk4_tile_kernel.inc), so the choice changes speed, never numbers.
#pragma once

#include <stdexcept>
#include <string>

namespace cb {

enum class SimdPath { Sse2, Avx2, Avx512 };

// "sse2", "avx2", "avx512": the name CHAINBREAK_SIMD takes and the JSON outputs report.
const char* simd_name(SimdPath path);

// Whether this CPU (and its operating system) can run the path.
bool simd_supported(SimdPath path);

// The widest path this CPU supports.
SimdPath widest_simd();

// A CHAINBREAK_SIMD value the user can fix: an unknown name or an ISA this CPU lacks.
struct SimdChoiceError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The path for a CHAINBREAK_SIMD value (null or "" or "auto": the widest supported).
// Throws SimdChoiceError with what, where and how to fix.
SimdPath simd_from_setting(const char* value);

// The process's path: CHAINBREAK_SIMD read on the first call (which may throw
// SimdChoiceError; the command line calls it at start-up so a bad value exits at once).
SimdPath active_simd();

// Of a kernel's three builds (the baseline's, AVX2's, AVX-512's), the one for `path`: the one
// switch every dispatch goes through (a path without a build of its own passes nullptr or {}).
template <class Kernel>
Kernel by_simd(SimdPath path, Kernel sse2, Kernel avx2, Kernel avx512) {
  switch (path) {
    case SimdPath::Avx512:
      return avx512;
    case SimdPath::Avx2:
      return avx2;
    case SimdPath::Sse2:
      break;
  }
  return sse2;
}

}  // namespace cb
