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

#include "snapshot/snapshot_internal.h"

namespace cb::snapshot_detail {

namespace {

constexpr double kPi = 3.14159265358979323846;

// Bead positions in pixels for one view; bead 0 is the wall's anchor point.
struct Placer {
  const std::vector<double>& psi;
  double x_wall, spacing, psi_scale, centre;
  bool transverse;

  double psi_at(int j) const { return j == 0 ? 0.0 : psi[j - 1]; }
  Point at(int j) const {
    const double p = psi_at(j);
    return transverse ? Point{x_wall + j * spacing, centre - p * psi_scale}
                      : Point{x_wall + (j + p) * spacing, centre};
  }
};

// Whether a shape spanning a and b, padded by `pad`, touches the frame (false for NaN).
bool on_frame(const Point& a, const Point& b, double pad, int width, int height) {
  return std::min(a.x, b.x) <= width + pad && std::max(a.x, b.x) >= -pad &&
         std::min(a.y, b.y) <= height + pad && std::max(a.y, b.y) >= -pad;
}

float f(double v) {
  return static_cast<float>(v);
}

std::string break_text(const BreakEvent& b) {
  char buffer[96];
  if (b.spring == 0) {
    std::snprintf(buffer, sizeof buffer, "pull string broke, τ = %.2f", b.tau);
  } else {
    std::snprintf(buffer, sizeof buffer, "spring %d broke, τ = %.2f", b.spring, b.tau);
  }
  return buffer;
}

// snprintf rather than string concatenation: GCC 12 warns falsely (-Wrestrict) on the latter.
std::string format_count(const char* fmt, int count) {
  char buffer[48];
  std::snprintf(buffer, sizeof buffer, fmt, count);
  return buffer;
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
  const double r = p.bead_radius;
  for_each_intact_spring(frame, at, [&](int j, const Point& a, const Point& b) {
    if (!on_frame(a, b, p.spring_width, W, H)) return;
    // Computed exactly as cb::extension() does, so tests can compare colours exactly.
    const double phi = at.psi_at(j) - at.psi_at(j - 1);
    // From bead surface to bead surface (the wall has no bead), so that no coil hides under
    // a bead; a spring squeezed below two radii keeps half of its length.
    const double dx = b.x - a.x, dy = b.y - a.y, d = std::hypot(dx, dy);
    const double inset = d > 0.0 ? std::min(r, 0.25 * d) / d : 0.0;
    const double ia = j == 1 ? 0.0 : inset;
    chain.springs.push_back(SpringInstance{f(a.x + ia * dx), f(a.y + ia * dy), f(b.x - inset * dx),
                                           f(b.y - inset * dy), p.spring_width, p.coils,
                                           strain_color(phi / frame.strain_scale, frame.style.theme)});
  });
  for (int j = 1; j <= frame.params.beads; ++j) {
    const Point c = at.at(j);
    if (on_frame(c, c, r, W, H)) beads.beads.push_back(BeadInstance{f(c.x), f(c.y), f(r), frame.pal.bead});
  }
}

// A broken spring recoils: two grey halves, one on each bead, shrinking from half the gap
// each (they meet at the break) to 30% of it over kRecoilTime, fast at first (ease-out).
void draw_broken_halves(Frame& frame, const PanelLayout& p, const Placer& at) {
  const int W = frame.style.width, H = frame.style.height;
  Layer& chain = frame.layer(kLayerChain);
  // The gap a spring breaks at, so a detached part flying away does not stretch its half.
  const double phi_c = frame.params.breakable() ? std::abs(frame.params.threshold) : 1.0;
  const double cap = p.spacing + std::max(1.0, phi_c) * p.psi_scale;
  for (int j : frame.state.broken) {
    if (j < 1 || j > frame.params.beads) continue;
    const Point a = at.at(j - 1), b = at.at(j);
    const double dx = b.x - a.x, dy = b.y - a.y;
    const double gap = std::hypot(dx, dy);
    if (!(gap > 1e-9)) continue;
    const double t = std::min(1.0, frame.break_age(j) / kRecoilTime);
    const double fraction = 0.5 - 0.2 * (1.0 - (1.0 - t) * (1.0 - t));
    const double len = fraction * std::min(gap, cap);
    const double ux = dx / gap * len, uy = dy / gap * len;
    const Point a1{a.x + ux, a.y + uy}, b1{b.x - ux, b.y - uy};
    const float coils = 0.5f * p.coils;  // half a spring has half the turns
    if (on_frame(a, a1, p.spring_width, W, H)) {
      chain.springs.push_back(
          SpringInstance{f(a.x), f(a.y), f(a1.x), f(a1.y), p.spring_width, coils, frame.pal.broken_half});
    }
    if (on_frame(b, b1, p.spring_width, W, H)) {
      chain.springs.push_back(
          SpringInstance{f(b.x), f(b.y), f(b1.x), f(b1.y), p.spring_width, coils, frame.pal.broken_half});
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
template <bool kTransverse>
void fold_springs(const Frame& frame, const PanelLayout& p, double origin, Columns& cols) {
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
      const double phi = pj - prev_psi;
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
  Columns cols;
  cols.best_abs.assign(w, -1.0);
  cols.best_phi.assign(w, 0.0);
  if (transverse) {
    cols.y_lo.assign(w, std::numeric_limits<double>::infinity());
    cols.y_hi.assign(w, -std::numeric_limits<double>::infinity());
    fold_springs<true>(frame, p, origin, cols);
  } else {
    fold_springs<false>(frame, p, origin, cols);
  }

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
      cell.color = strain_color(cols.best_phi[c] / frame.strain_scale, frame.style.theme);
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
  if (spring == 0) {
    const Point n = at.at(frame.params.beads);
    return {n.x + p.bead_radius + 0.5 * frame.layout.string_length, n.y};
  }
  const Point a = at.at(spring - 1), b = at.at(spring);
  if (p.view == View::Transverse) return {0.5 * (a.x + b.x), 0.5 * (a.y + b.y)};
  return {a.x + 0.5 * std::clamp(b.x - a.x, 0.0, static_cast<double>(p.spacing)), a.y};
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

  // Markers that stay: a pointer under every break, and a label for the first ones in time
  // (the rest are counted) unless the other panel labels them already (two panels). Rows
  // run from the break nearest the pull end (top) to the one nearest the wall (bottom):
  // labels extend right of their pointer and every pointer further left has a lower row, so
  // no leader line crosses a label. Anchors keep the springs' order as the chain moves, so
  // rows never reshuffle between frames.
  const double clear =
      std::max(static_cast<double>(p.bead_radius), frame.out.ribbon ? 0.5 * p.ribbon_width : 0.0) +
      2.0;
  const double tri_h = 0.6 * ts, tri_w = 0.35 * ts;
  const auto anchor_of = [&](const BreakEvent& b) {
    Point a = break_anchor(frame, p, at, b.spring);
    a.x = std::clamp(a.x, static_cast<double>(l.x_wall), W - static_cast<double>(l.margin));
    a.y = std::clamp(a.y, static_cast<double>(p.top), static_cast<double>(p.bottom));
    return a;
  };
  for (const BreakEvent& b : breaks) {
    const Point a = anchor_of(b);
    const double tip = a.y + clear, base = tip + tri_h;
    marks.triangles.push_back(
        Triangle{{f(a.x), f(a.x - tri_w), f(a.x + tri_w)}, {f(tip), f(base), f(base)}, frame.pal.marker});
  }
  if (l.panel_count == 2 && p.view == View::Transverse) return;

  const double row_h = 1.5 * ts;
  const int rows = std::max(1, static_cast<int>((p.bottom - p.markers_top) / row_h));
  const int count = static_cast<int>(breaks.size());
  const int shown = count <= rows ? count : std::max(1, rows - 1);
  std::vector<const BreakEvent*> order;
  for (int k = 0; k < shown; ++k) order.push_back(&breaks[k]);
  const auto from_wall = [&](const BreakEvent* b) {  // the pull string sits beyond bead N
    return b->spring == 0 ? frame.params.beads + 1 : b->spring;
  };
  std::stable_sort(order.begin(), order.end(), [&](const BreakEvent* a, const BreakEvent* b) {
    return from_wall(a) > from_wall(b);
  });
  for (int k = 0; k < shown; ++k) {
    const BreakEvent& b = *order[k];
    const Point a = anchor_of(b);
    const double base = a.y + clear + tri_h;
    const double row_y = p.markers_top + k * row_h;
    if (row_y + 0.5 * ts > base) {  // a leader line down to the label's row
      marks.segments.push_back(
          Segment{f(a.x), f(base), f(a.x), f(row_y + 0.5 * ts), 1.0f, frame.pal.marker});
    }
    std::string text = break_text(b);
    if (k == shown - 1 && shown == rows && count > shown) {
      text += format_count(" (+%d more)", count - shown);
    }
    const double w = text_width(text, l.font_px);
    double x = a.x + 0.5 * ts;
    if (x + w > W - l.margin) x = a.x - 0.5 * ts - w;  // near the right edge: to the left
    marks.labels.push_back(
        Label{text, f(std::max(static_cast<double>(l.margin), x)), f(row_y), l.font_px, frame.pal.text});
  }
  if (count > shown && shown < rows) {
    const std::string more = format_count("+%d more breaks", count - shown);
    marks.labels.push_back(
        Label{more, f(l.x_wall + 0.5 * ts), f(p.markers_top + shown * row_h), l.font_px, frame.pal.dim_text});
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
  const bool across = p.view == View::Transverse;
  const double ux = across ? 0.0 : 1.0, uy = across ? -1.0 : 0.0;  // +psi on screen
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
  const Point where = across ? Point{n.x + clear + 0.5 * ts, n.y - 0.5 * ts}
                             : Point{n.x + start, n.y - clear - 1.6 * ts};
  layer.labels.push_back(Label{label, f(where.x), f(where.y), l.font_px, frame.pal.text});
}

}  // namespace

void draw_chain_panel(Frame& frame, const PanelLayout& p) {
  // Where bead 0 at rest would be: the wall's face, or left of it by the beads a zoom skips
  // (longitudinal: and by the first drawn bead's displacement, so the stretch stays in view).
  const SnapshotLayout& l = frame.layout;
  const bool transverse = p.view == View::Transverse;
  const int first = l.first_bead;
  const double shift = first > 0 && !transverse ? frame.state.psi[first - 1] : 0.0;
  const double origin = l.x_wall - (first + shift) * p.spacing;
  const Placer at{frame.state.psi, origin, p.spacing, p.psi_scale, p.centre_y, transverse};
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
