// The overlay drawn with GL (both backends; skipped with a warning where a backend is
// missing, unless CHAINBREAK_REQUIRE_GL=1): a frame drawn twice is byte-identical, the overlay
// switched off leaves the renderer's pixels alone, plotted data land on the pixels the plot's
// mapping gives, a missing font names its package; and the overlay's cost at 1080p.
#include <unistd.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <memory>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "exact/exact_chain.h"
#include "gl/gl_context.h"
#include "gl_test_support.h"
#include "output/png_writer.h"
#include "overlay/modes.h"
#include "overlay/overlay.h"
#include "overlay/overlay_history.h"
#include "overlay/overlay_layout.h"
#include "overlay_test_support.h"
#include "physics/energy.h"
#include "physics/integrator.h"
#include "render/renderer.h"
#include "scene/scene.h"
#include "snapshot/snapshot.h"

using namespace cb::overlay_test;

// ---- GL ------------------------------------------------------------------------------------

namespace {

// A frame of the default scene's chain (N = 30, ramp 0.02, phi_c = 3) at frame `k` of a
// 0.5-tau-per-frame video, its overlay recorded over frames 0..k.
cb::Image draw(cb::Renderer& renderer, cb::Overlay* overlay, const cb::RenderSnapshot& snap) {
  renderer.draw(snap);
  if (overlay) overlay->draw(snap);
  cb::Image image;
  renderer.read(image);
  return image;
}

using cb::test::channel_distance;

}  // namespace

TEST_CASE("Overlay GL: the same frame twice is byte-identical, whatever came between",
          "[overlay]") {
  const cb::GlBackend backend = GENERATE(cb::GlBackend::OSMesa, cb::GlBackend::Egl);
  INFO("backend " << cb::gl_backend_name(backend));
  auto context = cb::test::create_or_skip(backend);
  if (!context) return;
  const Video video(1280, 720);
  const auto frames = video.frames(320);  // to tau = 159.5: past the first break (~150)
  cb::Renderer renderer(1280, 720);
  cb::Overlay overlay(1280, 720, 30.0, cb::OverlaySwitches{});
  const cb::Image a = draw(renderer, &overlay, frames[200]);
  const cb::Image b = draw(renderer, &overlay, frames.back());
  const cb::Image again = draw(renderer, &overlay, frames[200]);
  CHECK(cb::compare_images(a, again, 0).max_channel == 0);
  CHECK(cb::compare_images(a, b, 0).max_channel > 0);  // and the frames do differ
  // A second overlay (its own ImGui context) draws the same pixels.
  cb::Overlay other(1280, 720, 30.0, cb::OverlaySwitches{});
  CHECK(cb::compare_images(a, draw(renderer, &other, frames[200]), 0).max_channel == 0);
}

TEST_CASE("Overlay GL: switched off, the renderer's pixels are untouched", "[overlay]") {
  const cb::GlBackend backend = GENERATE(cb::GlBackend::OSMesa, cb::GlBackend::Egl);
  INFO("backend " << cb::gl_backend_name(backend));
  auto context = cb::test::create_or_skip(backend);
  if (!context) return;
  const Video video(1280, 720);
  const auto frames = video.frames(40);
  cb::Renderer renderer(1280, 720);
  const cb::Image plain = renderer.render(frames.back());
  // Every part off: no layout, nothing drawn.
  cb::Overlay off(1280, 720, 30.0, cb::OverlaySwitches{false, false, false, false});
  CHECK_FALSE(off.layout().enabled);
  CHECK(cb::compare_images(plain, draw(renderer, &off, frames.back()), 0).max_channel == 0);
  // A snapshot without overlay data: nothing drawn either.
  cb::Overlay on(1280, 720, 30.0, cb::OverlaySwitches{});
  cb::RenderSnapshot bare = frames.back();
  bare.overlay.reset();
  CHECK(cb::compare_images(plain, draw(renderer, &on, bare), 0).max_channel == 0);
  // And with data the overlay does draw, below the chain's band only.
  const cb::Image with = draw(renderer, &on, frames.back());
  const cb::ImageDiff diff = cb::compare_images(plain, with, 0);
  CHECK(diff.max_channel > 0);
  for (int y = 0; y < on.layout().chain_height; y += 7)
    for (int x = 0; x < 1280; x += 7)
      REQUIRE(std::equal(plain.pixel(x, y), plain.pixel(x, y) + 4, with.pixel(x, y)));
}

