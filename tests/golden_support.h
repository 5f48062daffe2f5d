// Shared by the golden tests (test_golden.cpp: frames; test_figures_gl.cpp: figures): an
// image compared with tests/golden/<name>.png within the stated tolerance, or written there
// on purpose with CHAINBREAK_UPDATE_GOLDENS=1 (tests/golden/README.md).
#pragma once

#include <catch2/catch.hpp>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "gl/gl_context.h"
#include "output/image.h"
#include "output/png_writer.h"

namespace cb::test {

// The tolerance. Physics and snapshot are bit-reproducible (-ffp-contract=off) and llvmpipe
// rasterises in fixed point, so on the machine that made them the frames match exactly, on
// OSMesa and EGL alike. Another CPU changes the code llvmpipe generates (vector width, FMA),
// which moves shading and antialiased edges by a step or two: allow 2 per channel
// everywhere, and more on 0.1% of the pixels (130 of 480x270, 960 of a 1200x800 figure),
// where a vertex rounds to the other side of a pixel centre. That catches a wrong colour map,
// a moved chain, curve, panel or label, a lost label or arrow; not one small bead (~50 px at
// 480x270): the exact-pixel tests in test_render.cpp and the snapshot tests cover single
// shapes.
constexpr int kGoldenChannelTolerance = 2;
constexpr double kGoldenMaxFractionOver = 0.001;

inline bool env_is_1(const char* name) {
  const char* value = std::getenv(name);
  return value != nullptr && std::string(value) == "1";
}

inline std::filesystem::path golden_dir() {
  return std::filesystem::path(__FILE__).parent_path() / "golden";
}

// Beside the test binary (build/tests/golden-actual), whatever the working directory.
inline std::filesystem::path golden_actual_dir() {
  std::error_code error;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", error);
  return (error ? std::filesystem::current_path() : exe.parent_path()) / "golden-actual";
}

// Compares with tests/golden/NAME.png (NAME may hold a folder: figures/fig4a); on failure
// writes the image to golden-actual/NAME.SOURCE.png for a human to look at. With
// CHAINBREAK_UPDATE_GOLDENS=1 an image that `may_update` becomes the golden.
inline void check_golden_image(const std::string& name, const std::string& source, bool may_update,
                               const Image& actual) {
  namespace fs = std::filesystem;
  const fs::path golden = golden_dir() / (name + ".png");
  if (env_is_1("CHAINBREAK_UPDATE_GOLDENS") && may_update) {
    fs::create_directories(golden.parent_path());
    write_png(golden.string(), actual);
    WARN("wrote " << golden.string() << ": inspect it before committing");
    return;
  }
  if (!fs::exists(golden))
    FAIL(golden.string() << " is missing; make it with CHAINBREAK_UPDATE_GOLDENS=1 "
                            "(tests/golden/README.md)");
  const ImageDiff d = compare_images(actual, read_png(golden.string()), kGoldenChannelTolerance);
  const bool ok = d.same_size && d.fraction_over <= kGoldenMaxFractionOver;
  std::string written;
  if (!ok) {
    const fs::path out = golden_actual_dir() / (name + "." + source + ".png");
    fs::create_directories(out.parent_path());
    written = out.string();
    write_png(written, actual);
  }
  INFO(name << " (" << source << "): max channel difference " << d.max_channel << ", "
            << 100.0 * d.fraction_over << "% of pixels over " << kGoldenChannelTolerance
            << " (allowed " << 100.0 * kGoldenMaxFractionOver << "%)"
            << (d.same_size ? "" : ", sizes differ") << (ok ? "" : "; actual image: " + written));
  CHECK(ok);
}

// A GL frame: the OSMesa image becomes the golden on an update.
inline void check_golden(const std::string& name, GlBackend backend, const Image& actual) {
  check_golden_image(name, gl_backend_name(backend), backend == GlBackend::OSMesa, actual);
}

}  // namespace cb::test
