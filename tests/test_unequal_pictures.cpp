// Pictures of unequal chains (issue #21): a bead's area follows its mass, a spring's width its
// stiffness (relative to the median, clamped), strain colours are phi_j / phi_c,j. Checked
// exactly on snapshots (no GL), then as pixels on trivial shapes; the uniform chain written
// with arrays of ones must draw exactly what the empty arrays draw.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <vector>

#include "gl_test_support.h"
#include "output/image.h"
#include "render/renderer.h"
#include "snapshot/snapshot.h"

namespace {

cb::ChainState state_with(const std::vector<double>& psi) {
  cb::ChainState s;
  s.psi = psi;
  s.vel.assign(psi.size(), 0.0);
  return s;
}

bool same(const cb::Color& a, const cb::Color& b) {
  return a.r == b.r && a.g == b.g && a.b == b.b && a.a == b.a;
}

// Every shape of two snapshots, field by field (exact: the same floats).
void check_identical(const cb::RenderSnapshot& a, const cb::RenderSnapshot& b) {
  REQUIRE(a.layers.size() == b.layers.size());
  for (std::size_t k = 0; k < a.layers.size(); ++k) {
    const cb::Layer &x = a.layers[k], &y = b.layers[k];
    INFO("layer " << k);
    REQUIRE(x.beads.size() == y.beads.size());
    for (std::size_t i = 0; i < x.beads.size(); ++i) {
      CHECK(x.beads[i].x == y.beads[i].x);
      CHECK(x.beads[i].y == y.beads[i].y);
      CHECK(x.beads[i].radius == y.beads[i].radius);
      CHECK(same(x.beads[i].color, y.beads[i].color));
    }
    REQUIRE(x.springs.size() == y.springs.size());
    for (std::size_t i = 0; i < x.springs.size(); ++i) {
      CHECK(x.springs[i].x0 == y.springs[i].x0);
      CHECK(x.springs[i].x1 == y.springs[i].x1);
      CHECK(x.springs[i].y0 == y.springs[i].y0);
      CHECK(x.springs[i].y1 == y.springs[i].y1);
      CHECK(x.springs[i].width == y.springs[i].width);
      CHECK(x.springs[i].coils == y.springs[i].coils);
      CHECK(same(x.springs[i].color, y.springs[i].color));
    }
    REQUIRE(x.rects.size() == y.rects.size());
    for (std::size_t i = 0; i < x.rects.size(); ++i) {
      CHECK(x.rects[i].x == y.rects[i].x);
      CHECK(x.rects[i].w == y.rects[i].w);
      CHECK(same(x.rects[i].color, y.rects[i].color));
    }
    REQUIRE(x.labels.size() == y.labels.size());
    for (std::size_t i = 0; i < x.labels.size(); ++i) {
      CHECK(x.labels[i].text == y.labels[i].text);
      CHECK(x.labels[i].x == y.labels[i].x);
      CHECK(x.labels[i].y == y.labels[i].y);
    }
    CHECK(x.segments.size() == y.segments.size());
    CHECK(x.triangles.size() == y.triangles.size());
  }
}

}  // namespace

TEST_CASE("Area and width ratios: the median's, clamped", "[snapshot][unequal]") {
  cb::ChainParams p;
  p.beads = 7;
  // Sorted: 0.01 0.5 1 1 1 2 10; the (lower) median is 1. 10 and 0.01 clamp to 4 and 1/4.
  p.mass = {1, 2, 1, 0.5, 10, 0.01, 1};
  CHECK(cb::bead_area_ratios(p) == std::vector<double>{1, 2, 1, 0.5, 4, 0.25, 1});
  // Half and half: the lower median is the softer material's, so the stiff half is 2x (the
  // clamp) and the soft half 1.
  p.stiffness = {1, 1, 1, 1, 4, 4, 4, 4};
  CHECK(cb::spring_width_ratios(p) == std::vector<double>{1, 1, 1, 1, 2, 2, 2, 2});
  p.stiffness = {2, 2, 2, 2, 2, 2, 1};  // relative to the median 2: only the last differs
  CHECK(cb::spring_width_ratios(p) == std::vector<double>{1, 1, 1, 1, 1, 1, 0.5});
  p.mass.clear();
  p.stiffness.clear();
  CHECK(cb::bead_area_ratios(p).empty());
  CHECK(cb::spring_width_ratios(p).empty());
}

