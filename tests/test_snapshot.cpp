// The snapshot builder, checked exactly on plain data (no GL): where beads and springs go,
// their colours, the colour map's lightness, the force arrow, break markers and the ribbon.
// Positions are compared to the layout's formulas up to float rounding (1e-3 px: the shapes
// store float, ~1e-4 px at 2000 px).
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <string>

#include "physics/integrator.h"
#include "snapshot/snapshot.h"

namespace {

constexpr double kPx = 1e-3;  // float rounding of pixel coordinates, see above

cb::ChainState rest_state(int beads) {
  cb::ChainState s;
  s.psi.assign(beads, 0.0);
  s.vel.assign(beads, 0.0);
  return s;
}

cb::ChainParams chain(int beads, double threshold = 1.0, bool pull_string = false) {
  cb::ChainParams p;
  p.beads = beads;
  p.threshold = threshold;
  p.pull_string = pull_string;
  return p;
}

// CIE L* of an sRGB colour (IEC 61966-2-1 decoding, Y from the Rec. 709 primaries), computed
// here independently of the colour map's own conversion.
double lightness(const cb::Color& c) {
  const auto lin = [](double v) {
    return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
  };
  const double y = 0.2126 * lin(c.r) + 0.7152 * lin(c.g) + 0.0722 * lin(c.b);
  return y > 216.0 / 24389.0 ? 116.0 * std::cbrt(y) - 16.0 : y * 24389.0 / 27.0;
}

bool same_color(const cb::Color& a, const cb::Color& b) {
  return a.r == b.r && a.g == b.g && a.b == b.b && a.a == b.a;
}

bool has_label(const cb::RenderSnapshot& snap, const std::string& part) {
  for (const auto& layer : snap.layers) {
    for (const auto& label : layer.labels) {
      if (label.text.find(part) != std::string::npos) return true;
    }
  }
  return false;
}

std::size_t element_count(const cb::RenderSnapshot& snap) {
  std::size_t n = 0;
  for (const auto& l : snap.layers) {
    n += l.rects.size() + l.segments.size() + l.triangles.size() + l.springs.size() +
         l.beads.size() + l.labels.size();
  }
  return n;
}

}  // namespace

TEST_CASE("Views parse and print", "[snapshot]") {
  for (cb::View v : {cb::View::Longitudinal, cb::View::Transverse, cb::View::Both}) {
    cb::View parsed = cb::View::Longitudinal;
    REQUIRE(cb::parse_view(cb::view_name(v), parsed));
    CHECK(parsed == v);
  }
  cb::View unused;
  CHECK_FALSE(cb::parse_view("sideways", unused));
}

TEST_CASE("Strain colours: lightness rises monotonically, neutral at rest, clamped", "[snapshot]") {
  // L* strictly increasing over 201 samples (the map sets L* = 61 + 31 s exactly).
  double previous = -1.0;
  for (int i = 0; i <= 200; ++i) {
    const double s = -1.0 + i / 100.0;
    const double L = lightness(cb::strain_color(s));
    INFO("s = " << s);
    CHECK(L > previous);
    previous = L;
  }
  // Ends as designed: L* 30 and 92 (tolerance 0.5: float storage and the decoding here).
  CHECK(lightness(cb::strain_color(-1.0)) == Approx(30.0).margin(0.5));
  CHECK(lightness(cb::strain_color(1.0)) == Approx(92.0).margin(0.5));
  // Greyscale keeps compression and tension apart: designed difference 31 in L*.
  CHECK(lightness(cb::strain_color(0.5)) - lightness(cb::strain_color(-0.5)) > 25.0);
  // At rest a neutral grey (zero chroma up to float rounding).
  const cb::Color grey = cb::strain_color(0.0);
  CHECK(std::abs(grey.r - grey.g) < 1e-3);
  CHECK(std::abs(grey.g - grey.b) < 1e-3);
  // Blue for compression, orange for tension.
  CHECK(cb::strain_color(-0.5).b > cb::strain_color(-0.5).r + 0.1);
  CHECK(cb::strain_color(0.5).r > cb::strain_color(0.5).b + 0.1);
  // Saturates visibly over the last 10%: the channel spread (a chroma proxy) grows a lot.
  const auto spread = [](const cb::Color& c) {
    return std::max({c.r, c.g, c.b}) - std::min({c.r, c.g, c.b});
  };
  CHECK(spread(cb::strain_color(1.0)) > spread(cb::strain_color(0.9)) + 0.2);
  CHECK(spread(cb::strain_color(-1.0)) > spread(cb::strain_color(-0.9)) + 0.2);
  // Clamped beyond |s| = 1.
  CHECK(same_color(cb::strain_color(1.7), cb::strain_color(1.0)));
  CHECK(same_color(cb::strain_color(-3.0), cb::strain_color(-1.0)));
}

