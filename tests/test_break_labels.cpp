// Break labels never overlap (issue #21, pictures): the placement of snapshot/break_labels.h
// checked on exact rectangles, without GL, and then on whole snapshots of cascades. The
// overlap test here is written independently of LabelBox::intersects: two boxes overlap when
// both their open x and open y intervals do.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <random>
#include <string>

#include "physics/integrator.h"
#include "snapshot/break_labels.h"
#include "snapshot/snapshot.h"
#include "text/text_layout.h"
#include "theme/theme.h"

namespace {

bool open_overlap(double a0, double a1, double b0, double b1) {
  return a0 < b1 && b0 < a1;
}

// Box a, widened by `gap` left and right, and box b share interior points.
bool boxes_overlap(const cb::LabelBox& a, const cb::LabelBox& b, double gap) {
  return open_overlap(a.x - gap, a.x + a.w + gap, b.x, b.x + b.w) &&
         open_overlap(a.y, a.y + a.h, b.y, b.y + b.h);
}

// A vertical leader at x from y0 to y1 runs through box b widened by `gap`.
bool leader_hits(double x, double y0, double y1, const cb::LabelBox& b, double gap) {
  return b.x - gap < x && x < b.x + b.w + gap && open_overlap(y0, y1, b.y, b.y + b.h);
}

cb::LabelArea area_of(int rows, double x_max) {
  cb::LabelArea a;
  a.first_row_y = 100;
  a.row_h = 24;
  a.rows = rows;
  a.box_above = 4;
  a.box_h = 22;
  a.leader_end = 8;
  a.x_min = 10;
  a.x_max = x_max;
  a.offset = 8;
  a.gap = 6;
  return a;
}

double more_width(int k) {
  return 60.0 + 8.0 * std::to_string(k).size();
}
double suffix_width(int k) {
  return 70.0 + 8.0 * std::to_string(k).size();
}

// Every property the placement promises, for any input.
void check_plan(const std::vector<cb::LabelRequest>& requests, const cb::LabelArea& a,
                const cb::LabelPlan& plan) {
  REQUIRE_FALSE(plan.labels.empty());
  CHECK(plan.labels.front().request == 0);  // the first break's label is always there
  int later = 0, more = 0;
  for (std::size_t i = 0; i < plan.labels.size(); ++i) {
    const cb::PlacedLabel& p = plan.labels[i];
    INFO("label " << i << " (request " << p.request << ") row " << p.row << " at " << p.box.x
                  << ", " << p.box.y << " size " << p.box.w << " x " << p.box.h);
    CHECK(p.row >= 0);
    CHECK(p.row < a.rows);
    CHECK(p.box.y == Approx(a.first_row_y + p.row * a.row_h - a.box_above));
    CHECK(p.box.h == a.box_h);
    if (p.box.w <= a.x_max - a.x_min) {  // inside the area
      CHECK(p.box.x >= a.x_min);
      CHECK(p.box.x + p.box.w <= a.x_max + 1e-9);
    }
    if (p.request > 0) ++later;
    if (p.request < 0) ++more;
    if (p.request >= 0) {
      const double extra = p.request == 0 && plan.more_in_first ? suffix_width(plan.dropped) : 0.0;
      CHECK(p.box.w == requests[p.request].width + extra);
    }
    if (p.has_leader) {  // from its pointer down to its own row, beside its own box
      CHECK(p.leader_x == requests[p.request].anchor_x);
      CHECK(p.leader_y0 == requests[p.request].leader_top);
      CHECK(p.leader_y1 == Approx(p.y + a.leader_end));
      CHECK_FALSE((p.box.x < p.leader_x && p.leader_x < p.box.x + p.box.w));
    }
    for (std::size_t k = 0; k < plan.labels.size(); ++k) {
      if (k == i) continue;
      const cb::PlacedLabel& q = plan.labels[k];
      INFO("against label " << k << " (request " << q.request << ") row " << q.row << " at "
                            << q.box.x << " size " << q.box.w);
      CHECK_FALSE(boxes_overlap(p.box, q.box, a.gap - 1e-9));
      if (p.has_leader)
        CHECK_FALSE(leader_hits(p.leader_x, p.leader_y0, p.leader_y1, q.box, a.gap - 1e-9));
    }
  }
  // Every request is labelled once or counted.
  std::vector<int> seen;
  for (const cb::PlacedLabel& p : plan.labels)
    if (p.request >= 0) seen.push_back(p.request);
  std::sort(seen.begin(), seen.end());
  CHECK(std::adjacent_find(seen.begin(), seen.end()) == seen.end());
  CHECK(later + plan.dropped == static_cast<int>(requests.size()) - 1);
  CHECK(more == (plan.has_more ? 1 : 0));
  CHECK(plan.has_more == (plan.dropped > 0 && !plan.more_in_first));
  if (plan.has_more) CHECK(plan.labels.back().box.w == more_width(plan.dropped));
}

}  // namespace