TEST_CASE("Bead areas follow masses, spring widths stiffness, colours phi_j / phi_c,j",
          "[snapshot][unequal]") {
  cb::ChainParams p;
  p.beads = 7;
  p.threshold = 2.0;
  p.mass = {1, 2, 1, 0.5, 10, 0.01, 1};
  p.stiffness = {1, 1.5, 1, 0.2, 9, 1, 1};
  p.thresholds = {2, 1, 4, 0.5, 2, std::numeric_limits<double>::infinity(), 2};
  // psi: extensions phi_j = 0.3, -0.2, 0.5, 0.1, -0.4, 0.25, 0.05.
  const std::vector<double> phi{0.3, -0.2, 0.5, 0.1, -0.4, 0.25, 0.05};
  std::vector<double> psi;
  double sum = 0;
  for (double x : phi) psi.push_back(sum += x);
  cb::SnapshotStyle style;  // 1280x720, longitudinal, dark
  style.threshold = 0.5;    // the smallest phi_c,j, as the app sets it
  style.psi_range = 2.0;
  const cb::RenderSnapshot snap = cb::build_snapshot(state_with(psi), p, 0.0, style);
  const cb::PanelLayout& panel = snap.layout.panels[0];
  const auto& beads = snap.layers[cb::kLayerBeads].beads;
  const auto& springs = snap.layers[cb::kLayerChain].springs;
  REQUIRE(beads.size() == 7);
  REQUIRE(springs.size() == 7);
  const std::vector<double> area{1, 2, 1, 0.5, 4, 0.25, 1};
  const double r = panel.bead_radius;
  for (int j = 1; j <= 7; ++j) {
    INFO("bead " << j);
    // Area ratio = (r_j / r_median)^2, up to the radius' float rounding.
    CHECK(double(beads[j - 1].radius) * beads[j - 1].radius / (r * r) ==
          Approx(area[j - 1]).epsilon(1e-6));
  }
  // The heaviest bead (area 4) is twice the median's radius, and fits in 45% of the spacing.
  CHECK(panel.largest_bead_radius == Approx(2.0 * r).epsilon(1e-6));
  CHECK(panel.largest_bead_radius <= 0.45 * panel.spacing + 1e-3);
  const std::vector<double> width{1, 1.5, 1, 0.5, 2, 1, 1};  // 0.2 and 9 clamp to 1/2 and 2
  for (int j = 1; j <= 7; ++j) {
    INFO("spring " << j);
    CHECK(springs[j - 1].width == Approx(panel.spring_width * width[j - 1]).epsilon(1e-6));
    // phi_j / phi_c,j; spring 6 cannot break and keeps the frame's scale (0.5).
    const double scale = j == 6 ? 0.5 : p.thresholds[j - 1];
    const double extension = psi[j - 1] - (j > 1 ? psi[j - 2] : 0.0);
    CHECK(same(springs[j - 1].color, cb::strain_color(extension / scale, style.theme)));
  }
  // The widest spring (2x) at most 2.2 median radii across.
  CHECK(2.0 * panel.spring_width <= 2.2 * r + 1e-3);
  // The colour bar says what the colours mean.
  bool legend = false;
  for (const cb::Label& l : snap.layers[cb::kLayerFrame].labels) legend |= l.text == "+φ_{c,j}";
  CHECK(legend);
}

TEST_CASE("The uniform chain written with arrays of ones draws exactly as without them",
          "[snapshot][unequal]") {
  const int n = 30;
  cb::ChainParams uniform;
  uniform.beads = n;
  uniform.threshold = 1.5;
  cb::ChainParams ones = uniform;
  ones.mass.assign(n, 1.0);
  ones.stiffness.assign(n, 1.0);
  ones.thresholds.assign(n, 1.5);
  std::vector<double> psi(n);
  for (int j = 1; j <= n; ++j) psi[j - 1] = 0.9 * std::sin(0.3 * j) + 0.05 * j;
  cb::ChainState s = state_with(psi);
  s.tau = 10.0;
  s.broken = {12, 20};
  s.breaks = {{20, 9.2, 920}, {12, 9.6, 960}};
  for (const cb::View view : {cb::View::Longitudinal, cb::View::Both}) {
    for (const int width : {1280, 200}) {  // beads, and the ribbon at 200 px
      INFO(cb::view_name(view) << ", " << width << " px");
      cb::SnapshotStyle style;
      style.view = view;
      style.width = width;
      style.threshold = 1.5;
      style.psi_range = 3.0;
      check_identical(cb::build_snapshot(s, uniform, 0.7, style),
                      cb::build_snapshot(s, ones, 0.7, style));
    }
  }
}

