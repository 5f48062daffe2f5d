// What the libFuzzer harnesses share (tests/fuzz/README.md says how to build and run them).
//
// A harness feeds one input to one of the parsers a user's text reaches and lets through only
// the errors that parser documents for bad input (SceneError, DriveError): anything else that
// escapes, a crash, a sanitizer report, a hang or a broken invariant (FUZZ_CHECK) is a finding.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

// An invariant of a parser's result; a violation aborts, which libFuzzer reports as a crash
// and saves the input.
#define FUZZ_CHECK(condition)                                                                  \
  do {                                                                                         \
    if (!(condition)) {                                                                        \
      std::fprintf(stderr, "FUZZ_CHECK failed: %s (%s:%d)\n", #condition, __FILE__, __LINE__); \
      std::abort();                                                                            \
    }                                                                                          \
  } while (false)

namespace cb::fuzz {

inline std::string text_of(const std::uint8_t* data, std::size_t size) {
  return std::string(reinterpret_cast<const char*>(data), size);
}

// A valid scene the override harness changes (the tests' kBase, tests/scene_test_support.h).
inline const char* const kBaseScene =
    "[chain]\nbeads = 30\ngamma = 0.0\nthreshold = 1.0\n[drive]\ntype = \"ramp\"\n"
    "beta = 0.02\n[integrator]\ndt = 0.01\nt_end = 400.0\n";

}  // namespace cb::fuzz
