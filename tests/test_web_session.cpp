// The page's session (src/web/web_session.h), compiled natively: the C++ under the browser page,
// called in the patterns a browser's frames make, must give `chainbreak run`'s breaks every time.
//
// Why here and not only in tests/web: a browser produces one calling pattern per run, chosen by
// its timing (how many frames it draws before the test's runTo, how many steps fit in a frame's
// physics budget, page.js), so the page tests see a few patterns and no sanitizer. Here many
// patterns run (draws before the run, chunks of every size, plots on and off, frames of several
// sizes, a restart halfway), and CI's ASan/UBSan build runs them too: WebKitGTK trapped now and
// then on an out-of-bounds access in the page's wasm (tests/web/browser_check.py), and this is
// where a memory error of ours on those paths would show.
#include <algorithm>
#include <catch2/catch.hpp>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <random>
#include <string>
#include <vector>

#include "test_support.h"
#include "web/web_session.h"

namespace {

struct RunBreak {
  int spring;
  double tau;
};

// `chainbreak run`'s breaks for a shipped scene (the oracle: the page must match the program).
std::vector<RunBreak> cli_breaks(const std::string& scene) {
  const auto r = cb::test::run_chainbreak("run " + scene + " --quiet");
  INFO(r.err);
  REQUIRE(r.status == 0);
  std::vector<RunBreak> out;
  const nlohmann::json summary = nlohmann::json::parse(r.out);
  for (const auto& b : summary["breaks"])
    out.push_back({b["spring"].get<int>(), b["tau"].get<double>()});
  return out;
}

// A frame as page.js draws one: the canvas's size, a theme, the scene's view, plots or not.
void draw(const cb::WebSession& s, std::mt19937& rng) {
  static const int kSizes[][2] = {{1280, 720}, {960, 540}, {640, 400}, {1920, 1080}};
  const auto& size = kSizes[rng() % 4];
  const cb::RenderSnapshot snap = s.snapshot(size[0], size[1], rng() % 2 ? "dark" : "light",
                                             s.scene().render.view, rng() % 3 != 0);
  CHECK_FALSE(snap.layers.empty());
}

// Every shipped scene, as the page's presets offer them (page.js walks the same folder).
std::vector<std::filesystem::path> shipped_scenes() {
  std::vector<std::filesystem::path> all;
  for (const auto& e : std::filesystem::recursive_directory_iterator(CHAINBREAK_SCENES))
    if (e.path().extension() == ".toml") all.push_back(e.path());
  std::sort(all.begin(), all.end());
  REQUIRE(all.size() >= 20);
  return all;
}

// Every shipped scene in one pattern of calls, giving run's breaks. Pattern 0: the test API's
// runTo at once (no frame drawn); 1, 2: a browser's frames, seeded (1 with a restart halfway).
void check_pattern(unsigned pattern) {
  for (const auto& file : shipped_scenes()) {
    const std::string path = file.string();
    INFO(path);
    const std::vector<RunBreak> want = cli_breaks(path);
    const std::string text = cb::read_scene_text(path);
    std::mt19937 rng(pattern * 7919u + 17u);
    cb::WebSession s;
    s.load(text, path, {});
    if (pattern > 0) {
      for (unsigned k = rng() % 4; k > 0; --k) draw(s, rng);
      const std::int64_t last = s.last_step();
      bool restarted = pattern != 1;
      while (!s.at_end()) {
        // A frame's worth: from one step to a fifth of the run, as the budget and speed set.
        const std::int64_t chunk = 1 + static_cast<std::int64_t>(rng() % (1 + last / 5));
        REQUIRE(s.advance_to(s.sim().state().step + chunk));
        if (rng() % 2) draw(s, rng);
        if (!restarted && s.sim().state().step > last / 2) {
          s.restart();  // the page's Restart button halfway
          restarted = true;
        }
      }
    }
    REQUIRE(s.advance_to(s.last_step()));
    REQUIRE(s.error().empty());
    CHECK(s.at_end());
    draw(s, rng);
    const auto& got = s.sim().state().breaks;
    REQUIRE(got.size() == want.size());
    for (std::size_t i = 0; i < got.size(); ++i) {
      CHECK(got[i].spring == want[i].spring);
      CHECK(got[i].tau == want[i].tau);  // the same doubles, as the page tests require
    }
  }
}

}  // namespace

// One test case a pattern, so that ctest runs them side by side: all three in one took 101 s in
// CI's ASan build (expr_drive's exact lines, a numerical convolution, are most of it), alone at
// the end of its ctest.
TEST_CASE("the page's session gives run's breaks when the test API runs to the end at once",
          "[web][session]") {
  check_pattern(0);
}

TEST_CASE("the page's session gives run's breaks with a browser's frames and a restart",
          "[web][session]") {
  check_pattern(1);
}

TEST_CASE("the page's session gives run's breaks with a browser's frames and steps interleaved",
          "[web][session]") {
  check_pattern(2);
}
