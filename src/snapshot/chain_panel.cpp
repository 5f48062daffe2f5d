// One chain panel of the frame: beads and springs, or the strain ribbon when the beads are
// too close to see; the halves of broken springs, break flashes and markers; the force.
//
// Design note: the ribbon is what makes N = 1e6 drawable. Instead of a million sub-pixel
// springs it keeps one value per pixel column (the spring with the largest |phi| there wins,
// so a spring about to break is never averaged away) and emits one Rect per run of equal
// colour: memory O(width), one pass over psi, whatever N is.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "snapshot/break_labels.h"
#include "snapshot/snapshot_internal.h"
#include "text/font.h"

namespace cb::snapshot_detail {

namespace {

constexpr double kPi = 3.14159265358979323846;

// Bead positions in pixels for one view; bead 0 is the wall's (ceiling's) anchor point.
// `origin`: bead 0 at rest along the chain (x; vertical: y); `centre`: the rest line's y
// (vertical: the chain's column, x).
struct Placer {
  const std::vector<double>& psi;
  double origin, spacing, psi_scale, centre;
  View view;

  double psi_at(int j) const { return j == 0 ? 0.0 : psi[j - 1]; }
  Point at(int j) const {
    const double p = psi_at(j);
    switch (view) {
      case View::Transverse:
        return {origin + j * spacing, centre - p * psi_scale};
      case View::Vertical:  // psi_j down from the ceiling (issue #22)
        return {centre, origin + (j + p) * spacing};
      default:
        return {origin + (j + p) * spacing, centre};
    }
  }
};

// Heald's ball (issue #22): one bead on the pull string, hanging, is drawn as lecturers show
// it, the ball on two strings: the upper "spring" is a straight string, not a coil.
bool ball_on_strings(const Frame& frame, const PanelLayout& p) {
  return p.view == View::Vertical && frame.params.beads == 1 && frame.params.pull_string;
}

// Whether a shape spanning a and b, padded by `pad`, touches the frame (false for NaN).
bool on_frame(const Point& a, const Point& b, double pad, int width, int height) {
  return std::min(a.x, b.x) <= width + pad && std::max(a.x, b.x) >= -pad &&
         std::min(a.y, b.y) <= height + pad && std::max(a.y, b.y) >= -pad;
}

float f(double v) {
  return static_cast<float>(v);
}

// The first break says so; later ones are named only (they are muted, and short labels fit
// more of a cascade).
std::string break_text(const BreakEvent& b, bool first) {
  char buffer[96];
  const char* what = first ? " broke first" : "";
  if (b.spring == 0) {
    std::snprintf(buffer, sizeof buffer, "pull string%s, τ = %.2f", what, b.tau);
  } else {
    std::snprintf(buffer, sizeof buffer, "spring %d%s, τ = %.2f", b.spring, what, b.tau);
  }
  return buffer;
}

// snprintf rather than string concatenation: GCC 12 warns falsely (-Wrestrict) on the latter.
std::string format_count(const char* fmt, int count) {
  char buffer[48];
  std::snprintf(buffer, sizeof buffer, fmt, count);
  return buffer;
}

// Bead j's radius: its area is area ratio x the median bead's (chain_sizes.cpp), at least a
// pixel; the median's radius itself for equal masses.
double bead_radius(const Frame& frame, const PanelLayout& p, int bead) {
  if (frame.bead_area.empty()) return p.bead_radius;
  return std::max(1.0, p.bead_radius * std::sqrt(frame.bead_area[bead - 1]));
}

// Spring j's width: width ratio x the median spring's; the median's for equal stiffness.
float spring_width(const Frame& frame, const PanelLayout& p, int spring) {
  if (frame.spring_width.empty()) return p.spring_width;
  return f(p.spring_width * frame.spring_width[spring - 1]);
}

// Calls fn(j, left, right) for every intact spring j = 1..N, left and right being the
// positions of beads j-1 and j. One pass, no allocation: state.broken is sorted.
template <class Fn>
void for_each_intact_spring(const Frame& frame, const Placer& at, Fn&& fn) {
  const std::vector<int>& broken = frame.state.broken;
  std::size_t next = 0;
  Point left = at.at(0);
  for (int j = 1; j <= frame.params.beads; ++j) {
    const Point right = at.at(j);
    while (next < broken.size() && broken[next] < j) ++next;
    if (next == broken.size() || broken[next] != j) fn(j, left, right);
    left = right;
  }
}

void draw_beads_and_springs(Frame& frame, const PanelLayout& p, const Placer& at) {
  const int W = frame.style.width, H = frame.style.height;
  Layer& chain = frame.layer(kLayerChain);
  Layer& beads = frame.layer(kLayerBeads);
  const std::size_t n = static_cast<std::size_t>(frame.params.beads);
  chain.springs.reserve(chain.springs.size() + n);
  beads.beads.reserve(beads.beads.size() + n);
  const bool strings = ball_on_strings(frame, p);
  const float string_width = f(std::max(2.0, 0.25 * frame.layout.text_size));
  for_each_intact_spring(frame, at, [&](int j, const Point& a, const Point& b) {
    const float width = strings ? string_width : spring_width(frame, p, j);
    if (!on_frame(a, b, width, W, H)) return;
    // Computed exactly as cb::extension() does, so tests can compare colours exactly.
    const double phi = at.psi_at(j) - at.psi_at(j - 1);
    // From bead surface to bead surface (the wall has no bead), so that no coil hides under
    // a bead; a spring squeezed below two radii keeps half of its length.
    const double dx = b.x - a.x, dy = b.y - a.y, d = std::hypot(dx, dy);
    const double ra = j == 1 ? 0.0 : bead_radius(frame, p, j - 1), rb = bead_radius(frame, p, j);
    const double ia = d > 0.0 ? std::min(ra, 0.25 * d) / d : 0.0;
    const double ib = d > 0.0 ? std::min(rb, 0.25 * d) / d : 0.0;
    chain.springs.push_back(SpringInstance{
        f(a.x + ia * dx), f(a.y + ia * dy), f(b.x - ib * dx), f(b.y - ib * dy), width,
        strings ? 0.0f : p.coils, strain_color(phi / frame.strain_scale_of(j), frame.style.theme)});
  });
  for (int j = 1; j <= frame.params.beads; ++j) {
    const Point c = at.at(j);
    const double r = bead_radius(frame, p, j);
    if (on_frame(c, c, r, W, H))
      beads.beads.push_back(BeadInstance{f(c.x), f(c.y), f(r), frame.pal.bead});
  }
}

// A broken spring recoils: two grey halves, one on each bead, shrinking from half the gap
// each (they meet at the break) to 30% of it over kRecoilTime, fast at first (ease-out).
void draw_broken_halves(Frame& frame, const PanelLayout& p, const Placer& at) {
  const int W = frame.style.width, H = frame.style.height;
  Layer& chain = frame.layer(kLayerChain);
  // The gap a spring breaks at, so a detached part flying away does not stretch its half.
  for (int j : frame.state.broken) {
    if (j < 1 || j > frame.params.beads) continue;
    const double c = std::abs(frame.params.threshold_of(j));
    const double cap = p.spacing + std::max(1.0, std::isfinite(c) ? c : 1.0) * p.psi_scale;
    const Point a = at.at(j - 1), b = at.at(j);
    const double dx = b.x - a.x, dy = b.y - a.y;
    const double gap = std::hypot(dx, dy);
    if (!(gap > 1e-9)) continue;
    const double t = std::min(1.0, frame.break_age(j) / kRecoilTime);
    const double fraction = 0.5 - 0.2 * (1.0 - (1.0 - t) * (1.0 - t));
    const double len = fraction * std::min(gap, cap);
    const double ux = dx / gap * len, uy = dy / gap * len;
    const Point a1{a.x + ux, a.y + uy}, b1{b.x - ux, b.y - uy};
    const bool strings = ball_on_strings(frame, p);
    const float coils = strings ? 0.0f : 0.5f * p.coils;  // half a spring has half the turns
    const float width =
        strings ? f(std::max(2.0, 0.25 * frame.layout.text_size)) : spring_width(frame, p, j);
    if (on_frame(a, a1, width, W, H)) {
      chain.springs.push_back(
          SpringInstance{f(a.x), f(a.y), f(a1.x), f(a1.y), width, coils, frame.pal.broken_half});
    }
    if (on_frame(b, b1, width, W, H)) {
      chain.springs.push_back(
          SpringInstance{f(b.x), f(b.y), f(b1.x), f(b1.y), width, coils, frame.pal.broken_half});
    }
  }
}

// The strain ribbon's pixel columns: per column the |phi| and signed phi of the most
// strained spring touching it and, in the transverse view, the curve's vertical extent.
struct Columns {
  std::vector<double> best_abs;  // < 0: no spring touches the column
  std::vector<double> best_phi;
  std::vector<double> y_lo, y_hi;

