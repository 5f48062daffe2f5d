// Shared by the GL tests: a context of one backend, or a clean skip where it cannot be made.
#pragma once

#include <algorithm>
#include <catch2/catch.hpp>
#include <cstdlib>
#include <memory>
#include <string>

#include "gl/gl_context.h"
#include "output/image.h"

namespace cb::test {

// ctest sets CHAINBREAK_REQUIRE_GL=1: the install line provides both backends, so a missing
// one is a failure there, and only a skip when the test binary is run by hand elsewhere.
inline bool gl_required() {
  const char* value = std::getenv("CHAINBREAK_REQUIRE_GL");
  return value != nullptr && std::string(value) == "1";
}

// The context, or null after a WARN when it cannot be made here (a FAIL if GL is required).
inline std::unique_ptr<GlContext> create_or_skip(GlBackend backend) {
  try {
    return create_gl_context(backend);
  } catch (const GlError& error) {
    if (gl_required()) FAIL("CHAINBREAK_REQUIRE_GL=1 but: " << error.what());
    WARN("skipped, no " << gl_backend_name(backend) << " context: " << error.what());
    return nullptr;
  }
}

// The largest channel difference between pixel (x, y) and colour c (any struct with r, g, b).
template <class Rgb>
int channel_distance(const Image& image, int x, int y, const Rgb& c) {
  const std::uint8_t* p = image.pixel(x, y);
  return std::max({std::abs(p[0] - c.r), std::abs(p[1] - c.g), std::abs(p[2] - c.b)});
}

}  // namespace cb::test
