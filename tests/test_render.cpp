// The renderer (src/render) on both headless backends: trivial shapes from hand-made
// snapshots land on exactly their pixels; a spring shows its strain colour; a break marker
// appears after the break; frames are deterministic; OSMesa and EGL agree; N = 1e6 renders
// at 1080p from an O(width) snapshot. The snapshot itself is checked without GL in
// test_snapshot.cpp, whole frames against goldens in test_golden.cpp.
// Each test runs once per backend; where a backend cannot be created it warns and passes,
// unless CHAINBREAK_REQUIRE_GL=1 (set by ctest), where both must work.
#include <unistd.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <sstream>
#include <string>

#include "drive/drive.h"
#include "gl/gl_context.h"
#include "gl_test_support.h"
#include "output/image.h"
#include "output/png_writer.h"
#include "output/yuv420.h"
#include "physics/integrator.h"
#include "render/renderer.h"
#include "text/font.h"
#include "text/text_layout.h"
#include "snapshot/snapshot.h"

namespace {

// Colours k/255 convert to unorm8 exactly (round(c * 255) = k), so opaque unblended shapes
// have exactly known pixels.
cb::Color rgb255(int r, int g, int b) {
  return cb::Color{r / 255.0f, g / 255.0f, b / 255.0f, 1.0f};
}

// The largest channel difference (r, g, b; alpha is always 255) between a pixel and a colour
// in 8 bits.
int diff(const cb::Image& image, int x, int y, const cb::Color& c) {
  const std::uint8_t* p = image.pixel(x, y);
  const float want[3] = {c.r, c.g, c.b};
  int worst = 0;
  for (int k = 0; k < 3; ++k)
    worst = std::max(worst, std::abs(int(p[k]) - int(std::lround(want[k] * 255.0f))));
  return worst;
}

std::string describe_pixel(const cb::Image& image, int x, int y) {
  const std::uint8_t* p = image.pixel(x, y);
  std::ostringstream out;
  out << "(" << x << ", " << y << ") = " << int(p[0]) << " " << int(p[1]) << " " << int(p[2]) << " "
      << int(p[3]);
  return out.str();
}

cb::RenderSnapshot blank_snapshot(int width, int height, const cb::Color& background) {
  cb::RenderSnapshot s;
  s.width = width;
  s.height = height;
  s.background = background;
  s.layers.resize(cb::kLayerCount);
  return s;
}

cb::ChainState rest_state(int beads) {
  cb::ChainState s;
  s.psi.assign(beads, 0.0);
  s.vel.assign(beads, 0.0);
  return s;
}

cb::ChainParams chain(int beads, double threshold) {
  cb::ChainParams p;
  p.beads = beads;
  p.threshold = threshold;
  return p;
}

// The anomalous breaking scene (scenes/anomalous_breaking.toml: N = 30, phi_c = 3, ramp
// beta = 0.02) half a time unit after its first break (spring 30 at tau ~ 150): flash,
// recoiling halves, marker and label, at the given size.
cb::RenderSnapshot anomalous_frame(int width, int height) {
  const cb::ChainParams params = chain(30, 3.0);
  cb::DriveDesc drive;
  drive.type = cb::DriveType::Ramp;
  drive.beta = 0.02;
  cb::Integrator sim(params, cb::make_forcing(drive), {0.01, 1});
  bool ok = true;
  while (ok && sim.state().breaks.empty() && sim.state().step < 40000) ok = sim.step();
  REQUIRE(ok);
  REQUIRE_FALSE(sim.state().breaks.empty());
  REQUIRE(sim.advance_to(sim.state().step + 50));
  cb::SnapshotStyle style;
  style.width = width;
  style.height = height;
  style.psi_range = 8.0;    // covers psi_N up to the break (~7.5)
  style.force_range = 3.0;  // f = 0.02 tau at the break
  style.threshold = 3.0;
  return cb::build_snapshot(sim.state(), params, sim.force_now(), style);
}

const cb::Label* find_label(const cb::RenderSnapshot& snap, const std::string& part) {
  for (const auto& layer : snap.layers)
    for (const auto& label : layer.labels)
      if (label.text.find(part) != std::string::npos) return &label;
  return nullptr;
}

}  // namespace