TEST_CASE("The strain ribbon colours each column by its largest phi_j / phi_c,j",
          "[snapshot][unequal]") {
  // N = 1e5 at 1280 px: the ribbon. phi_j = 0.5 everywhere; the right half has phi_c,j = 2,
  // the left half 1, so the left is coloured 0.5 and the right 0.25 of the way to breaking.
  const int n = 100000;
  cb::ChainParams p;
  p.beads = n;
  p.threshold = 1.0;
  p.thresholds.assign(n, 1.0);
  std::fill(p.thresholds.begin() + n / 2, p.thresholds.end(), 2.0);
  std::vector<double> psi(n);
  for (int j = 1; j <= n; ++j) psi[j - 1] = 0.5 * j;
  cb::SnapshotStyle style;
  style.threshold = 1.0;
  style.psi_range = psi.back();
  const cb::RenderSnapshot snap = cb::build_snapshot(state_with(psi), p, 0.0, style);
  REQUIRE(snap.ribbon);
  const auto& rects = snap.layers[cb::kLayerChain].rects;
  REQUIRE(rects.size() >= 2);
  const cb::SnapshotLayout& l = snap.layout;
  // Bead n/2 sits at x_wall + (n/2 + psi_{n/2}) * spacing.
  const double middle = l.x_wall + (n / 2 + psi[n / 2 - 1]) * l.panels[0].spacing;
  int left = 0, right = 0;
  for (const cb::Rect& r : rects) {
    if (r.x + r.w <= middle + 1) {  // a column either side of the middle may hold both
      CHECK(same(r.color, cb::strain_color(0.5, style.theme)));
      ++left;
    } else if (r.x >= middle - 1) {
      CHECK(same(r.color, cb::strain_color(0.25, style.theme)));
      ++right;
    }
  }
  CHECK(left >= 1);
  CHECK(right >= 1);
}

TEST_CASE("A bead four times the median mass inks four times the pixels", "[render][unequal]") {
  auto context = cb::test::create_or_skip(cb::GlBackend::Auto);
  if (!context) return;
  // Three beads far apart, masses 1, 4, 1 (area ratios 1, 4, 1); the springs and the force
  // taken out of the snapshot so that only the beads ink their squares.
  cb::ChainParams p;
  p.beads = 3;
  p.mass = {1, 4, 1};
  cb::SnapshotStyle style;
  style.width = 640;
  style.height = 360;
  style.strain_range = 1.0;
  cb::RenderSnapshot snap = cb::build_snapshot(state_with({0, 0, 0}), p, 0.0, style);
  snap.layers[cb::kLayerChain] = {};
  snap.layers[cb::kLayerForce] = {};
  const auto& beads = snap.layers[cb::kLayerBeads].beads;
  REQUIRE(beads.size() == 3);
  cb::Renderer renderer(style.width, style.height);
  const cb::Image image = renderer.render(snap);
  // Inked pixels (any channel 8 or more off the background) within each bead's square.
  const auto inked = [&](const cb::BeadInstance& b) {
    const double R = b.radius + 2;
    int count = 0;
    for (int y = static_cast<int>(b.y - R); y <= static_cast<int>(b.y + R); ++y)
      for (int x = static_cast<int>(b.x - R); x <= static_cast<int>(b.x + R); ++x) {
        const std::uint8_t* px = image.pixel(x, y);
        const float bg[3] = {snap.background.r, snap.background.g, snap.background.b};
        bool ink = false;
        for (int k = 0; k < 3; ++k)
          ink |= std::abs(int(px[k]) - int(std::lround(bg[k] * 255.0f))) >= 8;
        count += ink;
      }
    return count;
  };
  const int light = inked(beads[0]), heavy = inked(beads[1]), other = inked(beads[2]);
  INFO("inked pixels: " << light << ", " << heavy << ", " << other << "; radii " << beads[0].radius
                        << ", " << beads[1].radius);
  CHECK(light == Approx(other).epsilon(0.02));  // the same size at another sub-pixel offset
  // pi r^2 each, up to the antialiased rim (about 2 pi r pixels partly covered): within 10%.
  CHECK(static_cast<double>(heavy) / light == Approx(4.0).epsilon(0.10));
  CHECK(light == Approx(3.14159265 * beads[0].radius * beads[0].radius).epsilon(0.15));
}
