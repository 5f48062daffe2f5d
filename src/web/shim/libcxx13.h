// What Emscripten 3.1.6's libc++ 13 lacks of C++20 and the program's sources use
// (PLATFORM-NOTES.md): std::bit_cast, and std::to_chars for a double (shortest round trip).
// Force-included into every file of the page's build (src/web/wasm/CMakeLists.txt), so the
// program's sources compile unchanged. A newer libc++ has both and this adds nothing.
#pragma once

#include <version>

#if defined(__cplusplus) && defined(_LIBCPP_VERSION) && _LIBCPP_VERSION < 14000
#include <charconv>
#include <cstdio>
#include <cstdlib>
#include <type_traits>

namespace std {

#if !defined(__cpp_lib_bit_cast)
template <class To, class From>
requires(sizeof(To) == sizeof(From) && is_trivially_copyable_v<To> &&
         is_trivially_copyable_v<From>) constexpr To bit_cast(const From& from) noexcept {
  return __builtin_bit_cast(To, from);
}
#endif

// The shortest "%.Pg" that reads back as the same double. std::to_chars picks the shorter of
// fixed and scientific notation instead, so a few numbers are spelled differently (1e+20 for
// 100000000000000000000): they only appear in messages and text, never in the physics.
inline to_chars_result to_chars(char* first, char* last, double value) {
  char buf[32];
  int n = 0;
  for (int precision = 1; precision <= 17; ++precision) {
    n = snprintf(buf, sizeof buf, "%.*g", precision, value);
    if (strtod(buf, nullptr) == value || value != value) break;
  }
  if (n < 0 || n > last - first) return {last, errc::value_too_large};
  for (int i = 0; i < n; ++i) first[i] = buf[i];
  return {first + n, errc{}};
}

}  // namespace std
#endif