TEST_CASE("Longitudinal view: beads at x_wall + (j + psi_j) spacing", "[snapshot]") {
  const int n = 10;
  const auto params = chain(n);
  cb::SnapshotStyle style;  // 1280 x 720, psi_range 1
  const auto rest = cb::build_snapshot(rest_state(n), params, 0.0, style);
  const auto& l = rest.layout;
  REQUIRE_FALSE(rest.ribbon);
  REQUIRE(l.panel_count == 1);
  const auto& p = l.panels[0];
  CHECK(p.spacing == Approx((l.x_right - l.x_wall) / (n + style.psi_range)).margin(1e-4));
  const auto& beads = rest.layers[cb::kLayerBeads].beads;
  REQUIRE(beads.size() == static_cast<std::size_t>(n));
  for (int j = 1; j <= n; ++j) {
    CHECK(beads[j - 1].x == Approx(l.x_wall + j * p.spacing).margin(kPx));
    CHECK(beads[j - 1].y == Approx(p.centre_y).margin(kPx));
    CHECK(beads[j - 1].radius == Approx(std::clamp(0.3 * p.spacing, 1.5, 18.0)).margin(kPx));
  }
  const auto& springs = rest.layers[cb::kLayerChain].springs;
  REQUIRE(springs.size() == static_cast<std::size_t>(n));
  CHECK(springs[0].x0 == Approx(l.x_wall).margin(kPx));  // spring 1 starts at the wall
  CHECK(springs[0].x1 == Approx(beads[0].x - beads[0].radius).margin(kPx));  // to its surface
  CHECK(springs[1].x0 == Approx(beads[0].x + beads[0].radius).margin(kPx));
  CHECK(springs[0].coils >= 4);  // ~100 px apart: coils, not bars

  auto moved = rest_state(n);
  moved.psi[n - 1] = 2.0;
  const auto snap = cb::build_snapshot(moved, params, 0.0, style);
  const auto& b = snap.layers[cb::kLayerBeads].beads;
  CHECK(b[n - 1].x - beads[n - 1].x == Approx(2.0 * p.spacing).margin(kPx));
  CHECK(b[n - 1].y == Approx(p.centre_y).margin(kPx));
  CHECK(b[n - 2].x == beads[n - 2].x);
}

TEST_CASE("Transverse view: psi drawn across, beads evenly spaced along", "[snapshot]") {
  const int n = 12;
  const auto params = chain(n);
  cb::SnapshotStyle style;
  style.view = cb::View::Transverse;
  style.psi_range = 4.0;
  const auto rest = cb::build_snapshot(rest_state(n), params, 0.0, style);
  const auto& l = rest.layout;
  const auto& p = l.panels[0];
  REQUIRE(p.view == cb::View::Transverse);
  CHECK(p.spacing == Approx((l.x_right - l.x_wall) / n).margin(1e-4));
  CHECK(p.psi_scale == Approx(p.half_height / style.psi_range).margin(1e-4));
  auto moved = rest_state(n);
  moved.psi[n - 1] = 2.0;
  const auto snap = cb::build_snapshot(moved, params, 0.0, style);
  const auto& b0 = rest.layers[cb::kLayerBeads].beads;
  const auto& b = snap.layers[cb::kLayerBeads].beads;
  REQUIRE(b.size() == static_cast<std::size_t>(n));
  for (int j = 1; j <= n; ++j) CHECK(b[j - 1].x == Approx(l.x_wall + j * p.spacing).margin(kPx));
  // Up (y decreases) by psi_N * half_height / psi_range = half the half height.
  CHECK(b0[n - 1].y - b[n - 1].y == Approx(0.5 * p.half_height).margin(kPx));
  CHECK(b[n - 2].y == Approx(p.centre_y).margin(kPx));
}

