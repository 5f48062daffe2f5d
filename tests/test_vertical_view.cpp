// The vertical view (issue #22): a hanging chain drawn hanging. Checked exactly on the snapshot
// (no GL): bead j at x = chain_x, y = ceiling_y + (j + psi_j) * spacing (snapshot.h), below
// bead j - 1; the hatched ceiling above bead 1; the force arrow pointing down at bead N;
// Heald's ball on two strings; break labels that never overlap; and the scenes of issue #22
// picking the view by default. Positions to float rounding (1e-3 px, as test_snapshot.cpp).
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <string>
#include <vector>

#include "app/frames.h"
#include "scene/scene.h"
#include "snapshot/snapshot.h"

namespace {

constexpr double kPx = 1e-3;

cb::ChainParams hanging(int beads, double gravity, bool pull_string = false) {
  cb::ChainParams p;
  p.beads = beads;
  p.threshold = 1.0;
  p.gravity = gravity;
  p.pull_string = pull_string;
  return p;
}

// The hanging equilibrium of a uniform chain, independently of the physics code:
// phi_j = G (N - j + 1) (issue #22: phi_eq,j = G sum_{i>=j} m_i / K_j), psi_j = sum_{i<=j} phi_i.
cb::ChainState equilibrium(int beads, double gravity) {
  cb::ChainState s;
  double psi = 0.0;
  for (int j = 1; j <= beads; ++j) s.psi.push_back(psi += gravity * (beads - j + 1));
  s.vel.assign(beads, 0.0);
  return s;
}

cb::SnapshotStyle vertical_style(double psi_range) {
  cb::SnapshotStyle style;
  style.width = 1280;
  style.height = 720;
  style.view = cb::View::Vertical;
  style.psi_range = psi_range;
  style.force_range = 1.0;
  style.threshold = 1.0;
  return style;
}

}  // namespace

TEST_CASE("vertical view: beads hang below the ceiling at psi scaled, the arrow points down",
          "[snapshot][vertical]") {
  const int n = 30;
  const double g = 0.01;
  const cb::ChainState state = equilibrium(n, g);
  const auto snap =
      cb::build_snapshot(state, hanging(n, g), 0.4, vertical_style(state.psi.back() + 5.0));
  REQUIRE(snap.layout.panel_count == 1);
  const cb::PanelLayout& p = snap.layout.panels[0];
  REQUIRE(p.view == cb::View::Vertical);
  CHECK_FALSE(snap.ribbon);
  const auto& beads = snap.layers[cb::kLayerBeads].beads;
  REQUIRE(beads.size() == static_cast<std::size_t>(n));
  for (int j = 1; j <= n; ++j) {
    INFO("bead " << j);
    CHECK(beads[j - 1].x == Approx(p.chain_x).margin(kPx));
    CHECK(beads[j - 1].y == Approx(p.ceiling_y + (j + state.psi[j - 1]) * p.spacing).margin(kPx));
    if (j > 1) CHECK(beads[j - 1].y > beads[j - 2].y);  // down the frame, y grows
  }
  // The ceiling: a filled block whose lower face is bead 0's height, above bead 1, spanning
  // the chain's column, hatched, with its face drawn across.
  const auto& back = snap.layers[cb::kLayerFrame];
  const auto ceiling = std::find_if(back.rects.begin(), back.rects.end(), [&](const cb::Rect& r) {
    return std::abs(r.y + r.h - p.ceiling_y) < kPx && r.x < p.chain_x && r.x + r.w > p.chain_x;
  });
  REQUIRE(ceiling != back.rects.end());
  CHECK(ceiling->h > 0.0f);
  CHECK(p.ceiling_y < beads[0].y - beads[0].radius);
  int hatch = 0;
  bool face = false;
  for (const cb::Segment& s : back.segments) {
    const bool inside = std::min(s.x0, s.x1) >= ceiling->x - kPx &&
                        std::max(s.x0, s.x1) <= ceiling->x + ceiling->w + kPx &&
                        std::min(s.y0, s.y1) >= ceiling->y - kPx &&
                        std::max(s.y0, s.y1) <= ceiling->y + ceiling->h + kPx;
    if (inside && std::abs((s.x1 - s.x0) + (s.y1 - s.y0)) < 1e-2) ++hatch;  // x + y = k
    face |= s.y0 == p.ceiling_y && s.y1 == p.ceiling_y && s.x0 < p.chain_x && s.x1 > p.chain_x;
  }
  CHECK(hatch >= 5);
  CHECK(face);
  // Springs run straight down the column, from the ceiling to bead 1 and bead to bead.
  const auto& springs = snap.layers[cb::kLayerChain].springs;
  REQUIRE(springs.size() == static_cast<std::size_t>(n));
  CHECK(springs[0].y0 == Approx(p.ceiling_y).margin(kPx));
  for (const auto& s : springs) {
    CHECK(s.x0 == Approx(p.chain_x).margin(kPx));
    CHECK(s.x1 == Approx(p.chain_x).margin(kPx));
    CHECK(s.y1 > s.y0);
  }
  // The pull: f = 0.4 of force_range 1 is 0.4 of the longest arrow, pointing down from bead N.
  CHECK(snap.arrow_length == Approx(0.4 * snap.layout.arrow_max).margin(kPx));
  const auto& force = snap.layers[cb::kLayerForce];
  REQUIRE(force.triangles.size() == 1);
  const cb::Triangle& head = force.triangles[0];
  const cb::BeadInstance& last = beads.back();
  CHECK(head.x[0] == Approx(p.chain_x).margin(kPx));
  CHECK(head.y[0] > head.y[1]);  // the tip below the head's base
  CHECK(head.y[1] == Approx(head.y[2]).margin(kPx));
  CHECK(
      head.y[0] ==
      Approx(last.y + last.radius + 0.25 * snap.layout.text_size + snap.arrow_length).margin(kPx));
}