TEST_CASE("Overlay GL: plotted data land on the pixels the plot's mapping gives", "[overlay]") {
  const cb::GlBackend backend = GENERATE(cb::GlBackend::OSMesa, cb::GlBackend::Egl);
  INFO("backend " << cb::gl_backend_name(backend));
  auto context = cb::test::create_or_skip(backend);
  if (!context) return;
  constexpr int kW = 1280, kH = 720;
  const cb::OverlaySwitches all;
  cb::Overlay overlay(kW, kH, 30.0, all);
  const cb::OverlayLayout& l = overlay.layout();
  REQUIRE(l.enabled);

  // Hand-made data, half-way through a 100-tau video: three well separated curves (points at
  // 0, 1, 2; phi_1's exact line at -0.5, clear of its points) and a space-time ramp.
  auto d = std::make_shared<cb::OverlayData>();
  d->beads = 30;
  d->tau = 60.0;
  d->tau_end = 100.0;
  d->tau_per_frame = 1.0;
  d->phi_lo = -1.0;
  d->phi_hi = 3.0;
  d->spring_count = 3;
  d->springs[0] = 1;
  d->springs[1] = 15;
  d->springs[2] = 30;
  d->exact = true;
  d->spacetime_columns = 30;
  for (int k = 0; k <= 60; ++k) {
    d->history_tau.push_back(k);
    for (int s = 0; s < 3; ++s) d->phi[s].push_back(s);
    d->energy_total.push_back(0.0);
    d->energy_kinetic.push_back(0.0);
    d->energy_potential.push_back(0.0);
    d->exact_tau.push_back(k);
    d->exact_phi[0].push_back(-0.5);
    d->exact_phi[1].push_back(1.0);
    d->exact_phi[2].push_back(2.0);
    d->spacetime_tau.push_back(k);
    for (int c = 0; c < 30; ++c) d->spacetime.push_back(static_cast<float>((c - 15) / 15.0));
  }
  cb::RenderSnapshot snap;
  snap.width = kW;
  snap.height = kH;
  snap.background = cb::Color{0.09f, 0.094f, 0.11f, 1.0f};
  snap.layers.resize(cb::kLayerCount);
  snap.overlay = d;
  cb::Renderer renderer(kW, kH);
  const cb::Image image = draw(renderer, &overlay, snap);

  // The newest phi_N point (drawn last, an opaque disc): its centre pixel has its colour exactly.
  const cb::PlotMapping phi = cb::phi_mapping(l, *d);
  const int px = static_cast<int>(std::floor(phi.px(60.0)));
  const int py = static_cast<int>(std::floor(phi.py(2.0)));
  INFO("phi_N point at (" << px << ", " << py << ")");
  CHECK(channel_distance(image, px, py, cb::theme(cb::ThemeName::Dark).series[2]) == 0);
  CHECK(channel_distance(image, px, py - 12, cb::theme(cb::ThemeName::Dark).series[2]) > 60);  // and a point only

  // phi_1's exact line at -0.5 passes through its pixel: an antialiased line 2 px wide in its
  // colour at kOverlayExactLineAlpha over the background, so within a pixel of the mapped row
  // some pixel is close to that blend (the edges are lighter); 5 px away, the background.
  const auto blend = [](std::uint8_t line, std::uint8_t back) {
    return static_cast<std::uint8_t>(std::lround(cb::kOverlayExactLineAlpha * line +
                                                 (1.0f - cb::kOverlayExactLineAlpha) * back));
  };
  const cb::OverlayRgb s0 = cb::theme(cb::ThemeName::Dark).series[0], bg = cb::theme(cb::ThemeName::Dark).background;
  const cb::OverlayRgb line{blend(s0.r, bg.r), blend(s0.g, bg.g), blend(s0.b, bg.b)};
  const int lx = static_cast<int>(std::floor(phi.px(30.5)));
  const int ly = static_cast<int>(std::floor(phi.py(-0.5)));
  int nearest = 255;
  for (int y = ly - 1; y <= ly + 1; ++y)
    nearest = std::min(nearest, channel_distance(image, lx, y, line));
  INFO("exact line near (" << lx << ", " << ly << ")");
  CHECK(nearest <= 12);
  CHECK(channel_distance(image, lx, ly - 5, bg) == 0);
  CHECK(channel_distance(image, lx, ly + 5, bg) == 0);

  // The space-time picture: the cell of spring c + 1 at row r, through its texel, exactly.
  const cb::PlotMapping st = cb::spacetime_mapping(l, *d);
  for (auto [c, r] : {std::pair{4, 30}, {15, 10}, {27, 55}}) {
    const int x = static_cast<int>(std::floor(st.px(c + 0.5)));
    const int y = static_cast<int>(std::floor(st.py(r)));
    INFO("space-time cell " << c << ", " << r << " at (" << x << ", " << y << ")");
    CHECK(channel_distance(image, x, y, cb::overlay_strain_rgb((c - 15) / 15.0f, cb::ThemeName::Dark)) == 0);
  }
}

