// Lecture- and print-quality pictures (issue 11): one typeface and no bitmap font anywhere,
// text contrast >= 7:1 (WCAG AAA) measured on rendered frames in both themes, the strain map
// against each theme's background, zoom on a long chain, and side-by-side runs whose breaks
// are each scene's own.
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "gl_test_support.h"
#include "output/png_writer.h"
#include "render/renderer.h"
#include "snapshot/snapshot.h"
#include "test_support.h"
#include "theme/theme.h"
#include "video_probe.h"

namespace fs = std::filesystem;
using json = nlohmann::json;

namespace {

const fs::path kSource = fs::path(CHAINBREAK_SCENES).parent_path();

cb::Rgb8 pixel(const cb::Image& image, int x, int y) {
  const auto* p = &image.rgba[(static_cast<std::size_t>(y) * image.width + x) * 4];
  return {p[0], p[1], p[2]};
}

cb::ChainParams chain(int n, double threshold) {
  cb::ChainParams p;
  p.beads = n;
  p.threshold = threshold;
  return p;
}

}  // namespace

TEST_CASE("no bitmap font and no text path but the TTF one remain in the sources", "[pictures]") {
  // Spelled in pieces so that this file does not match itself.
  const std::vector<std::string> forbidden = {
      std::string("stb_easy") + "_font",          // the old bitmap font
      std::string("AddFont") + "Default",         // Dear ImGui's built-in bitmap font
      std::string("Proggy") + "Clean",            // its name
      std::string("glut") + "BitmapCharacter",    // any GL bitmap text
  };
  int files = 0;
  for (const char* dir : {"src", "tests", "shaders"}) {
    for (const auto& entry : fs::recursive_directory_iterator(kSource / dir)) {
      if (!entry.is_regular_file()) continue;
      const std::string ext = entry.path().extension().string();
      if (ext != ".cpp" && ext != ".h" && ext != ".txt" && ext != ".frag" && ext != ".vert") continue;
      std::ifstream in(entry.path());
      std::stringstream text;
      text << in.rdbuf();
      ++files;
      for (const std::string& word : forbidden) {
        INFO(entry.path().string() << " mentions " << word);
        CHECK(text.str().find(word) == std::string::npos);
      }
    }
  }
  CHECK(files > 100);  // the walk saw the tree
}

TEST_CASE("the strain map differs from each theme's background and its lightness is monotone",
          "[pictures]") {
  for (cb::ThemeName name : {cb::ThemeName::Dark, cb::ThemeName::Light}) {
    INFO(cb::theme_name(name));
    const auto rgb = [&](double s) {
      const cb::Color c = cb::strain_color(s, name);
      return cb::Rgb8{static_cast<std::uint8_t>(std::lround(c.r * 255)),
                      static_cast<std::uint8_t>(std::lround(c.g * 255)),
                      static_cast<std::uint8_t>(std::lround(c.b * 255))};
    };
    // Zero strain is a grey well apart from the background (>= 10 Delta E, CIE76).
    CHECK(cb::delta_e76(rgb(0.0), cb::theme(name).background) >= 10.0);
    // Lightness rises with s over the whole scale: greyscale print keeps the order.
    double previous = -1.0;
    for (int i = 0; i <= 200; ++i) {
      const double L = cb::srgb_to_lab(rgb(-1.0 + i / 100.0)).L;
      CHECK(L > previous - 0.5);  // 8-bit rounding may wobble by less than half a step
      previous = L;
    }
    CHECK(cb::srgb_to_lab(rgb(1.0)).L - cb::srgb_to_lab(rgb(-1.0)).L > 50.0);
  }
}