TEST_CASE("vertical view: one bead on the pull string is Heald's ball on two strings",
          "[snapshot][vertical]") {
  const double g = 0.05;
  const cb::ChainState state = equilibrium(1, g);
  const auto snap = cb::build_snapshot(state, hanging(1, g, true), 0.3, vertical_style(1.0));
  const cb::PanelLayout& p = snap.layout.panels[0];
  const auto& beads = snap.layers[cb::kLayerBeads].beads;
  REQUIRE(beads.size() == 1);
  const cb::BeadInstance& ball = beads[0];
  CHECK(ball.y == Approx(p.ceiling_y + (1.0 + g) * p.spacing).margin(kPx));
  // The upper string: straight (no coil) from the ceiling to the top of the ball.
  const auto& springs = snap.layers[cb::kLayerChain].springs;
  REQUIRE(springs.size() == 1);
  CHECK(springs[0].coils == 0.0f);
  CHECK(springs[0].x0 == Approx(p.chain_x).margin(kPx));
  CHECK(springs[0].y0 == Approx(p.ceiling_y).margin(kPx));
  CHECK(springs[0].y1 == Approx(ball.y - ball.radius).margin(kPx));
  // The lower string: from the bottom of the ball straight down, then the arrow below it.
  const auto& force = snap.layers[cb::kLayerForce];
  REQUIRE(!force.segments.empty());
  const cb::Segment& lower = force.segments[0];
  CHECK(lower.x0 == Approx(p.chain_x).margin(kPx));
  CHECK(lower.x1 == Approx(p.chain_x).margin(kPx));
  CHECK(lower.y0 == Approx(ball.y + ball.radius).margin(kPx));
  CHECK(lower.y1 == Approx(ball.y + ball.radius + snap.layout.string_length).margin(kPx));
  REQUIRE(force.triangles.size() == 1);
  CHECK(force.triangles[0].y[0] > lower.y1);
  // A hanging chain longer than one bead keeps its coils.
  const auto two =
      cb::build_snapshot(equilibrium(2, g), hanging(2, g, true), 0.3, vertical_style(1.0));
  CHECK(two.layers[cb::kLayerChain].springs[0].coils > 0.0f);
}