TEST_CASE("Overlay GL: the HUD's first break stands out behind an accent bar, later ones muted",
          "[overlay]") {
  auto context = cb::test::create_or_skip(cb::GlBackend::Auto);
  if (!context) return;
  constexpr int kW = 1280, kH = 720;
  cb::Overlay overlay(kW, kH, 30.0, cb::OverlaySwitches{});
  const cb::OverlayLayout& l = overlay.layout();
  REQUIRE(l.enabled);
  const cb::Theme& t = cb::theme(cb::ThemeName::Dark);
  // Pixels of the HUD within 10 per channel of a colour.
  const auto count = [&](const cb::Image& image, const cb::OverlayRgb& c) {
    int n = 0;
    for (int y = static_cast<int>(l.hud.y); y < static_cast<int>(l.hud.bottom()); ++y)
      for (int x = static_cast<int>(l.hud.x); x < static_cast<int>(l.hud.right()); ++x)
        n += channel_distance(image, x, y, c) <= 10;
    return n;
  };
  cb::Renderer renderer(kW, kH);
  const auto frame = [&](std::vector<cb::OverlayBreak> breaks) {
    auto d = std::make_shared<cb::OverlayData>();
    d->beads = 30;
    d->tau = 50.0;
    d->tau_end = 100.0;
    d->breaks = std::move(breaks);
    cb::RenderSnapshot snap;
    snap.width = kW;
    snap.height = kH;
    snap.background = cb::Color{0.09f, 0.094f, 0.11f, 1.0f};
    snap.layers.resize(cb::kLayerCount);
    snap.overlay = d;
    return draw(renderer, &overlay, snap);
  };
  const cb::Image none = frame({});
  const cb::Image three = frame({{30, 31.0}, {10, 45.41}, {9, 45.44}});
  CHECK(count(none, t.accent) == 0);
  // The bar: 0.3 x 0.9 of the font size, about 4 x 13 px at 720p, opaque.
  CHECK(count(three, t.accent) >= 30);
  // The later breaks are muted, in the secondary text colour (a grey), not the marker's amber:
  // the only warm pixels (red well above blue) are the bar's.
  const auto warm = [&](const cb::Image& image) {
    int n = 0;
    for (int y = static_cast<int>(l.hud.y); y < static_cast<int>(l.hud.bottom()); ++y)
      for (int x = static_cast<int>(l.hud.x); x < static_cast<int>(l.hud.right()); ++x) {
        const std::uint8_t* p = image.pixel(x, y);
        n += int(p[0]) - int(p[2]) > 60;
      }
    return n;
  };
  const double fs = l.font_px;
  CHECK(warm(none) == 0);
  CHECK(warm(three) <= (std::ceil(0.3 * fs) + 2) * (std::ceil(0.9 * fs) + 2));
  CHECK(count(three, t.marker) == 0);
}

TEST_CASE("Overlay: a missing font names the package to install", "[overlay]") {
  auto context = cb::test::create_or_skip(cb::GlBackend::Auto);
  if (!context) return;
  ::setenv("CHAINBREAK_FONT_DIR", "/nonexistent-chainbreak-fonts", 1);
  std::string message;
  try {
    cb::Overlay overlay(1280, 720, 30.0, cb::OverlaySwitches{});
  } catch (const std::runtime_error& e) {
    message = e.what();
  }
  ::unsetenv("CHAINBREAK_FONT_DIR");
  CHECK(message.find("fonts-dejavu-core") != std::string::npos);
  CHECK(message.find("/nonexistent-chainbreak-fonts/DejaVuSans.ttf") != std::string::npos);
  cb::Overlay fine(1280, 720, 30.0, cb::OverlaySwitches{});  // and nothing was left behind
  CHECK(fine.layout().enabled);
}

TEST_CASE("render --no-overlay draws the chain alone, exactly as without the overlay",
          "[overlay]") {
  // A frame of a render equals a snapshot at its tau (same state, same layout: see
  // test_render_cli.cpp); at 640x360 the overlay is on by default, so only --no-overlay
  // (or overlay = false) keeps that equality, pixel for pixel.
  if (!cb::test::create_or_skip(cb::GlBackend::Auto)) return;  // the child processes make their own
  namespace fs = std::filesystem;
  const fs::path dir =
      fs::temp_directory_path() / ("chainbreak-overlay-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  for (const char* sub : {"off", "on", "snap"}) fs::create_directories(dir / sub);
  const std::string exe = CHAINBREAK_EXE,
                    scene = std::string(CHAINBREAK_SCENES) + "/ramp_pulled_end.toml";
  const std::string common = " --size 640x360 --set integrator.t_end=24";
  const auto run = [](const std::string& command) {
    return std::system((command + " >/dev/null 2>&1").c_str());
  };
  REQUIRE(run(exe + " render " + scene + " --frames " + (dir / "off").string() + common +
              " --fps 30 --speed 30 --quiet --no-overlay") == 0);
  REQUIRE(run(exe + " render " + scene + " --frames " + (dir / "on").string() + common +
              " --fps 30 --speed 30 --quiet") == 0);
  REQUIRE(run(exe + " snapshot " + scene + " --at 24 -o " + (dir / "snap").string() + common) == 0);
  const cb::Image snap =
      cb::read_png((dir / "snap" / "ramp_pulled_end_tau_000024.000.png").string());
  const cb::Image off = cb::read_png((dir / "off" / "ramp_pulled_end_000024.png").string());
  const cb::Image on = cb::read_png((dir / "on" / "ramp_pulled_end_000024.png").string());
  CHECK(cb::compare_images(off, snap, 0).max_channel == 0);
  CHECK(cb::compare_images(on, snap, 0).max_channel > 0);
  fs::remove_all(dir);
}

// The overlay's cost at 1080p: median frame time (draw + read back) of 50 frames of the default
// scene, with and without the overlay, and the producer's recording per frame. Not a check:
// run by hand, `chainbreak_tests "[.overlay_cost]"`.