TEST_CASE("Both views: two panels stacked, longitudinal on top", "[snapshot]") {
  const int n = 8;
  cb::SnapshotStyle style;
  style.view = cb::View::Both;
  const auto snap = cb::build_snapshot(rest_state(n), chain(n), 0.5, style);
  REQUIRE(snap.layout.panel_count == 2);
  CHECK(snap.layout.panels[0].view == cb::View::Longitudinal);
  CHECK(snap.layout.panels[1].view == cb::View::Transverse);
  CHECK(snap.layout.panels[0].bottom <= snap.layout.panels[1].top);
  CHECK(snap.layers[cb::kLayerBeads].beads.size() == static_cast<std::size_t>(2 * n));
}

TEST_CASE("Spring colours are strain_color(phi / phi_c)", "[snapshot]") {
  const int n = 20;
  auto state = rest_state(n);
  for (int j = 0; j < n; ++j) state.psi[j] = 0.3 * std::sin(0.7 * j) + 0.02 * j;
  cb::SnapshotStyle style;
  style.threshold = 0.25;
  for (double threshold : {0.25, 0.0}) {
    style.threshold = threshold;
    style.strain_range = 0.4;  // used when threshold <= 0
    const double scale = threshold > 0 ? threshold : style.strain_range;
    const auto snap = cb::build_snapshot(state, chain(n), 0.0, style);
    const auto& springs = snap.layers[cb::kLayerChain].springs;
    REQUIRE(springs.size() == static_cast<std::size_t>(n));
    for (int j = 1; j <= n; ++j) {
      INFO("spring " << j << ", scale " << scale);
      CHECK(same_color(springs[j - 1].color, cb::strain_color(cb::extension(state, j) / scale)));
    }
  }
}

TEST_CASE("Layout depends on the style only, the wall is hatched at 45 degrees", "[snapshot]") {
  const int n = 15;
  cb::SnapshotStyle style;
  auto other = rest_state(n);
  other.psi[4] = 0.7;
  other.tau = 3.0;
  const auto a = cb::build_snapshot(rest_state(n), chain(n), 0.1, style);
  const auto b = cb::build_snapshot(other, chain(n), 0.9, style);
  CHECK(a.layout.x_wall == b.layout.x_wall);
  CHECK(a.layout.x_right == b.layout.x_right);
  CHECK(a.layout.panels[0].centre_y == b.layout.panels[0].centre_y);
  CHECK(a.layout.panels[0].spacing == b.layout.panels[0].spacing);
  const auto& frame = a.layers[cb::kLayerFrame];
  int hatches = 0;
  for (const auto& s : frame.segments) {
    if (std::abs(std::abs(s.x1 - s.x0) - std::abs(s.y1 - s.y0)) < 1e-3 && s.x1 != s.x0) ++hatches;
  }
  CHECK(hatches >= 3);
  CHECK(has_label(a, "compression"));
  CHECK(has_label(a, "tension"));
  CHECK(has_label(a, "φ = +1"));  // unbreakable scale: strain_range = 1
  style.threshold = 1.5;
  CHECK(has_label(cb::build_snapshot(rest_state(n), chain(n), 0.1, style), "+φ_c = 1.5"));
  CHECK(has_label(b, "τ = 3.00"));
}