TEST_CASE("Trivial shapes land on exactly their pixels", "[render]") {
  const cb::GlBackend backend = GENERATE(cb::GlBackend::OSMesa, cb::GlBackend::Egl);
  INFO("backend " << cb::gl_backend_name(backend));
  auto context = cb::test::create_or_skip(backend);
  if (!context) return;
  constexpr int kW = 128, kH = 96;
  const cb::Color bg = rgb255(20, 24, 28);
  cb::RenderSnapshot snap = blank_snapshot(kW, kH, bg);
  // Each shape in its own region so the checks do not see each other.
  const cb::Rect rect{10, 8, 20, 12, rgb255(200, 40, 60)};
  snap.layers[cb::kLayerFrame].rects.push_back(rect);
  // Centred on row 12 (y = 12.5 is that row's centre line), 5 px thick.
  const cb::Segment seg{50, 12.5f, 110, 12.5f, 5.0f, rgb255(30, 180, 90)};
  snap.layers[cb::kLayerChain].segments.push_back(seg);
  const cb::Triangle tri{{10, 50, 10}, {40, 40, 90}, rgb255(250, 200, 20)};
  snap.layers[cb::kLayerForce].triangles.push_back(tri);
  const cb::BeadInstance bead{90.5f, 60.5f, 10.0f, rgb255(100, 150, 220)};
  snap.layers[cb::kLayerBeads].beads.push_back(bead);

  cb::Renderer renderer(kW, kH);
  const cb::Image image = renderer.render(snap);
  REQUIRE(image.width == kW);
  REQUIRE(image.height == kH);
  REQUIRE(image.rgba.size() == std::size_t(kW) * kH * 4);

  SECTION("a rect covers x in [x, x+w), y in [y, y+h), rows top-down") {
    int wrong = 0;
    std::string first;
    for (int y = 0; y < 30; ++y)
      for (int x = 0; x < 40; ++x) {
        const bool inside = x >= 10 && x < 30 && y >= 8 && y < 20;
        if (diff(image, x, y, inside ? rect.color : bg) == 0) continue;
        if (wrong++ == 0) first = describe_pixel(image, x, y);
      }
    INFO("first wrong pixel " << first);
    CHECK(wrong == 0);
    // The corners explicitly, so a failure says which side is off (or that rows are flipped).
    CHECK(diff(image, 10, 8, rect.color) == 0);
    CHECK(diff(image, 9, 8, bg) == 0);
    CHECK(diff(image, 10, 7, bg) == 0);
    CHECK(diff(image, 29, 19, rect.color) == 0);
    CHECK(diff(image, 30, 19, bg) == 0);
    CHECK(diff(image, 29, 20, bg) == 0);
    CHECK(image.pixel(10, 8)[3] == 255);
  }

  SECTION("a wide segment is its exact colour on the centre line, background beyond") {
    // Antialiasing only fades the outer half pixel of each long edge: 2 px either side of
    // the centre line are fully covered.
    for (int x : {60, 80, 100}) {
      INFO(describe_pixel(image, x, 12));
      CHECK(diff(image, x, 12, seg.color) == 0);
      CHECK(diff(image, x, 10, seg.color) == 0);
      CHECK(diff(image, x, 14, seg.color) == 0);
      // 4 px from the centre line: beyond half the width plus the 1 px fade.
      CHECK(diff(image, x, 8, bg) == 0);
      CHECK(diff(image, x, 16, bg) == 0);
    }
  }

  SECTION("a triangle fills the pixels whose centres are inside") {
    // Edges: x = 10, y = 40, and the line from (50, 40) to (10, 90). A pixel centre more
    // than 0.5 px inside every edge is covered, more than 0.5 px outside one is not; the
    // band between is left to the rasteriser's tie rules.
    const double ex = 40.0, ey = -50.0, len = std::hypot(ex, ey);
    int wrong = 0;
    std::string first;
    for (int y = 35; y < 95; ++y)
      for (int x = 5; x < 55; ++x) {
        const double cx = x + 0.5, cy = y + 0.5;
        // Signed distance to the slanted edge, positive on the triangle's side.
        const double slant = ((cx - 50.0) * ey - (cy - 40.0) * ex) / len;
        const double inside = std::min({cx - 10.0, cy - 40.0, slant});
        if (std::abs(inside) <= 0.5) continue;
        if (diff(image, x, y, inside > 0 ? tri.color : bg) == 0) continue;
        if (wrong++ == 0) first = describe_pixel(image, x, y);
      }
    INFO("first wrong pixel " << first);
    CHECK(wrong == 0);
    CHECK(diff(image, 15, 45, tri.color) == 0);
  }

  SECTION("a bead is lit at its centre and ends within radius + 1") {
    // disc.frag at the centre: the normal faces the viewer, so the colour is scaled by
    // 0.45 + 0.6 * lambert with lambert = the light's z, plus a highlight 0.35 * z^24.
    // Tolerance 2/255: the shader's float arithmetic and 8-bit rounding.
    const double z = 0.7 / std::sqrt(0.45 * 0.45 + 0.55 * 0.55 + 0.7 * 0.7);
    const double gain = 0.45 + 0.6 * z, highlight = 0.35 * std::pow(z, 24.0);
    const auto lit = [&](float c) { return static_cast<float>(c * gain + highlight); };
    const cb::Color expected{lit(bead.color.r), lit(bead.color.g), lit(bead.color.b), 1.0f};
    INFO(describe_pixel(image, 90, 60));
    CHECK(diff(image, 90, 60, expected) <= 2);
    // Clearly not the background a few pixels inside the rim, in every direction.
    for (int k : {-7, 7}) {
      CHECK(diff(image, 90 + k, 60, bg) > 20);
      CHECK(diff(image, 90, 60 + k, bg) > 20);
    }
    // Pixel centres 11.5 px (radius + 1.5) from the centre: nothing drawn.
    for (int k : {-12, 11}) {
      CHECK(diff(image, 90 + k, 60, bg) == 0);
      CHECK(diff(image, 90, 60 + k, bg) == 0);
    }
  }
}

