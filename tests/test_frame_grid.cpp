// The frame clock (src/app/frame_grid.h): uniform frames on the integrator's grid, slow motion
// around breaks (F x the normal step inside the window, the normal step outside it and its
// easing), and the CLI's sidecar listing every frame's tau.
#include <catch2/catch.hpp>
#include <cmath>
#include <nlohmann/json.hpp>

#include "app/frame_grid.h"
#include "scene/scene.h"
#include "test_support.h"

namespace {

using json = nlohmann::json;

// Steps between frame k and k + 1.
std::int64_t gap(const cb::FrameGrid& g, std::int64_t k) {
  return g.step(k + 1) - g.step(k);
}

}  // namespace

TEST_CASE("a uniform grid puts frame k at k x speed / fps, on whole integrator steps",
          "[frames]") {
  // 10 tau/s at 60 fps: 1/6 tau a frame; the scene's dt 0.01 shrinks to 1/6/17 (17 steps).
  cb::FrameGrid g(10.0 / 60.0, 0.01, {});
  CHECK(g.substeps() == 17);
  CHECK(g.dt() == Approx(10.0 / 60.0 / 17.0).epsilon(1e-15));
  CHECK(g.dt() <= 0.01);
  g.lay_out(100.0, {42.0});  // a break changes nothing without slow motion
  CHECK(g.frames() == 601);  // tau 0 .. 100 inclusive
  for (std::int64_t k : {0, 1, 7, 599, 600}) {
    CHECK(g.step(k) == 17 * k);
    CHECK(g.speed(k) == 1.0);
  }
  CHECK(g.tau(600) == Approx(100.0).epsilon(1e-12));
  CHECK(g.step(700) == 17 * 700);  // past the end (the viewer): the normal pace goes on
  CHECK(g.frame_at(50.0, 1e-9) == 300);
  CHECK(g.frame_at(50.05, 1e-9) == -1);
  CHECK(g.first_frame_at_or_after(50.05) == 301);
}

TEST_CASE("slow motion: F x the normal step within +-W of every break, normal outside, eased",
          "[frames]") {
  const double F = 0.1, W = 2.0;
  // 1/6 tau a frame: 17 steps would make F x 17 = 1.7 steps; the grid takes 170 (dt / 10).
  cb::FrameGrid g(10.0 / 60.0, 0.01, cb::SlowMotion{F, W});
  REQUIRE(g.substeps() == 170);
  const std::int64_t normal = g.substeps(), slow = 17;
  const std::vector<double> breaks = {40.0, 90.0};
  g.lay_out(100.0, breaks);
  const std::vector<double> tau = g.taus();
  REQUIRE(static_cast<std::int64_t>(tau.size()) == g.frames());
  int inside = 0, outside = 0, eased = 0;
  for (std::int64_t k = 0; k + 1 < g.frames(); ++k) {
    REQUIRE(g.step(k + 1) > g.step(k));  // strictly increasing
    double distance = 1e300;
    for (double b : breaks) distance = std::min(distance, std::abs(g.tau(k) - b));
    INFO("frame " << k << " at tau " << g.tau(k));
    if (distance <= W) {
      CHECK(gap(g, k) == slow);
      ++inside;
    } else if (distance >= W + 0.5 * W) {  // past the easing ramp (half a window)
      CHECK(gap(g, k) == normal);
      ++outside;
    } else {
      CHECK(gap(g, k) >= slow);
      CHECK(gap(g, k) <= normal);
      ++eased;
    }
  }
  // 2 windows of 4 tau at 1/60 tau a frame; the easing takes a few frames, not one jump.
  CHECK(inside == Approx(2 * 4.0 / (F / 6.0)).margin(4));
  CHECK(eased >= 8);
  CHECK(outside > 400);
  // Every frame lands on the integrator's grid exactly: tau = step x dt.
  for (std::int64_t k : {0L, 100L, g.frames() - 1}) CHECK(g.tau(k) == g.step(k) * g.dt());
}

TEST_CASE("a slow-motion factor that no whole number of steps can make is refused", "[frames]") {
  CHECK_THROWS_AS(cb::FrameGrid(0.1, 0.01, cb::SlowMotion{0.0001234, 2.0}), cb::SceneError);
  CHECK_NOTHROW(cb::FrameGrid(0.1, 0.01, cb::SlowMotion{1.0 / 7.0, 2.0}));
  CHECK_NOTHROW(cb::FrameGrid(0.1, 0.01, cb::SlowMotion{0.25, 2.0}));
}

TEST_CASE("render --slowmo lists every frame's tau in the plan, slowed around the break",
          "[frames][cli]") {
  const std::string scene = std::string(CHAINBREAK_SCENES) + "/ramp_pulled_end.toml";
  const auto plain = cb::test::run_chainbreak("render " + scene +
                                              " --fps 30 --speed 30 --dry-run --quiet");
  REQUIRE(plain.status == 0);
  const json p = json::parse(plain.out);
  REQUIRE(p["frame_tau"].size() == p["frames"].get<std::size_t>());
  CHECK(p["slowmo"].is_null());
  for (std::size_t k = 0; k < p["frame_tau"].size(); ++k)
    CHECK(p["frame_tau"][k].get<double>() == Approx(static_cast<double>(k)).margin(1e-9));

  const auto r = cb::test::run_chainbreak(
      "render " + scene + " --fps 30 --speed 30 --slowmo 0.1 --slowmo-window 1 --dry-run --quiet");
  REQUIRE(r.status == 0);
  const json j = json::parse(r.out);
  const auto& t = j["frame_tau"];
  REQUIRE(t.size() == j["frames"].get<std::size_t>());
  REQUIRE(j["breaks"].size() >= 1);
  const double b = j["breaks"][0]["tau"];
  // Slowed around every break the video shows, not just the first.
  const auto nearest = [&](double tau) {
    double d = 1e300;
    for (const auto& e : j["breaks"]) d = std::min(d, std::abs(tau - e["tau"].get<double>()));
    return d;
  };
  CHECK(j["slowmo"]["factor"] == 0.1);
  int slow = 0;
  for (std::size_t k = 0; k + 1 < t.size(); ++k) {
    const double tk = t[k], step = t[k + 1].get<double>() - tk;
    REQUIRE(step > 0);
    if (nearest(tk) <= 1.0) {
      CHECK(step == Approx(0.1).margin(1e-9));  // F x the normal 1 tau a frame
      ++slow;
    } else if (nearest(tk) >= 1.5) {
      CHECK(step == Approx(1.0).margin(1e-9));
    }
  }
  CHECK(slow >= 19);  // 2 tau of window at 0.1 tau a frame
  // The break's first frame is the first frame at or after it.
  const std::size_t f = j["breaks"][0]["frame"];
  CHECK(t[f].get<double>() >= b);
  CHECK(t[f - 1].get<double>() < b);
}