TEST_CASE("One label goes right of its leader in the top row, left of it at the right edge",
          "[snapshot][labels]") {
  const cb::LabelArea a = area_of(5, 500);
  // Leader from the pointer at (200, 80) down to row 0: text at 200 + offset.
  cb::LabelPlan plan = cb::place_labels({{200, 80, 120}}, a, more_width, suffix_width);
  REQUIRE(plan.labels.size() == 1);
  const cb::PlacedLabel& p = plan.labels[0];
  CHECK(p.row == 0);
  CHECK(p.x == 208.0);
  CHECK(p.y == 100.0);
  CHECK(p.box.x == 208.0);
  CHECK(p.box.y == 96.0);
  CHECK(p.box.w == 120.0);
  CHECK(p.box.h == 22.0);
  CHECK(p.has_leader);
  CHECK(p.leader_y0 == 80.0);
  CHECK(p.leader_y1 == 108.0);
  CHECK(plan.dropped == 0);
  // Near the right edge (500) the text would leave the area: it ends left of the leader.
  plan = cb::place_labels({{450, 80, 120}}, a, more_width, suffix_width);
  CHECK(plan.labels[0].x == 450.0 - 8.0 - 120.0);
  CHECK(plan.labels[0].row == 0);
}

TEST_CASE("A cascade forms a staircase: each leader drops left of the labels above it",
          "[snapshot][labels]") {
  const cb::LabelArea a = area_of(8, 1000);
  // The first break at the pulled end (x = 900), then three breaks near the wall, 40 px apart
  // (labels 150 px wide cannot share a row).
  const std::vector<cb::LabelRequest> r{
      {900, 80, 150}, {100, 80, 150}, {140, 80, 150}, {180, 80, 150}};
  const cb::LabelPlan plan = cb::place_labels(r, a, more_width, suffix_width);
  check_plan(r, a, plan);
  REQUIRE(plan.labels.size() == 4);
  CHECK(plan.dropped == 0);
  // The first break keeps row 0 (its text fits right of nothing else's leader); the rest go
  // right to left down the rows: x = 180 in row 0 (right of its leader, clear of the first's
  // label at 742..892), then 140 in row 1, 100 in row 2.
  const auto row_of = [&](int request) {
    for (const cb::PlacedLabel& p : plan.labels)
      if (p.request == request) return p.row;
    return -1;
  };
  CHECK(row_of(0) == 0);
  CHECK(row_of(3) == 0);
  CHECK(row_of(2) == 1);
  CHECK(row_of(1) == 2);
}

TEST_CASE("Breaks that do not fit are counted; the first break's label never gives way",
          "[snapshot][labels]") {
  // One row, 280 px wide: the first label (200 px) fills most of it.
  cb::LabelArea a = area_of(1, 290);
  std::vector<cb::LabelRequest> r{{20, 80, 200}};
  for (int k = 0; k < 10; ++k) r.push_back({30.0 + 5 * k, 80, 150});
  cb::LabelPlan plan = cb::place_labels(r, a, more_width, suffix_width);
  check_plan(r, a, plan);
  CHECK(plan.labels.front().request == 0);
  CHECK(plan.dropped == 10);  // every leader would run through the first label
  // No room for "+10 more" beside it either: the count joins the first label's text.
  CHECK(plan.more_in_first);
  CHECK(plan.labels.size() == 1);
  CHECK(plan.labels.front().box.w == 200 + suffix_width(10));
  CHECK(plan.labels.front().box.x == a.x_min);  // wider than the area: from its left edge

  // With room to its right, the count stands on its own.
  a = area_of(1, 600);
  plan = cb::place_labels(r, a, more_width, suffix_width);
  check_plan(r, a, plan);
  CHECK(plan.has_more);
  CHECK_FALSE(plan.more_in_first);
  CHECK(plan.labels.back().request == -1);
}