// A segment's antialiasing margin widens it across, never along: it stops at its end points
// (an earlier quad.vert lengthened it by one fully covered pixel at each end).
TEST_CASE("A segment stops at its end points", "[render]") {
  const cb::GlBackend backend = GENERATE(cb::GlBackend::OSMesa, cb::GlBackend::Egl);
  INFO("backend " << cb::gl_backend_name(backend));
  auto context = cb::test::create_or_skip(backend);
  if (!context) return;
  constexpr int kW = 128, kH = 32;
  const cb::Color bg = rgb255(20, 24, 28);
  cb::RenderSnapshot snap = blank_snapshot(kW, kH, bg);
  const cb::Segment seg{50, 12.5f, 110, 12.5f, 5.0f, rgb255(30, 180, 90)};
  snap.layers[cb::kLayerChain].segments.push_back(seg);
  cb::Renderer renderer(kW, kH);
  const cb::Image image = renderer.render(snap);
  // Pixel centres 0.5 px inside the ends are covered, 0.5 px outside are not.
  CHECK(diff(image, 50, 12, seg.color) == 0);
  CHECK(diff(image, 109, 12, seg.color) == 0);
  INFO(describe_pixel(image, 49, 12) << ", " << describe_pixel(image, 110, 12));
  CHECK(diff(image, 49, 12, bg) == 0);
  CHECK(diff(image, 110, 12, bg) == 0);
}