TEST_CASE("Force arrow: length proportional to f, gone when the pull string broke", "[snapshot]") {
  const int n = 5;
  cb::SnapshotStyle style;
  style.force_range = 2.0;
  const auto params = chain(n, 1.0, true);
  const auto state = rest_state(n);
  const auto half = cb::build_snapshot(state, params, 1.0, style);
  const auto quarter = cb::build_snapshot(state, params, 0.5, style);
  const double max_len = half.layout.arrow_max;
  CHECK(half.arrow_length == Approx(0.5 * max_len).margin(1e-9));
  CHECK(quarter.arrow_length == Approx(0.25 * max_len).margin(1e-9));
  // Geometry: shaft tail (after the string) to the head's tip spans arrow_length.
  const auto& force = half.layers[cb::kLayerForce];
  REQUIRE(force.triangles.size() == 1);
  REQUIRE(force.segments.size() == 2);  // the pull string, then the shaft
  const auto& string = force.segments[0];
  const auto& shaft = force.segments[1];
  const auto& bead_n = half.layers[cb::kLayerBeads].beads.back();
  CHECK(string.x0 == Approx(bead_n.x + bead_n.radius).margin(kPx));
  CHECK(string.x1 == Approx(string.x0 + half.layout.string_length).margin(kPx));
  CHECK(shaft.x0 == Approx(string.x1).margin(kPx));
  CHECK(force.triangles[0].x[0] - shaft.x0 == Approx(half.arrow_length).margin(kPx));
  // Pushing: points left, same span.
  const auto push = cb::build_snapshot(state, params, -1.0, style);
  CHECK(push.arrow_length == Approx(-0.5 * max_len).margin(1e-9));
  CHECK(push.layers[cb::kLayerForce].triangles[0].x[0] == Approx(shaft.x0).margin(kPx));
  // Beyond force_range the arrow stops at its maximum.
  CHECK(cb::build_snapshot(state, params, 10.0, style).arrow_length == Approx(max_len));

  auto broken = state;
  broken.string_broken = true;
  broken.breaks.push_back(cb::BreakEvent{0, 0.0, 0});
  const auto after = cb::build_snapshot(broken, params, 0.0, style);
  CHECK(after.arrow_length == 0.0);
  CHECK(after.layers[cb::kLayerForce].triangles.empty());
  CHECK(after.layers[cb::kLayerForce].segments.empty());
  CHECK(has_label(after, "pull string broke first, τ = 0.00"));
}

TEST_CASE("Breaking: recoiling halves, a fading flash and a marker that stays", "[snapshot]") {
  const int n = 30;
  const auto params = chain(n, 1.0);
  cb::SnapshotStyle style;
  style.threshold = 1.0;
  auto state = rest_state(n);
  state.tau = 12.0;
  const auto before = cb::build_snapshot(state, params, 0.5, style);
  CHECK_FALSE(has_label(before, "broke"));
  CHECK(before.breaks_shown.empty());

  // Spring 7 broke at tau = 12.5; the detached part (beads 7..N) moved on by 1.5.
  for (int j = 7; j <= n; ++j) state.psi[j - 1] = 1.5;
  state.broken = {7};
  state.breaks = {cb::BreakEvent{7, 12.5, 1250}};
  // The flash's glow is a translucent triangle fan (unshaded, unlike a bead).
  const auto flash_at = [](const cb::RenderSnapshot& s) {
    int count = 0;
    for (const auto& t : s.layers[cb::kLayerMarks].triangles) count += t.color.a < 1.0f;
    return count > 0 ? 1 : 0;
  };
  state.tau = 13.0;  // age 0.5
  const auto young = cb::build_snapshot(state, params, 0.5, style);
  REQUIRE(young.breaks_shown.size() == 1);
  CHECK(has_label(young, "spring 7 broke first, τ = 12.50"));
  CHECK(flash_at(young) == 1);
  const auto& springs = young.layers[cb::kLayerChain].springs;
  REQUIRE(springs.size() == static_cast<std::size_t>(n - 1 + 2));  // intact + two halves
  // The halves hang on beads 6 and 7 and point at each other.
  const auto& beads = young.layers[cb::kLayerBeads].beads;
  const auto& h1 = springs[n - 1];
  const auto& h2 = springs[n];
  CHECK(h1.x0 == Approx(beads[5].x).margin(kPx));
  CHECK(h2.x0 == Approx(beads[6].x).margin(kPx));
  CHECK(h1.x1 > h1.x0);
  CHECK(h2.x1 < h2.x0);
  CHECK(h1.color.r == h1.color.g);  // neutral grey: no strain colour

  state.tau = 20.0;  // age 7.5: recoiled to 30% of the gap, flash gone, marker stays
  const auto old = cb::build_snapshot(state, params, 0.5, style);
  CHECK(flash_at(old) == 0);
  CHECK(has_label(old, "spring 7 broke first, τ = 12.50"));
  const auto& o = old.layers[cb::kLayerChain].springs;
  const auto& ob = old.layers[cb::kLayerBeads].beads;
  // The gap is 2.5 spacings; a half is capped at the gap a spring breaks at,
  // spacing + phi_c * psi_scale = 2 spacings here, so it is 0.3 * 2 spacings long.
  const double gap = ob[6].x - ob[5].x;
  const double cap = 2.0 * old.layout.panels[0].spacing;
  CHECK(o[n - 1].x1 - o[n - 1].x0 == Approx(0.3 * std::min(gap, cap)).margin(kPx));

  // Two panels: each points at the break, only the longitudinal one labels it.
  style.view = cb::View::Both;
  const auto both = cb::build_snapshot(state, params, 0.5, style);
  int labels = 0;
  for (const auto& label : both.layers[cb::kLayerMarks].labels) {
    labels += label.text.find("spring 7") != std::string::npos;
  }
  CHECK(labels == 1);
  CHECK(both.layers[cb::kLayerMarks].triangles.size() == 2);

  // A break after this frame's time is not shown yet.
  state.tau = 12.0;
  CHECK(cb::build_snapshot(state, params, 0.5, style).breaks_shown.empty());
}