TEST_CASE("Random cascades: no two labels or a label and a leader ever meet",
          "[snapshot][labels]") {
  std::mt19937 rng(20261125);  // fixed: the same 2000 cases on every machine
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int dropped = 0, placed = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const int rows = 1 + static_cast<int>(unit(rng) * 10);
    const double width = 200 + unit(rng) * 1800;
    const cb::LabelArea a = area_of(rows, width);
    const int n = 1 + static_cast<int>(unit(rng) * (trial % 20 == 0 ? 300 : 40));
    std::vector<cb::LabelRequest> r;
    const bool clustered = unit(rng) < 0.5;  // a cascade: anchors in a narrow band
    const double band_x = a.x_min + unit(rng) * (width - a.x_min);
    for (int i = 0; i < n; ++i) {
      const double x = clustered ? std::min(width, band_x + unit(rng) * 120)
                                 : a.x_min + unit(rng) * (width - a.x_min);
      // Widths up to wider than the whole area (a tiny frame).
      r.push_back({x, 60 + unit(rng) * 30, 40 + unit(rng) * (trial % 7 == 0 ? 2.0 * width : 260)});
    }
    INFO("trial " << trial << ": " << n << " requests, " << rows << " rows, width " << width);
    const cb::LabelPlan plan = cb::place_labels(r, a, more_width, suffix_width);
    check_plan(r, a, plan);
    dropped += plan.dropped;
    placed += static_cast<int>(plan.labels.size());
  }
  // Not vacuous: both outcomes are exercised many times.
  CHECK(dropped > 1000);
  CHECK(placed > 5000);
}

namespace {

// A state of N beads with `breaks` springs broken, the given ones at the given times, the
// beads spread as after a cascade (every broken spring opened by 1.5).
cb::ChainState cascade_state(int beads, const std::vector<cb::BreakEvent>& breaks, double tau) {
  cb::ChainState s;
  s.psi.assign(beads, 0.0);
  s.vel.assign(beads, 0.0);
  s.tau = tau;
  s.breaks = breaks;
  for (const cb::BreakEvent& b : breaks)
    if (b.spring > 0) s.broken.push_back(b.spring);
  std::sort(s.broken.begin(), s.broken.end());
  double shift = 0.0;
  std::size_t next = 0;
  for (int j = 1; j <= beads; ++j) {
    if (next < s.broken.size() && s.broken[next] == j) {
      shift += 1.5;
      ++next;
    }
    s.psi[j - 1] = shift;
  }
  return s;
}

// The snapshot's break labels against each other and against the drawn leaders; the first
// break's label present, bold, in the text colour, its pointer in the accent colour.
void check_snapshot_labels(const cb::RenderSnapshot& snap, const cb::ChainState& state,
                           cb::ThemeName theme) {
  const auto& shown = snap.breaks_shown;
  REQUIRE_FALSE(shown.empty());
  const cb::BreakEvent* first = &shown.front();
  for (const cb::BreakEvent& b : shown)
    if (b.tau < first->tau) first = &b;
  REQUIRE_FALSE(snap.break_labels.empty());
  CHECK(snap.break_labels.front().first);
  CHECK(snap.break_labels.front().spring == first->spring);
  int labelled = 0, more = 0;
  for (std::size_t i = 0; i < snap.break_labels.size(); ++i) {
    CHECK(snap.break_labels[i].first == (i == 0));
    labelled += snap.break_labels[i].spring >= 0;
    more += snap.break_labels[i].spring < 0;
    for (std::size_t k = i + 1; k < snap.break_labels.size(); ++k) {
      INFO("labels " << i << " and " << k);
      CHECK_FALSE(boxes_overlap(snap.break_labels[i].box, snap.break_labels[k].box, 0.0));
    }
  }
  CHECK(labelled + snap.breaks_unlabelled == static_cast<int>(shown.size()));
  CHECK(more <= 1);
  (void)state;
  // The drawn labels are the placed boxes: same left edge and width (text_layout's width).
  const cb::Theme& t = cb::theme(theme);
  const auto& marks = snap.layers[cb::kLayerMarks];
  int bold = 0;
  for (const cb::Label& l : marks.labels) {
    if (l.face != cb::FontFace::Bold) continue;
    ++bold;
    CHECK(l.text.find("broke first") != std::string::npos);
    CHECK(l.color.r == t.text.r / 255.0f);
    CHECK(l.color.g == t.text.g / 255.0f);
    CHECK(l.x == static_cast<float>(snap.break_labels.front().box.x));
    CHECK(cb::text_width(l.text, l.size, l.face) ==
          Approx(snap.break_labels.front().box.w).margin(1e-3));
  }
  CHECK(bold == 1);
  // Every vertical segment of the marks (the leaders) misses every label box but its own.
  for (const cb::Segment& s : marks.segments) {
    if (s.x0 != s.x1) continue;
    int hits = 0;
    for (const cb::BreakLabelBox& b : snap.break_labels)
      hits += leader_hits(s.x0, std::min(s.y0, s.y1), std::max(s.y0, s.y1), b.box, 0.0);
    CHECK(hits == 0);
  }
  // The accent pointer is the first break's, drawn last.
  const cb::Triangle& last = marks.triangles.back();
  CHECK(last.color.r == t.accent.r / 255.0f);
  CHECK(last.color.g == t.accent.g / 255.0f);
}

}  // namespace