TEST_CASE("A label draws the typeface's anti-aliased glyphs where the layout puts them",
          "[render][text]") {
  const cb::GlBackend backend = GENERATE(cb::GlBackend::OSMesa, cb::GlBackend::Egl);
  INFO("backend " << cb::gl_backend_name(backend));
  auto context = cb::test::create_or_skip(backend);
  if (!context) return;
  constexpr int kW = 220, kH = 60;
  const cb::Color bg = rgb255(10, 10, 10);
  cb::RenderSnapshot snap = blank_snapshot(kW, kH, bg);
  // Greek, a subscript and a minus sign: real glyphs, not names.
  const cb::Label label{"τ = 12 φ_c \u2212ψ", 20.3f, 14.6f, 22.0f, rgb255(230, 230, 240)};
  snap.layers[cb::kLayerMarks].labels.push_back(label);

  cb::Renderer renderer(kW, kH);
  const cb::Image image = renderer.render(snap);
  // The oracle: stb_truetype's coverage of each glyph, placed by the layout on whole pixels
  // (baseline one cap height below the label's top), blended over the background. Expected
  // within 2/255 (8-bit rounding of the blend on two paths).
  const cb::TextLine line = cb::layout_text(label.text, label.size);
  const int x0 = static_cast<int>(std::round(label.x));
  const int baseline = static_cast<int>(std::round(label.y + line.cap_height));
  std::vector<int> expected(kW * kH, -1);  // coverage per pixel; -1: no glyph there
  for (const cb::PlacedGlyph& g : line.glyphs) {
    const cb::GlyphBitmap bm = cb::Font::get(cb::FontFace::Sans).rasterize(g.c, g.px);
    for (int y = 0; y < bm.height; ++y)
      for (int x = 0; x < bm.width; ++x) {
        const int px = x0 + g.x + bm.left + x, py = baseline + g.dy + bm.top + y;
        REQUIRE((px >= 0 && px < kW && py >= 0 && py < kH));
        int& e = expected[py * kW + px];
        e = std::max(e, static_cast<int>(bm.coverage[y * bm.width + x]));
      }
  }
  int worst = 0, partial = 0, full = 0;
  std::string where;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      const int cov = std::max(0, expected[y * kW + x]);
      const auto* p = &image.rgba[(static_cast<std::size_t>(y) * kW + x) * 4];
      const float want = 10.0f + (230.0f - 10.0f) * cov / 255.0f;  // the red channel
      const int d = static_cast<int>(std::abs(p[0] - want) + 0.5f);
      if (d > worst) {
        worst = d;
        where = describe_pixel(image, x, y);
      }
      partial += cov > 0 && cov < 255;
      full += cov == 255;
    }
  INFO("worst pixel " << where);
  CHECK(worst <= 2);
  CHECK(partial > 50);  // anti-aliased edges, not a bitmap font
  CHECK(full > 30);
  // τ, φ, ψ and the minus sign are in the face (no replacement glyph).
  for (const cb::PlacedGlyph& g : line.glyphs) CHECK(g.c != U'\uFFFD');
}