TEST_CASE("Breaking from the integrator shows the spring that broke", "[snapshot]") {
  cb::ChainParams params = chain(20, 0.5);
  cb::Forcing forcing;
  forcing.f = [](double) { return 1.0; };  // a step: the pull end breaks first
  cb::Integrator sim(params, forcing, {0.01, 1});
  while (sim.state().breaks.empty() && sim.state().step < 5000) REQUIRE(sim.step());
  REQUIRE_FALSE(sim.state().breaks.empty());
  const cb::BreakEvent first = sim.state().breaks.front();
  cb::SnapshotStyle style;
  style.threshold = 0.5;
  style.psi_range = 5.0;
  const auto snap = cb::build_snapshot(sim.state(), params, 1.0, style);
  char expected[64];
  std::snprintf(expected, sizeof expected, "spring %d broke first, τ = %.2f", first.spring, first.tau);
  CHECK(has_label(snap, expected));
}

TEST_CASE("Ribbon: N = 1e5 at 1920 px aggregates springs into pixel columns", "[snapshot]") {
  const int n = 100000, k = 50000;
  auto state = rest_state(n);
  for (int j = k; j <= n; ++j) state.psi[j - 1] = 0.5;  // only spring k is strained, phi = 0.5
  cb::SnapshotStyle style;
  style.width = 1920;
  style.height = 1080;
  style.threshold = 1.0;
  for (cb::View view : {cb::View::Longitudinal, cb::View::Transverse, cb::View::Both}) {
    style.view = view;
    const auto snap = cb::build_snapshot(state, chain(n), 0.5, style);
    INFO("view " << cb::view_name(view));
    REQUIRE(snap.ribbon);
    CHECK(snap.layers[cb::kLayerBeads].beads.empty());
    std::size_t rects = 0;
    for (const auto& l : snap.layers) rects += l.rects.size();
    CHECK(rects <= 2u * style.width);
    // The column holding spring k shows its colour; the chain at rest elsewhere is grey.
    const auto& p = snap.layout.panels[0];
    const double x = p.view == cb::View::Transverse
                         ? snap.layout.x_wall + (k - 0.5) * p.spacing
                         : snap.layout.x_wall + (k - 0.5 + 0.25) * p.spacing;
    const double y = p.view == cb::View::Transverse ? p.centre_y - 0.25 * p.psi_scale : p.centre_y;
    bool found = false;
    for (const auto& r : snap.layers[cb::kLayerChain].rects) {
      if (x >= r.x && x < r.x + r.w && y >= r.y && y <= r.y + r.h) {
        found = true;
        CHECK(same_color(r.color, cb::strain_color(0.5)));
      }
    }
    CHECK(found);
    CHECK(same_color(snap.layers[cb::kLayerChain].rects.front().color, cb::strain_color(0.0)));
  }
}

TEST_CASE("Ribbon: N = 1e6 needs O(width) elements", "[snapshot]") {
  const int n = 1000000;
  auto state = rest_state(n);
  for (int j = 0; j < n; ++j) state.psi[j] = 0.8 * std::sin(j * 1e-5);
  cb::SnapshotStyle style;
  style.view = cb::View::Both;
  const auto snap = cb::build_snapshot(state, chain(n), 0.5, style);
  CHECK(snap.ribbon);
  CHECK(element_count(snap) <= 4u * style.width);
  CHECK(snap.layers[cb::kLayerChain].springs.empty());
}