  // Spring from (xa, ya) to (xb, yb) with extension phi covers the columns under [xa, xb].
  void add(double xa, double xb, double ya, double yb, double phi, int width, bool transverse) {
    double lo = std::min(xa, xb), hi = std::max(xa, xb);
    if (!(lo >= 0.0 && hi < width)) {  // crosses the frame's edge, is off it, or NaN
      if (!(hi >= 0.0 && lo < width)) return;
      lo = std::max(lo, 0.0);
      hi = std::min(hi, width - 0.5);
    }
    const double a = std::abs(phi);  // NaN never wins a comparison below
    for (int c = static_cast<int>(lo), c1 = static_cast<int>(hi); c <= c1; ++c) {
      if (a > best_abs[c]) {
        best_abs[c] = a;
        best_phi[c] = phi;
      }
      if (transverse) {
        y_lo[c] = std::min(y_lo[c], std::min(ya, yb));
        y_hi[c] = std::max(y_hi[c], std::max(ya, yb));
      }
    }
  }
};

// One pass over psi for one view, written out (no Placer, no callback) because at N = 1e6 it
// is the whole cost of a frame; the view is a template parameter so the loop has no branch
// on it. Consecutive springs inside one pixel column (hundreds of them at N = 1e6) are
// reduced in registers and merged into the column once: updating the column in memory for
// each would chain every iteration to the previous one's store.
// kPerSpring: the value kept is phi_j / phi_c,j (frame.spring_scale) rather than phi_j.
template <bool kTransverse, bool kPerSpring>
void fold_springs(const Frame& frame, const PanelLayout& p, double origin, Columns& cols) {
  const double* scale = kPerSpring ? frame.spring_scale.data() : nullptr;
  const int n = frame.params.beads, width = frame.style.width;
  const double* psi = frame.state.psi.data();
  const double x_wall = origin, spacing = p.spacing;
  const double centre = p.centre_y, psi_scale = p.psi_scale;
  const std::vector<int>& broken = frame.state.broken;
  std::size_t next = 0;
  while (next < broken.size() && broken[next] < 1) ++next;
  int next_broken = next < broken.size() ? broken[next] : n + 1;
  // The open run: column [run_x0, run_x1) (empty when there is none), its largest |phi|
  // with its sign, and its vertical extent.
  double run_x0 = 1.0, run_x1 = 0.0;
  double run_abs = -1.0, run_phi = 0.0, run_lo = 0.0, run_hi = 0.0;
  const auto close_run = [&] {
    if (run_x0 < run_x1) {
      const double mid = run_x0 + 0.5;
      cols.add(mid, mid, run_lo, run_hi, run_phi, width, kTransverse);
    }
    run_x0 = 1.0;
    run_x1 = 0.0;
  };
  double prev_psi = 0.0, prev_x = x_wall, prev_y = centre;
  for (int j = 1; j <= n; ++j) {
    const double pj = psi[j - 1];
    const double x = kTransverse ? x_wall + j * spacing : x_wall + (j + pj) * spacing;
    const double y = kTransverse ? centre - pj * psi_scale : centre;
    if (j == next_broken) {
      ++next;
      next_broken = next < broken.size() ? broken[next] : n + 1;
    } else {
      const double phi = kPerSpring ? (pj - prev_psi) / scale[j - 1] : pj - prev_psi;
      const double lo = std::min(prev_x, x), hi = std::max(prev_x, x);
      const double y0 = std::min(prev_y, y), y1 = std::max(prev_y, y);
      if (lo >= run_x0 && hi < run_x1) {  // inside the open run's column
        const double a = std::abs(phi);
        if (a > run_abs) {
          run_abs = a;
          run_phi = phi;
        }
        if (kTransverse) {
          run_lo = std::min(run_lo, y0);
          run_hi = std::max(run_hi, y1);
        }
      } else {
        close_run();
        const int c = lo >= 0.0 && hi < width ? static_cast<int>(lo) : -1;
        if (c >= 0 && c == static_cast<int>(hi)) {  // opens a run in column c
          run_x0 = c;
          run_x1 = c + 1.0;
          run_abs = std::abs(phi);
          run_phi = phi;
          run_lo = y0;
          run_hi = y1;
        } else {  // spans columns, leaves the frame or is not finite
          cols.add(prev_x, x, prev_y, y, phi, width, kTransverse);
        }
      }
    }
    prev_psi = pj;
    prev_x = x;
    prev_y = y;
  }
  close_run();
}

// Folds every intact spring into the pixel columns it covers, keeping the most strained
// one per column; emits one Rect per run of columns with equal colour (and, in the
// transverse view, equal vertical extent).
void draw_ribbon(Frame& frame, const PanelLayout& p, double origin) {
  const int W = frame.style.width;
  const bool transverse = p.view == View::Transverse;
  const std::size_t w = static_cast<std::size_t>(W);
  const bool per_spring = !frame.spring_scale.empty();
  Columns cols;
  cols.best_abs.assign(w, -1.0);
  cols.best_phi.assign(w, 0.0);
  if (transverse) {
    cols.y_lo.assign(w, std::numeric_limits<double>::infinity());
    cols.y_hi.assign(w, -std::numeric_limits<double>::infinity());
    if (per_spring) {
      fold_springs<true, true>(frame, p, origin, cols);
    } else {
      fold_springs<true, false>(frame, p, origin, cols);
    }
  } else if (per_spring) {
    fold_springs<false, true>(frame, p, origin, cols);
  } else {
    fold_springs<false, false>(frame, p, origin, cols);
  }
  const double scale = per_spring ? 1.0 : frame.strain_scale;

  Layer& chain = frame.layer(kLayerChain);
  const double half = 0.5 * p.ribbon_width;
  bool open = false;
  Rect run;
  for (int c = 0; c <= W; ++c) {
    const bool filled = c < W && cols.best_abs[c] >= 0.0;
    Rect cell;
    if (filled) {
      cell.x = f(c);
      cell.w = 1.0f;
      cell.y = f(transverse ? cols.y_lo[c] - half : p.centre_y - half);
      cell.h = f(transverse ? cols.y_hi[c] - cols.y_lo[c] + 2.0 * half : 2.0 * half);
      cell.color = strain_color(cols.best_phi[c] / scale, frame.style.theme);
    }
    const bool extends = open && filled && cell.y == run.y && cell.h == run.h &&
                         cell.color.r == run.color.r && cell.color.g == run.color.g &&
                         cell.color.b == run.color.b;
    if (extends) {
      run.w += 1.0f;
      continue;
    }
    if (open) chain.rects.push_back(run);
    open = filled;
    run = cell;
  }
}

// Where a break is shown: just right of the wall-side bead in the longitudinal view (that
// part stays in frame while the detached part may fly off), the gap's middle in the
// transverse view, the string's middle for the pull string.
Point break_anchor(const Frame& frame, const PanelLayout& p, const Placer& at, int spring) {
  const bool vertical = p.view == View::Vertical;
  if (spring == 0) {
    const Point n = at.at(frame.params.beads);
    const double d = p.bead_radius + 0.5 * frame.layout.string_length;
    return vertical ? Point{n.x, n.y + d} : Point{n.x + d, n.y};
  }
  const Point a = at.at(spring - 1), b = at.at(spring);
  if (p.view == View::Transverse) return {0.5 * (a.x + b.x), 0.5 * (a.y + b.y)};
  if (vertical)
    return {a.x, a.y + 0.5 * std::clamp(b.y - a.y, 0.0, static_cast<double>(p.spacing))};
  return {a.x + 0.5 * std::clamp(b.x - a.x, 0.0, static_cast<double>(p.spacing)), a.y};
}

// The labels of the breaks (break_labels.h): the first break's in bold with an accent leader,
// then the later ones by time in the dim text colour where they fit, the rest counted.
// `below`: from a break's anchor down to its pointer's base, where the leader line starts.
template <class AnchorOf>
void place_break_labels(Frame& frame, const PanelLayout& p, int first, double below,
                        const AnchorOf& anchor_of) {
  const std::vector<BreakEvent>& breaks = frame.out.breaks_shown;
  Layer& marks = frame.layer(kLayerMarks);
  const SnapshotLayout& l = frame.layout;
  const double ts = l.text_size, px = l.font_px;
  const int W = frame.style.width;

  // Requests in priority order: the first break, then the others by time.
  std::vector<int> order;
  order.reserve(breaks.size());
  order.push_back(first);
  for (int k = 0; k < static_cast<int>(breaks.size()); ++k)
    if (k != first) order.push_back(k);
  std::stable_sort(order.begin() + 1, order.end(),
                   [&](int a, int b) { return breaks[a].tau < breaks[b].tau; });
  std::vector<LabelRequest> requests;
  std::vector<std::string> texts;
  requests.reserve(order.size());
  texts.reserve(order.size());
  for (std::size_t i = 0; i < order.size(); ++i) {
    const BreakEvent& b = breaks[order[i]];
    const bool is_first = i == 0;
    const Point a = anchor_of(b);
    texts.push_back(break_text(b, is_first));
    requests.push_back(LabelRequest{
        a.x, a.y + below,
        text_width(texts.back(), l.font_px, is_first ? FontFace::Bold : FontFace::Sans)});
  }

  // A label's box: from the top of the tallest glyph to the bottom of the deepest descender,
  // in either face; its `y` is the top of its capitals.
  double above = 0.0, under = 0.0;
  for (FontFace face : {FontFace::Sans, FontFace::Bold}) {
    const Font& font = Font::get(face);
    const double ascent = font.ascent(l.font_px), cap = font.cap_height(l.font_px);
    above = std::max(above, ascent - cap);
    under = std::max(under, cap + (px - ascent));
  }
  LabelArea area;
  area.first_row_y = p.markers_top;
  area.row_h = std::max(1.5 * ts, above + under + 0.15 * ts);  // boxes a little apart
  area.rows = std::max(1, static_cast<int>((p.bottom - p.markers_top) / area.row_h));
  area.box_above = above;
  area.box_h = above + under;
  area.leader_end = 0.5 * ts;
  area.x_min = l.margin;
  area.x_max = W - l.margin;
  area.offset = 0.5 * ts;
  area.gap = ts;  // two labels in a row read as two
  const auto more_text = [](int k) {
    return format_count(k == 1 ? "+%d more break" : "+%d more breaks", k);
  };
  const auto suffix_text = [](int k) { return format_count(" (+%d more)", k); };
  const LabelPlan plan = place_labels(
      requests, area,
      [&](int k) { return static_cast<double>(text_width(more_text(k), l.font_px)); },
      [&](int k) {
        return static_cast<double>(text_width(suffix_text(k), l.font_px, FontFace::Bold));
      });

  frame.out.breaks_unlabelled = plan.dropped;
  for (const PlacedLabel& placed : plan.labels) {
    if (placed.request < 0) {  // "+k more breaks"
      marks.labels.push_back(
          Label{more_text(plan.dropped), f(placed.x), f(placed.y), l.font_px, frame.pal.dim_text});
      frame.out.break_labels.push_back(BreakLabelBox{-1, false, placed.box});
      continue;
    }
    const bool is_first = placed.request == 0;
    const Color& line = is_first ? frame.pal.first_break : frame.pal.later_break;
    if (placed.has_leader) {
      // The leader, then a short elbow into the label's row when the label sits beside it.
      const float width = is_first ? f(std::max(2.0, 0.12 * ts)) : 1.0f;
      marks.segments.push_back(Segment{f(placed.leader_x), f(placed.leader_y0), f(placed.leader_x),
                                       f(placed.leader_y1), width, line});
      const double to = placed.box.x >= placed.leader_x ? placed.box.x - 0.15 * ts
                                                        : placed.box.right() + 0.15 * ts;
      if (std::abs(to - placed.leader_x) <= area.offset) {
        marks.segments.push_back(Segment{f(placed.leader_x), f(placed.leader_y1), f(to),
                                         f(placed.leader_y1), width, line});
      }
    }
    std::string text = texts[placed.request];
    if (is_first && plan.more_in_first) text += suffix_text(plan.dropped);
    marks.labels.push_back(Label{text, f(placed.x), f(placed.y), l.font_px,
                                 is_first ? frame.pal.text : frame.pal.dim_text,
                                 is_first ? FontFace::Bold : FontFace::Sans});
    frame.out.break_labels.push_back(
        BreakLabelBox{breaks[order[placed.request]].spring, is_first, placed.box});
  }
}

// The vertical view's labels (issue #22): a column right of the hanging chain, each label as
// near its break's height as it can be without its box meeting another's; leaders run from
// the pointers (right of the chain, at x `from_x`) across the gap to the labels. Same rules
// as place_break_labels otherwise: the first break's label always, in bold over an accent
// leader; later ones by time where they fit; the rest counted in "+k more" (or, when that
// finds no room, in the first label's text).
template <class AnchorOf>
void place_break_labels_beside(Frame& frame, const PanelLayout& p, int first, double from_x,
                               const AnchorOf& anchor_of) {
  const std::vector<BreakEvent>& breaks = frame.out.breaks_shown;
  Layer& marks = frame.layer(kLayerMarks);
  const SnapshotLayout& l = frame.layout;
  const double ts = l.text_size, px = l.font_px;
  std::vector<int> order{first};
  for (int k = 0; k < static_cast<int>(breaks.size()); ++k)
    if (k != first) order.push_back(k);
  std::stable_sort(order.begin() + 1, order.end(),
                   [&](int a, int b) { return breaks[a].tau < breaks[b].tau; });
  // A label's box: ascent to descent of either face, `above` over the top of its capitals.
  double above = 0.0, under = 0.0;
  for (FontFace face : {FontFace::Sans, FontFace::Bold}) {
    const Font& font = Font::get(face);
    const double ascent = font.ascent(l.font_px), cap = font.cap_height(l.font_px);
    above = std::max(above, ascent - cap);
    under = std::max(under, cap + (px - ascent));
  }
  const double box_h = above + under, sep = 0.15 * ts;
  const double x = p.labels_x, y_min = p.top, y_max = p.bottom;  // boxes stay in the panel
  std::vector<LabelBox> placed;
  // The free box top nearest `want` (the top of a box centred on the anchor), or NaN.
  const auto slot = [&](double want, double w) {
    std::vector<double> tries{want};
    for (const LabelBox& b : placed) {
      tries.push_back(b.bottom() + sep);
      tries.push_back(b.y - sep - box_h);
    }
    double best = std::numeric_limits<double>::quiet_NaN();
    for (double y : tries) {
      y = std::clamp(y, y_min, std::max(y_min, y_max - box_h));
      const LabelBox box{x, y, w, box_h};
      bool free = true;
      for (const LabelBox& b : placed) free = free && !box.intersects(b);
      if (free && !(std::abs(y - want) >= std::abs(best - want))) best = y;
    }
    return best;
  };
  struct Placed {
    int k;
    double y;
  };
  std::vector<Placed> labels;
  int dropped = 0;
  for (std::size_t i = 0; i < order.size(); ++i) {
    const BreakEvent& b = breaks[order[i]];
    const double w =
        text_width(break_text(b, i == 0), l.font_px, i == 0 ? FontFace::Bold : FontFace::Sans);
    const double want = anchor_of(b).y - 0.5 * ts - above;
    double y = slot(want, w);
    if (i == 0 && std::isnan(y)) y = std::clamp(want, y_min, std::max(y_min, y_max - box_h));
    if (std::isnan(y)) {
      ++dropped;
      continue;
    }
    placed.push_back(LabelBox{x, y, w, box_h});
    labels.push_back({order[i], y + above});
  }
  const auto more_text = [](int k) {
    return format_count(k == 1 ? "+%d more break" : "+%d more breaks", k);
  };
  bool more_in_first = false;
  if (dropped > 0) {
    const double y = slot(y_max - box_h, text_width(more_text(dropped), l.font_px));
    if (std::isnan(y)) {
      more_in_first = true;
    } else {
      marks.labels.push_back(
          Label{more_text(dropped), f(x), f(y + above), l.font_px, frame.pal.dim_text});
      frame.out.break_labels.push_back(BreakLabelBox{
          -1, false, LabelBox{x, y, text_width(more_text(dropped), l.font_px), box_h}});
    }
  }
  frame.out.breaks_unlabelled = dropped;
  for (std::size_t i = 0; i < labels.size(); ++i) {
    const bool is_first = i == 0;
    const BreakEvent& b = breaks[labels[i].k];
    std::string text = break_text(b, is_first);
    if (is_first && more_in_first) text += format_count(" (+%d more)", dropped);
    const FontFace face = is_first ? FontFace::Bold : FontFace::Sans;
    const Point a = anchor_of(b);
    const double mid = labels[i].y + 0.5 * ts;  // the middle of the capitals
    marks.segments.push_back(Segment{f(from_x), f(a.y), f(x - 0.3 * ts), f(mid),
                                     is_first ? f(std::max(2.0, 0.12 * ts)) : 1.0f,
                                     is_first ? frame.pal.first_break : frame.pal.later_break});
    marks.labels.push_back(Label{text, f(x), f(labels[i].y), l.font_px,
                                 is_first ? frame.pal.text : frame.pal.dim_text, face});
    frame.out.break_labels.push_back(
        BreakLabelBox{b.spring, is_first,
                      LabelBox{x, labels[i].y - above, text_width(text, l.font_px, face), box_h}});
  }
}

void draw_breaks(Frame& frame, const PanelLayout& p, const Placer& at) {
  const std::vector<BreakEvent>& breaks = frame.out.breaks_shown;
  if (breaks.empty()) return;
  Layer& marks = frame.layer(kLayerMarks);
  const SnapshotLayout& l = frame.layout;
  const double ts = l.text_size;
  const int W = frame.style.width;

  // The flash: a bright unshaded glow (a triangle fan: discs are lit as spheres and would
  // read as a ghostly bead) at the gap and eight short rays bursting outwards, all fading
  // over kFlashTime.
  const double flash_r = std::max(1.6 * p.bead_radius, 1.2 * ts);
  const float ray_width = f(std::max(1.5, 0.2 * ts));
  for (const BreakEvent& b : breaks) {
    const double age = frame.state.tau - b.tau;
    if (age < 0.0 || age >= kFlashTime) continue;
    Point c;
    if (b.spring == 0) {
      c = break_anchor(frame, p, at, 0);
    } else {
      const Point a = at.at(b.spring - 1), e = at.at(b.spring);
      c = {0.5 * (a.x + e.x), 0.5 * (a.y + e.y)};
    }
    const double t = age / kFlashTime, fade = 1.0 - t;
    Color glow = frame.pal.flash, ray = frame.pal.flash;
    glow.a = f(0.55 * fade * fade);
    ray.a = f(fade);
    const double glow_r = flash_r * (1.0 + 0.5 * t);
    constexpr int kFan = 20;
    for (int k = 0; k < kFan; ++k) {
      const double a0 = 2.0 * kPi * k / kFan, a1 = 2.0 * kPi * (k + 1) / kFan;
      Triangle tri;
      tri.x[0] = f(c.x);
      tri.y[0] = f(c.y);
      tri.x[1] = f(c.x + glow_r * std::cos(a0));
      tri.y[1] = f(c.y + glow_r * std::sin(a0));
      tri.x[2] = f(c.x + glow_r * std::cos(a1));
      tri.y[2] = f(c.y + glow_r * std::sin(a1));
      tri.color = glow;
      marks.triangles.push_back(tri);
    }
    const double inner = flash_r * (0.9 + 0.8 * t), outer = flash_r * (1.4 + 1.4 * t);
    for (int k = 0; k < 8; ++k) {
      const double angle = (k + 0.5) * kPi / 4.0;
      const double cx = std::cos(angle), cy = std::sin(angle);
      marks.segments.push_back(Segment{f(c.x + inner * cx), f(c.y + inner * cy),
                                       f(c.x + outer * cx), f(c.y + outer * cy), ray_width, ray});
    }
  }

  // Markers that stay: a pointer under every break, the first break's in the accent colour
  // and drawn last (on top), the later ones muted. Labels go in rows below the chain where
  // they overlap nothing (break_labels.h), unless the other panel labels them already.
  int first = 0;  // the earliest break; of equal times, the one recorded first
  for (int k = 1; k < static_cast<int>(breaks.size()); ++k)
    if (breaks[k].tau < breaks[first].tau) first = k;
  const double clear = std::max(static_cast<double>(p.largest_bead_radius),
                                frame.out.ribbon ? 0.5 * p.ribbon_width : 0.0) +
                       2.0;
  const double tri_h = 0.6 * ts, tri_w = 0.35 * ts;
  const bool vertical = p.view == View::Vertical;
  const auto anchor_of = [&](const BreakEvent& b) {
    Point a = break_anchor(frame, p, at, b.spring);
    if (!vertical)
      a.x = std::clamp(a.x, static_cast<double>(l.x_wall), W - static_cast<double>(l.margin));
    a.y = std::clamp(a.y, static_cast<double>(p.top), static_cast<double>(p.bottom));
    return a;
  };
  const auto pointer = [&](const BreakEvent& b, const Color& colour) {
    const Point a = anchor_of(b);
    if (vertical) {  // right of the chain, pointing left at the break
      const double tip = a.x + clear, base = tip + tri_h;
      marks.triangles.push_back(
          Triangle{{f(tip), f(base), f(base)}, {f(a.y), f(a.y - tri_w), f(a.y + tri_w)}, colour});
      return;
    }
    const double tip = a.y + clear, base = tip + tri_h;
    marks.triangles.push_back(
        Triangle{{f(a.x), f(a.x - tri_w), f(a.x + tri_w)}, {f(tip), f(base), f(base)}, colour});
  };
  for (int k = 0; k < static_cast<int>(breaks.size()); ++k)
    if (k != first) pointer(breaks[k], frame.pal.later_break);
  pointer(breaks[first], frame.pal.first_break);
  if (l.panel_count == 2 && p.view == View::Transverse) return;
  if (vertical) {
    place_break_labels_beside(frame, p, first, p.chain_x + clear + tri_h, anchor_of);
  } else {
    place_break_labels(frame, p, first, clear + tri_h, anchor_of);
  }
}

// The pull: an arrow at bead N whose length is f / force_range of the longest arrow, after
// the pull string when there is one. Gone once the string broke (nothing pulls any more).
// It points the way the force acts on psi_N: along the chain in the longitudinal view,
// across it (up for f > 0, as psi is drawn) in the transverse view.
void draw_force(Frame& frame, const PanelLayout& p, const Placer& at) {
  if (!frame.string_intact) {
    frame.out.arrow_length = 0.0;
    return;
  }
  Layer& layer = frame.layer(kLayerForce);
  const SnapshotLayout& l = frame.layout;
  const double ts = l.text_size;
  const bool across = p.view == View::Transverse, vertical = p.view == View::Vertical;
  // +psi on screen: right, up (transverse) or down (vertical: the pull hangs from bead N).
  const double ux = across || vertical ? 0.0 : 1.0, uy = across ? -1.0 : vertical ? 1.0 : 0.0;
  const Point n = at.at(frame.params.beads);
  const auto along = [&](double d) { return Point{n.x + ux * d, n.y + uy * d}; };
  double start = p.bead_radius;
  if (frame.params.pull_string) {
    const Point a = along(start), b = along(start + l.string_length);
    layer.segments.push_back(
        Segment{f(a.x), f(a.y), f(b.x), f(b.y), f(std::max(1.0, ts / 10.0)), frame.pal.force});
    start += l.string_length;
  } else {
    start += 0.25 * ts;
  }
  const double ratio = std::clamp(frame.force / frame.style.force_range, -1.0, 1.0);
  // Across the chain the arrow keeps inside its panel: at most the panel's half height.
  const double longest = across ? std::min<double>(l.arrow_max, 0.9 * p.half_height) : l.arrow_max;
  const double length = longest * (std::isnan(ratio) ? 0.0 : ratio);
  frame.out.arrow_length = length;
  const double head = std::min(std::abs(length), std::clamp(1.2 * ts, 8.0, 28.0));
  const double hw = 0.45 * std::clamp(1.2 * ts, 8.0, 28.0);
  if (std::abs(length) >= 0.5) {
    // Tail to tip spans [start, start + |length|] from the bead either way; the head is at
    // the tip. Distances are along u; the head's corners are hw to either side of it.
    const double dir = length > 0 ? 1.0 : -1.0;
    const double tail = length > 0 ? start : start + std::abs(length);
    const double tip = tail + length;
    const double neck = tip - dir * head;
    const Point t0 = along(tail), t1 = along(neck), t2 = along(tip);
    if (std::abs(neck - tail) > 0.0) {
      layer.segments.push_back(Segment{f(t0.x), f(t0.y), f(t1.x), f(t1.y),
                                       f(std::clamp(0.25 * ts, 2.0, 6.0)), frame.pal.force});
    }
    const double vx = -uy * hw, vy = ux * hw;
    layer.triangles.push_back(Triangle{{f(t2.x), f(t1.x + vx), f(t1.x - vx)},
                                       {f(t2.y), f(t1.y + vy), f(t1.y - vy)},
                                       frame.pal.force});
  }
  char text[48];
  std::snprintf(text, sizeof text, "f = %.2f", frame.force);
  std::string label = text;
  if (const auto m = label.find('-'); m != std::string::npos) label.replace(m, 1, "\u2212");
  const double clear = std::max(static_cast<double>(p.bead_radius), hw);
  const Point where =
      across     ? Point{n.x + clear + 0.5 * ts, n.y - 0.5 * ts}
      : vertical ? Point{n.x + clear + 0.5 * ts, n.y + start + 0.5 * std::abs(length) - 0.5 * ts}
                 : Point{n.x + start, n.y - clear - 1.6 * ts};
  layer.labels.push_back(Label{label, f(where.x), f(where.y), l.font_px, frame.pal.text});
}

}  // namespace

void draw_chain_panel(Frame& frame, const PanelLayout& p) {
  // Where bead 0 at rest would be: the wall's face, or left of it by the beads a zoom skips
  // (longitudinal: and by the first drawn bead's displacement, so the stretch stays in view).
  const SnapshotLayout& l = frame.layout;
  const bool transverse = p.view == View::Transverse, vertical = p.view == View::Vertical;
  const int first = l.first_bead;
  const double shift = first > 0 && !transverse ? frame.state.psi[first - 1] : 0.0;
  const double origin = (vertical ? p.ceiling_y : l.x_wall) - (first + shift) * p.spacing;
  const Placer at{
      frame.state.psi, origin, p.spacing, p.psi_scale, vertical ? p.chain_x : p.centre_y, p.view};
  if (frame.out.ribbon) {
    draw_ribbon(frame, p, origin);
  } else {
    draw_beads_and_springs(frame, p, at);
    draw_broken_halves(frame, p, at);
  }
  draw_breaks(frame, p, at);
  if (l.last_bead == frame.params.beads) draw_force(frame, p, at);
}

}  // namespace cb::snapshot_detail