TEST_CASE("A spring shows strain_color of its extension", "[render]") {
  const cb::GlBackend backend = GENERATE(cb::GlBackend::OSMesa, cb::GlBackend::Egl);
  INFO("backend " << cb::gl_backend_name(backend));
  auto context = cb::test::create_or_skip(backend);
  if (!context) return;
  cb::SnapshotStyle style;
  style.width = 640;
  style.height = 360;
  style.threshold = 1.0;
  cb::Renderer renderer(style.width, style.height);
  // Tolerance 2/255 per channel: strain_color is not a multiple of 1/255, so the 8-bit
  // conversion rounds (<= 0.5/255); the rest is room for the driver's float arithmetic.
  const cb::Color tension = cb::strain_color(0.5);
  const cb::Color rest = cb::strain_color(0.0);

  // Spring k has phi = psi_k - psi_{k-1} = 0.5: beads k..N moved by 0.5, every other spring
  // is at rest. N = 5 draws coils (about 90 px apart), N = 60 short bars (about 9 px).
  for (const int n : {5, 60}) {
    const int k = n == 5 ? 3 : 30;
    INFO("N = " << n << ", spring " << k);
    auto state = rest_state(n);
    for (int j = k; j <= n; ++j) state.psi[j - 1] = 0.5;
    const auto snap = cb::build_snapshot(state, chain(n, 1.0), 0.0, style);
    const auto& springs = snap.layers[cb::kLayerChain].springs;
    REQUIRE(springs.size() == static_cast<std::size_t>(n));  // all intact, all in frame
    const cb::SpringInstance& s = springs[k - 1];
    REQUIRE((s.coils == 0.0f) == (n == 60));  // each path of renderer.cpp's append_spring
    const cb::Image image = renderer.render(snap);

    if (s.coils == 0.0f) {
      // A bar: its middle pixel is fully covered (the bar is over 2 px thick).
      const int mx = static_cast<int>(std::floor(0.5f * (s.x0 + s.x1)));
      const int my = static_cast<int>(std::floor(0.5f * (s.y0 + s.y1)));
      INFO(describe_pixel(image, mx, my));
      CHECK(diff(image, mx, my, tension) <= 2);
      const cb::SpringInstance& left = springs[k - 2];
      const int lx = static_cast<int>(std::floor(0.5f * (left.x0 + left.x1)));
      CHECK(diff(image, lx, my, rest) <= 2);
      continue;
    }
    // A coil: its zigzag lines (~5 px thick) are fully covered along their middles. Count
    // the pixels of the spring's colour in its box, and in the same box of its neighbour.
    const auto count = [&](const cb::SpringInstance& sp, const cb::Color& c) {
      int hits = 0;
      const int x0 = static_cast<int>(std::min(sp.x0, sp.x1));
      const int x1 = static_cast<int>(std::max(sp.x0, sp.x1));
      const int y0 = static_cast<int>(sp.y0 - sp.width), y1 = static_cast<int>(sp.y0 + sp.width);
      for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) hits += diff(image, x, y, c) <= 2;
      return hits;
    };
    CHECK(count(s, tension) >= 100);  // 8 turns of lines ~5 px wide over ~60 px
    CHECK(count(springs[k - 2], tension) == 0);
    CHECK(count(springs[k - 2], rest) >= 100);
  }
}

TEST_CASE("The break marker appears after the break and not before", "[render]") {
  const cb::GlBackend backend = GENERATE(cb::GlBackend::OSMesa, cb::GlBackend::Egl);
  INFO("backend " << cb::gl_backend_name(backend));
  auto context = cb::test::create_or_skip(backend);
  if (!context) return;
  const int n = 30;
  const auto params = chain(n, 1.0);
  cb::SnapshotStyle style;
  style.width = 640;
  style.height = 360;
  style.threshold = 1.0;
  style.psi_range = 2.0;
  auto state = rest_state(n);
  state.tau = 12.0;
  const auto before = cb::build_snapshot(state, params, 0.5, style);
  // Spring 7 broke at tau = 12.5; the detached part moved on by 1.5. At tau = 20 the flash
  // has faded (it lasts 1.5), so only the marker and its label are new.
  for (int j = 7; j <= n; ++j) state.psi[j - 1] = 1.5;
  state.broken = {7};
  state.breaks = {cb::BreakEvent{7, 12.5, 1250}};
  state.tau = 20.0;
  const auto after = cb::build_snapshot(state, params, 0.5, style);
  const cb::Label* label = find_label(after, "spring 7 broke");
  REQUIRE(label != nullptr);
  REQUIRE(find_label(before, "broke") == nullptr);

  cb::Renderer renderer(style.width, style.height);
  const cb::Image a = renderer.render(before);
  const cb::Image b = renderer.render(after);
  // The label's box; 10/7 of the cap height leaves room for descenders (p, g).
  const int x0 = static_cast<int>(std::floor(label->x));
  const int x1 = static_cast<int>(std::ceil(label->x + cb::text_width(label->text, label->size)));
  // From above the capitals (accents) to below the descenders: the font's pixel height.
  const int y0 = static_cast<int>(std::floor(label->y - 0.2f * label->size));
  const int y1 = static_cast<int>(std::ceil(label->y + label->size));
  REQUIRE(x1 <= style.width);
  REQUIRE(y1 <= style.height);
  int background_before = 0, text_after = 0;
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) {
      background_before += diff(a, x, y, before.background) == 0;
      text_after += diff(b, x, y, before.background) > 60;  // ink, anti-aliased edges aside
    }
  CHECK(background_before == (x1 - x0) * (y1 - y0));
  CHECK(text_after >= 100);  // ~25 glyphs

  // The pointer under the break: a marker-coloured triangle, opaque and unantialiased.
  const auto& triangles = after.layers[cb::kLayerMarks].triangles;
  REQUIRE(triangles.size() == 1);
  const cb::Triangle& t = triangles[0];
  const int cx = static_cast<int>((t.x[0] + t.x[1] + t.x[2]) / 3.0f);
  const int cy = static_cast<int>((t.y[0] + t.y[1] + t.y[2]) / 3.0f);
  CHECK(diff(a, cx, cy, before.background) == 0);
  CHECK(diff(b, cx, cy, t.color) <= 1);  // the marker colour rounded to 8 bits
}