TEST_CASE("Snapshots of a cascade: labels apart, the first break in bold over an accent pointer",
          "[snapshot][labels]") {
  // scenes/units_example.toml's cascade (spring 30 first at 51.60, then 16 springs near the
  // wall within 0.3) and a synthetic one of 400 breaks, at three frame sizes and both themes.
  std::vector<cb::BreakEvent> units{{30, 51.60, 0}, {19, 55.71, 0}, {20, 55.71, 0}, {14, 55.76, 0},
                                    {10, 55.76, 0}, {2, 55.77, 0},  {6, 55.79, 0},  {5, 55.79, 0},
                                    {7, 55.81, 0},  {8, 55.82, 0},  {12, 55.84, 0}, {16, 55.85, 0},
                                    {17, 55.86, 0}, {22, 55.93, 0}, {4, 58.88, 0}};
  std::vector<cb::BreakEvent> many;
  for (int k = 0; k < 400; ++k)
    many.push_back({1 + (k * 7919) % 2000, 10.0 + 0.001 * ((k * 31) % 400), 0});
  std::sort(many.begin(), many.end(), [](auto& a, auto& b) { return a.spring < b.spring; });
  many.erase(
      std::unique(many.begin(), many.end(), [](auto& a, auto& b) { return a.spring == b.spring; }),
      many.end());
  struct Case {
    int beads;
    const std::vector<cb::BreakEvent>* breaks;
  };
  for (const Case& c : {Case{30, &units}, Case{2000, &many}}) {
    for (const auto& [w, h] : {std::pair{480, 270}, std::pair{854, 480}, std::pair{1920, 1080}}) {
      for (const cb::ThemeName theme : {cb::ThemeName::Dark, cb::ThemeName::Light}) {
        for (const cb::View view : {cb::View::Longitudinal, cb::View::Transverse, cb::View::Both}) {
          INFO(c.beads << " beads, " << w << "x" << h << ", " << cb::theme_name(theme) << ", "
                       << cb::view_name(view));
          cb::ChainParams params;
          params.beads = c.beads;
          params.threshold = 1.0;
          const cb::ChainState state = cascade_state(c.beads, *c.breaks, 60.0);
          cb::SnapshotStyle style;
          style.width = w;
          style.height = h;
          style.theme = theme;
          style.view = view;
          style.threshold = 1.0;
          style.psi_range = state.psi.back() + 1.0;
          const cb::RenderSnapshot snap = cb::build_snapshot(state, params, 0.0, style);
          check_snapshot_labels(snap, state, theme);
        }
      }
    }
  }
}