TEST_CASE("vertical view: break labels beside the chain never overlap, the first in bold",
          "[snapshot][vertical]") {
  // A cascade near the ceiling (the same breaks as test_golden.cpp's cascade_labels), each
  // broken spring opened by 1.5.
  const int n = 30;
  const std::vector<cb::BreakEvent> breaks{
      {30, 51.60, 0}, {19, 55.71, 0}, {20, 55.71, 0}, {14, 55.76, 0}, {10, 55.76, 0},
      {2, 55.77, 0},  {6, 55.79, 0},  {5, 55.79, 0},  {7, 55.81, 0},  {8, 55.82, 0},
      {12, 55.84, 0}, {16, 55.85, 0}, {17, 55.86, 0}, {22, 55.93, 0}, {4, 58.88, 0}};
  cb::ChainState state;
  state.tau = 60.0;
  state.breaks = breaks;
  for (const cb::BreakEvent& b : breaks) state.broken.push_back(b.spring);
  std::sort(state.broken.begin(), state.broken.end());
  double shift = 0.0;
  for (int j = 1; j <= n; ++j) {
    if (std::binary_search(state.broken.begin(), state.broken.end(), j)) shift += 1.5;
    state.psi.push_back(shift);
  }
  state.vel.assign(n, 0.0);
  for (const int height : {720, 270}) {  // roomy and cramped
    INFO("height " << height);
    cb::SnapshotStyle style = vertical_style(state.psi.back());
    style.height = height;
    style.width = height * 16 / 9;
    const auto snap = cb::build_snapshot(state, hanging(n, 0.01), 0.0, style);
    const cb::PanelLayout& p = snap.layout.panels[0];
    const auto& labels = snap.break_labels;
    REQUIRE(!labels.empty());
    CHECK(labels[0].first);
    CHECK(labels[0].spring == 30);
    int named = 0;
    for (std::size_t a = 0; a < labels.size(); ++a) {
      named += labels[a].spring > 0 ? 1 : 0;
      CHECK(labels[a].first == (a == 0));
      CHECK(labels[a].box.x > p.chain_x + p.largest_bead_radius);  // right of the chain
      CHECK(labels[a].box.y >= p.top - kPx);
      CHECK(labels[a].box.bottom() <= p.bottom + kPx);
      for (std::size_t b = a + 1; b < labels.size(); ++b) {
        INFO("labels " << a << " and " << b);
        CHECK_FALSE(labels[a].box.intersects(labels[b].box));
      }
    }
    CHECK(named + snap.breaks_unlabelled == static_cast<int>(breaks.size()));
    if (height == 720) CHECK(snap.breaks_unlabelled < static_cast<int>(breaks.size()) - 1);
    // The bold label is the first break's.
    int bold = 0;
    for (const cb::Label& l : snap.layers[cb::kLayerMarks].labels)
      if (l.face == cb::FontFace::Bold) {
        ++bold;
        CHECK(l.text.rfind("spring 30 broke first", 0) == 0);
      }
    CHECK(bold == 1);
  }
}

TEST_CASE("a hanging chain's scenes render in the vertical view unless they say otherwise",
          "[snapshot][vertical][scene]") {
  const std::string dir = std::string(CHAINBREAK_SCENES) + "/";
  for (const char* file : {"hanging_chain.toml", "inertia_ball.toml", "gravity/ball_heavy.toml"}) {
    INFO(file);
    const cb::SceneDesc scene = cb::load_scene(dir + file);
    CHECK(scene.render.view == "vertical");
    CHECK(cb::snapshot_style(scene, scene.render, cb::RunExtent{}).view == cb::View::Vertical);
  }
  // Without weight the default stays, and a scene's own render.view wins over the default.
  CHECK(cb::load_scene(dir + "ball_pull.toml").render.view == "longitudinal");
  CHECK(cb::load_scene(dir + "gravity/ball_weightless.toml").render.view == "longitudinal");
  const auto told =
      cb::load_scene(dir + "hanging_chain.toml", {cb::parse_override("render.view=transverse")});
  CHECK(told.render.view == "transverse");
  CHECK(cb::load_scene(dir + "ball_pull.toml", {cb::parse_override("chain.gravity=0.05")})
            .render.view == "vertical");
}