TEST_CASE("Rendering is deterministic, down to the PNG bytes", "[render]") {
  const cb::GlBackend backend = GENERATE(cb::GlBackend::OSMesa, cb::GlBackend::Egl);
  INFO("backend " << cb::gl_backend_name(backend));
  auto context = cb::test::create_or_skip(backend);
  if (!context) return;
  const auto snap = anomalous_frame(480, 270);
  cb::Image first, second, fresh;
  {
    cb::Renderer renderer(480, 270);
    first = renderer.render(snap);
    second = renderer.render(snap);
  }
  {
    cb::Renderer renderer(480, 270);  // no state carried over from the previous renderer
    fresh = renderer.render(snap);
  }
  CHECK(first.rgba == second.rgba);
  CHECK(first.rgba == fresh.rgba);

  const auto dir = std::filesystem::temp_directory_path() /
                   ("chainbreak_test_render_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const auto read_all = [](const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  cb::write_png((dir / "a.png").string(), first);
  cb::write_png((dir / "b.png").string(), second);
  const std::string a = read_all(dir / "a.png");
  CHECK(a.size() > 1000);
  CHECK(a == read_all(dir / "b.png"));
  CHECK(cb::read_png((dir / "a.png").string()).rgba == first.rgba);  // lossless round trip
  std::filesystem::remove_all(dir);
}

TEST_CASE("read_yuv420 equals converting what read returns", "[render][yuv420]") {
  const cb::GlBackend backend = GENERATE(cb::GlBackend::OSMesa, cb::GlBackend::Egl);
  INFO("backend " << cb::gl_backend_name(backend));
  auto context = cb::test::create_or_skip(backend);
  if (!context) return;
  // 481 x 271: odd, so H.264's padding applies; 271 rows: the last band is a partial one.
  cb::Renderer renderer(481, 271);
  renderer.draw(anomalous_frame(481, 271));
  cb::Image rgba;
  renderer.read(rgba);
  cb::Yuv420Image direct, via_rgba;
  renderer.read_yuv420(direct, 482, 272);
  cb::rgba_to_yuv420({rgba.rgba.data(), 481, 271, 481 * 4, false}, 482, 272, via_rgba);
  CHECK(direct.bytes == via_rgba.bytes);
  CHECK(direct.width == 482);
  CHECK_THROWS_AS(renderer.read_yuv420(direct, 480, 271), std::invalid_argument);
}

TEST_CASE("OSMesa and EGL draw the same frame", "[render]") {
  // One context at a time (the GL function table is global): render with one, drop it,
  // render with the other.
  std::optional<cb::Image> images[2];
  const cb::GlBackend backends[2] = {cb::GlBackend::OSMesa, cb::GlBackend::Egl};
  for (int i = 0; i < 2; ++i) {
    auto context = cb::test::create_or_skip(backends[i]);
    if (!context) return;
    const auto snap = anomalous_frame(640, 360);
    cb::Renderer renderer(640, 360);
    images[i] = renderer.render(snap);
  }
  // Same Mesa, same llvmpipe: PLATFORM-NOTES measured "within 1/255 on a few pixels". Held
  // to the goldens' tolerance (test_golden.cpp): <= 2 per channel on all but 0.1% of pixels.
  const cb::ImageDiff d = cb::compare_images(*images[0], *images[1], 2);
  CAPTURE(d.max_channel, d.fraction_over);
  CHECK(d.same_size);
  CHECK(d.fraction_over <= 0.001);
  if (d.max_channel > 0) WARN("OSMesa and EGL differ by up to " << d.max_channel << "/255");
}

TEST_CASE("N = 1e6 renders a 1080p ribbon from an O(width) snapshot", "[render]") {
  const cb::GlBackend backend = GENERATE(cb::GlBackend::OSMesa, cb::GlBackend::Egl);
  INFO("backend " << cb::gl_backend_name(backend));
  auto context = cb::test::create_or_skip(backend);
  if (!context) return;
  const int n = 1000000;
  auto state = rest_state(n);
  // A slow wave (|phi| <= 8e-6) and one spring at phi = 0.7 among ~600 per pixel column,
  // which the ribbon must not average away (it keeps the most strained spring per column).
  for (int j = 0; j < n; ++j) state.psi[j] = 0.8 * std::sin(j * 1e-5);
  const int k = n / 2;
  for (int j = k; j <= n; ++j) state.psi[j - 1] += 0.7;
  cb::SnapshotStyle style;
  style.width = 1920;
  style.height = 1080;
  style.threshold = 1.0;
  style.psi_range = 2.0;
  cb::Renderer renderer(style.width, style.height);

  const auto start = std::chrono::steady_clock::now();
  const auto snap = cb::build_snapshot(state, chain(n, 1.0), 0.5, style);
  const cb::Image image = renderer.render(snap);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  CAPTURE(seconds);
  CHECK(seconds < 2.0);  // measured ~0.05 s; a per-spring path would take far longer

  REQUIRE(snap.ribbon);
  std::size_t elements = 0, bytes = 0;
  for (const auto& l : snap.layers) {
    elements += l.rects.size() + l.segments.size() + l.triangles.size() + l.springs.size() +
                l.beads.size() + l.labels.size();
    bytes += l.rects.capacity() * sizeof(cb::Rect) + l.segments.capacity() * sizeof(cb::Segment) +
             l.triangles.capacity() * sizeof(cb::Triangle) +
             l.springs.capacity() * sizeof(cb::SpringInstance) +
             l.beads.capacity() * sizeof(cb::BeadInstance) +
             l.labels.capacity() * sizeof(cb::Label);
  }
  CAPTURE(elements, bytes);
  CHECK(elements <= 4u * style.width);
  CHECK(bytes < 1000000u);  // one spring each would be 36 MB

  // The column holding spring k shows strain_color(0.7) on the ribbon's centre line (its phi
  // differs by 8e-6, far below one 8-bit step; tolerance 2 as for the springs above). The
  // column is found to within a pixel: bead k sits at x_wall + (k + psi_k) spacing.
  const auto& p = snap.layout.panels[0];
  const double x = snap.layout.x_wall + (k + state.psi[k - 1]) * p.spacing;
  const int px = static_cast<int>(x), py = static_cast<int>(p.centre_y);
  int best = 255;
  for (int dx = -1; dx <= 1; ++dx)
    best = std::min(best, diff(image, px + dx, py, cb::strain_color(0.7)));
  INFO(describe_pixel(image, px, py));
  CHECK(best <= 2);
}