TEST_CASE("rendered text reaches 7:1 against its background in both themes", "[pictures][gl]") {
  auto context = cb::test::create_or_skip(cb::GlBackend::Auto);
  if (!context) return;
  for (cb::ThemeName name : {cb::ThemeName::Dark, cb::ThemeName::Light}) {
    INFO(cb::theme_name(name));
    cb::SnapshotStyle style;
    style.width = 854;  // the smallest preset: its text is the smallest drawn
    style.height = 480;
    style.theme = name;
    style.threshold = 1.0;
    cb::ChainState state;
    state.psi.assign(30, 0.0);
    const cb::RenderSnapshot snap = cb::build_snapshot(state, chain(30, 1.0), 0.5, style);
    cb::Renderer renderer(style.width, style.height);
    const cb::Image image = renderer.render(snap);
    // Every label: its most inked pixel (a glyph stem, fully covered) against the background.
    int labels = 0;
    const cb::Rgb8 bg = cb::theme(name).background;
    for (const cb::Layer& layer : snap.layers)
      for (const cb::Label& l : layer.labels) {
        double best = 1.0;
        const int x0 = static_cast<int>(l.x), x1 = static_cast<int>(l.x + cb::text_width(l.text, l.size));
        const int y0 = static_cast<int>(l.y), y1 = static_cast<int>(l.y + 0.7f * l.size);
        for (int y = std::max(0, y0); y < std::min(style.height, y1); ++y)
          for (int x = std::max(0, x0); x < std::min(style.width, x1); ++x)
            best = std::max(best, cb::contrast_ratio(pixel(image, x, y), bg));
        INFO("label '" << l.text << "'");
        CHECK(best >= 7.0);
        ++labels;
      }
    CHECK(labels >= 6);  // time, force, colour bar ticks and ends
    CHECK(pixel(image, 0, 0) == bg);
    for (const cb::Layer& layer : snap.layers)
      for (const cb::Label& l : layer.labels) CHECK(l.size >= 14.0f);  // theme/fonts.h
  }
}

TEST_CASE("zoom draws beads of a 60-spring window of N = 1e5, each spring where the window puts it",
          "[pictures]") {
  const int n = 100000, first = 50001, last = 50060;
  cb::ChainState state;
  state.psi.resize(n);
  // Every spring a different extension: phi_j = 1e-3 * (j mod 97), psi the running sum.
  double psi = 0.0;
  for (int j = 1; j <= n; ++j) state.psi[j - 1] = psi += 1e-3 * (j % 97);
  cb::SnapshotStyle style;
  style.width = 1280;
  style.height = 720;
  style.threshold = 0.1;
  style.strain_range = 0.1;  // as snapshot_style sets it for a breakable chain
  style.psi_range = psi;
  style.zoom_first = first;
  style.zoom_last = last;
  const cb::RenderSnapshot snap = cb::build_snapshot(state, chain(n, 0.1), 0.0, style);
  CHECK_FALSE(snap.ribbon);  // beads, not the ribbon the whole chain would need
  const cb::Layer& chain_layer = snap.layers[cb::kLayerChain];
  const cb::PanelLayout& p = snap.layout.panels[0];
  // Longitudinal, moving with bead first - 1: bead j sits at
  // x_wall + (j - (first - 1) + psi_j - psi_{first-1}) * spacing.
  const double origin = snap.layout.x_wall - (first - 1 + state.psi[first - 2]) * p.spacing;
  int checked = 0;
  for (const cb::SpringInstance& s : chain_layer.springs) {
    // The pixel under the spring's middle: which spring does the window map there?
    const double x = 0.5 * (s.x0 + s.x1);
    int j = -1;
    for (int k = first - 200; k <= last + 200; ++k) {
      const double a = origin + (k - 1 + state.psi[k - 2]) * p.spacing;
      const double b = origin + (k + state.psi[k - 1]) * p.spacing;
      if (x > a && x < b) j = k;
    }
    REQUIRE(j > 0);
    const double phi = state.psi[j - 1] - state.psi[j - 2];
    const cb::Color want = cb::strain_color(phi / 0.1, cb::ThemeName::Dark);
    CHECK(s.color.r == want.r);
    CHECK(s.color.g == want.g);
    CHECK(s.color.b == want.b);
    if (j >= first && j <= last) ++checked;
  }
  CHECK(checked == last - first + 1);  // every spring of the window is drawn
  CHECK(snap.layers[cb::kLayerBeads].beads.size() >= static_cast<std::size_t>(last - first + 1));
  CHECK(snap.layers[cb::kLayerBeads].beads.size() < 200);  // and not the rest of the chain
}

TEST_CASE("two scenes side by side: one video of the stated size, each run's own breaks",
          "[pictures][cli]") {
  auto context = cb::test::create_or_skip(cb::GlBackend::Auto);
  if (!context) return;
  const cb::test::TempDir dir("chainbreak-sbs");
  const std::string a = std::string(CHAINBREAK_SCENES) + "/regimes/fast_pull.toml";
  const std::string b = std::string(CHAINBREAK_SCENES) + "/regimes/slow_pull.toml";
  const std::string out = (dir.path / "pair.mp4").string();
  // 1 tau a frame at the scenes' dt 0.01: the shared clock steps exactly as `run` does.
  const auto r = cb::test::run_chainbreak("render " + a + " " + b + " -o " + out +
                                          " --size 320x240 --fps 30 --speed 30 --slowmo 1 --quiet");
  REQUIRE(r.status == 0);
  const json j = json::parse(cb::test::read_bytes((dir.path / "pair.json").string()));
  const cb::test::Decoded d = cb::test::decode(out, -1);
  CHECK(d.width == 320);
  CHECK(d.height == 240);
  CHECK(d.frames == j["frames"].get<int>());
  REQUIRE(j["runs"].size() == 2);
  for (int i = 0; i < 2; ++i) {
    const auto alone = cb::test::run_chainbreak("run " + std::string(i ? b : a));
    REQUIRE(alone.status == 0);
    const json expected = json::parse(alone.out)["breaks"];
    const json& got = j["runs"][i]["breaks"];
    INFO("run " << i);
    // Breaks up to where the video stops: the first ones `run` reports, bit for bit.
    REQUIRE(got.size() >= 1);
    REQUIRE(got.size() <= expected.size());
    for (std::size_t k = 0; k < got.size(); ++k) {
      CHECK(got[k]["spring"] == expected[k]["spring"]);
      CHECK(got[k]["tau"].get<double>() == expected[k]["tau"].get<double>());
    }
  }
  CHECK(j["runs"][0]["breaks"][0]["spring"] == 30);  // the fast pull breaks the pulled end
  CHECK(j["runs"][1]["breaks"][0]["spring"] == 2);   // the slower one near the wall
  CHECK(j["runs"][0]["label"].get<std::string>().find("β = 0.075") != std::string::npos);
}

TEST_CASE("snapshot stacks two scenes in one picture, each band showing its own run",
          "[pictures][cli]") {
  auto context = cb::test::create_or_skip(cb::GlBackend::Auto);
  if (!context) return;
  const cb::test::TempDir dir("chainbreak-stacked-snapshot");
  const std::string a = std::string(CHAINBREAK_SCENES) + "/regimes/fast_pull.toml";
  const std::string b = std::string(CHAINBREAK_SCENES) + "/regimes/slow_pull.toml";
  // At tau 45 the fast pull's spring 30 has broken (tau 41.0, `run`), the slow pull's first
  // break is still to come (tau 80.5).
  const auto r = cb::test::run_chainbreak("snapshot " + a + " " + b +
                                          " --at 45 --size 640x480 --theme light -o " +
                                          dir.path.string());
  INFO(r.err);
  REQUIRE(r.status == 0);
  const std::string png = (dir.path / "fast_pull_vs_slow_pull_tau_000045.000.png").string();
  CHECK(r.out == png + "\n");
  const cb::Image image = cb::read_png(png);
  REQUIRE(image.width == 640);
  REQUIRE(image.height == 480);
  // The first break's marker and leader are drawn in the theme's accent colour: in the top
  // band (the fast pull) and nowhere in the bottom one.
  const cb::Rgb8 marker = cb::theme(cb::ThemeName::Light).accent;
  int top = 0, bottom = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const cb::Rgb8 p = pixel(image, x, y);
      if (std::abs(p.r - marker.r) + std::abs(p.g - marker.g) + std::abs(p.b - marker.b) < 12)
        ++(y < image.height / 2 ? top : bottom);
    }
  CHECK(top > 10);  // the marker arrow (its label is drawn in the text colour)
  CHECK(bottom == 0);
  // The background is the light theme's in both bands (corners).
  const cb::Rgb8 bg = cb::theme(cb::ThemeName::Light).background;
  for (int y : {2, image.height / 2 + 4, image.height - 3}) {
    const cb::Rgb8 p = pixel(image, image.width - 3, y);
    CHECK((p.r == bg.r && p.g == bg.g && p.b == bg.b));
  }

  // The overlay plots one run: stacked scenes with --overlay are a user error.
  const auto overlay = cb::test::run_chainbreak("snapshot " + a + " " + b +
                                                " --at 45 --overlay hud -o " + dir.path.string());
  CHECK(overlay.status == 2);
  CHECK(overlay.err.find("--overlay") != std::string::npos);
}
