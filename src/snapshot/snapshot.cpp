// build_snapshot: the layout of a frame and its fixed furniture (wall, legend, time label);
// the chain itself is drawn by chain_panel.cpp.
//
// Design note: every position comes from snapshot_layout(style, params), which depends on
// nothing that changes during a run, so a video's frames share one layout and nothing jumps.
// Sizes scale with the frame: the text is frame_text_px (2% of the height, at least 14 px) as
// in the overlay, margins and the wall follow the frame's size, and the chain takes the rest.
#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <limits>

#include "snapshot/snapshot_internal.h"
#include "snapshot/strain_scale.h"
#include "text/font.h"

namespace cb {

using namespace snapshot_detail;

bool parse_view(const std::string& text, View& out) {
  if (text == "longitudinal") {
    out = View::Longitudinal;
  } else if (text == "transverse") {
    out = View::Transverse;
  } else if (text == "both") {
    out = View::Both;
  } else if (text == "vertical") {
    out = View::Vertical;
  } else {
    return false;
  }
  return true;
}

const char* view_name(View view) {
  switch (view) {
    case View::Longitudinal:
      return "longitudinal";
    case View::Transverse:
      return "transverse";
    case View::Both:
      return "both";
    case View::Vertical:
      return "vertical";
  }
  return "?";
}

namespace {

constexpr double kMaxBeadRadius = 18.0;
constexpr double kRibbonSpacing = 3.0;  // below this many pixels per bead: the strain ribbon

// `two_panels`: the first text row holds the panel's caption, so the chain keeps off it.
// `sizes`: the largest bead area and spring width ratio (1 for equal masses / stiffness).
PanelLayout panel_layout(View view, double top, double bottom, bool two_panels,
                         const SnapshotLayout& l, const SnapshotStyle& style, int beads,
                         const SizeRange& sizes) {
  // A zoomed panel spans its stretch of springs; a longitudinal one moves with the stretch's
  // first bead, so it needs room for the stretch's own extension only.
  const double full_range = style.psi_range;
  double psi_range = full_range;
  if (l.zoomed()) {
    beads = l.last_bead - l.first_bead;
    psi_range = std::min(full_range, beads * std::max(style.threshold, style.strain_range));
  }
  PanelLayout p;
  p.view = view;
  p.top = static_cast<float>(top);
  p.bottom = static_cast<float>(bottom);
  const double ts = l.text_size;
  if (two_panels) top = std::min(bottom - 1.0, top + 1.6 * ts);
  const double h = bottom - top;
  // Vertical: a ceiling as thick as the wall is wide, then the chain down to the room the
  // string, the longest arrow and bead N's radius need.
  const bool vertical = view == View::Vertical;
  const double ceiling_y = top + (l.x_wall - l.margin);
  const double usable = vertical ? std::max(1.0, bottom - ceiling_y - l.arrow_max -
                                                     l.string_length - 0.5 * ts - kMaxBeadRadius)
                                 : l.x_right - l.x_wall;
  // Longitudinal (vertical): bead N lands on x_right (the bottom of the room) when psi_N =
  // psi_range, the largest extension.
  const double spacing = view == View::Transverse ? usable / beads : usable / (beads + psi_range);
  // A chain that stretches a lot would get tiny beads at rest; size them for the geometric
  // mean of the rest and the fully stretched spacing (still below half the rest spacing).
  const double typical = std::min(std::sqrt(spacing * usable / beads), 1.6 * spacing);
  const double r0 = std::clamp(0.3 * typical, 1.5, kMaxBeadRadius);
  // Unequal masses: the median bead shrinks until the heaviest one (area ratio max_area) fits
  // where an equal bead could be, or into 45% of the spacing if that is more (and never
  // beyond kMaxBeadRadius, which the layout keeps free right of bead N).
  double r = r0;
  if (sizes.max_area > 1.0) {
    const double room = std::max(r0, std::min(0.45 * spacing, kMaxBeadRadius));
    r = std::min(r0, room / std::sqrt(sizes.max_area));
  }
  const double r_max = sizes.max_area > 1.0 ? r * std::sqrt(sizes.max_area) : r;
  // Unequal stiffness likewise: the widest spring at most 2.2 median radii across (a little
  // more than a bead's diameter; wider, a short stiff coil reads as a block).
  double spring_width = 1.4 * r;
  if (sizes.max_width > 1.0) spring_width = std::min(spring_width, 2.2 * r / sizes.max_width);
  // A coil needs room between the beads to read as one; short springs are bars.
  const double free_length = spacing - 2.0 * r;
  p.spacing = static_cast<float>(spacing);
  p.bead_radius = static_cast<float>(r);
  p.largest_bead_radius = static_cast<float>(r_max);
  p.spring_width = static_cast<float>(spring_width);
  p.coils = free_length >= 20.0
                ? static_cast<float>(std::clamp(std::round(free_length / 6.0), 4.0, 8.0))
                : 0.0f;
  if (vertical) {
    // The chain hangs in a column a third of the way across; its break labels stand in a
    // column right of it (the pointers between), the force's value right of the arrow.
    p.chain_x = static_cast<float>(std::round(0.3 * style.width));
    p.ceiling_y = static_cast<float>(ceiling_y);
    p.centre_y = p.ceiling_y;
    p.psi_scale = p.spacing;
    p.ribbon_width = static_cast<float>(std::clamp(0.1 * h, 4.0, 30.0));
    p.wall_half_height = static_cast<float>(std::max(4.0 * r_max, 3.0 * ts));  // the ceiling's
    p.half_height = static_cast<float>(0.5 * h);
    p.markers_top = p.ceiling_y;
    const double clear = std::max(r_max, 0.5 * p.ribbon_width) + 2.0;
    p.labels_x = static_cast<float>(p.chain_x + clear + 0.6 * ts + 1.5 * ts);
  } else if (view == View::Longitudinal) {
    // The chain sits a little above the middle: break markers stack below it.
    const double centre = top + 0.42 * h;
    p.centre_y = static_cast<float>(centre);
    p.psi_scale = p.spacing;
    p.ribbon_width = static_cast<float>(std::clamp(0.1 * h, 4.0, 30.0));
    p.wall_half_height = static_cast<float>(std::min(0.35 * h, std::max(4.0 * r, 0.15 * h)));
    p.half_height = static_cast<float>(0.5 * h);
    const double clear = std::max(r_max, 0.5 * p.ribbon_width) + 2.0;
    p.markers_top = static_cast<float>(centre + clear + 0.6 * ts + 0.4 * ts);
  } else {
    // A band at the bottom holds the break markers' labels (with two panels the
    // longitudinal one shows them); psi is drawn across the rest.
    const double band = two_panels ? 0.5 * ts : std::min(8.0 * ts, 0.3 * h);
    const double plot_bottom = bottom - band;
    const double centre = 0.5 * (top + plot_bottom);
    const double half = std::max(1.0, 0.5 * (plot_bottom - top) - r_max - 2.0);
    p.centre_y = static_cast<float>(centre);
    p.half_height = static_cast<float>(half);
    p.psi_scale = static_cast<float>(half / style.psi_range);
    p.ribbon_width = static_cast<float>(std::clamp(0.02 * h, 2.0, 8.0));
    p.wall_half_height = static_cast<float>(half + r_max);
    p.markers_top = static_cast<float>(plot_bottom + 0.4 * ts);
  }
  return p;
}

// A hatched block (the wall, the ceiling): a filled rectangle crossed at 45 degrees by the
// lines x + y = k, clipped to it.
void add_hatched_block(Layer& layer, double x0, double y0, double x1, double y1,
                       const SnapshotLayout& l, const Palette& pal) {
  layer.rects.push_back(Rect{static_cast<float>(x0), static_cast<float>(y0),
                             static_cast<float>(x1 - x0), static_cast<float>(y1 - y0), pal.wall});
  const double step = std::max(5.0, std::round(0.5 * l.text_size));
  const float width = static_cast<float>(std::max(1.0, l.text_size / 10.0));
  for (double k = x0 + y0 + step; k < x1 + y1; k += step) {
    const double lo = std::max(x0, k - y1), hi = std::min(x1, k - y0);
    if (hi - lo < 0.5) continue;
    layer.segments.push_back(Segment{static_cast<float>(lo), static_cast<float>(k - lo),
                                     static_cast<float>(hi), static_cast<float>(k - hi), width,
                                     pal.hatch});
  }
}

void add_wall(Layer& layer, const SnapshotLayout& l, const PanelLayout& p, const Palette& pal) {
  const double y0 = p.centre_y - p.wall_half_height, y1 = p.centre_y + p.wall_half_height;
  add_hatched_block(layer, l.margin, y0, l.x_wall, y1, l, pal);
  layer.segments.push_back(Segment{l.x_wall, static_cast<float>(y0), l.x_wall,
                                   static_cast<float>(y1), 2.0f, pal.wall_face});
}

// The vertical view's ceiling (issue #22): the wall turned upright, a hatched block as thick
// as the wall over the chain's column, whose lower face is bead 0.
void add_ceiling(Layer& layer, const SnapshotLayout& l, const PanelLayout& p, const Palette& pal) {
  const double x0 = p.chain_x - p.wall_half_height, x1 = p.chain_x + p.wall_half_height;
  add_hatched_block(layer, x0, p.ceiling_y - (l.x_wall - l.margin), x1, p.ceiling_y, l, pal);
  layer.segments.push_back(Segment{static_cast<float>(x0), p.ceiling_y, static_cast<float>(x1),
                                   p.ceiling_y, 2.0f, pal.wall_face});
}

std::string format(const char* fmt, double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, fmt, value);
  return buffer;
}

// A leading hyphen as the typographic minus sign (U+2212), as in the overlay and figures.
std::string minus(std::string text) {
  if (!text.empty() && text[0] == '-') text.replace(0, 1, "\u2212");
  return text;
}

// The colour bar: strain_color over s in [-1, 1], ticks at -1, 0, +1 with their values, and
// which side is compression and which tension.
// `per_spring`: the springs have thresholds of their own, and the bar is s = phi_j / phi_c,j.
void add_legend(Layer& layer, const SnapshotLayout& l, const SnapshotStyle& style, bool per_spring,
                const Palette& pal) {
  const float ts = l.text_size;
  const int cells = std::max(1, std::min(256, static_cast<int>(l.legend_w)));
  const float cell_w = l.legend_w / static_cast<float>(cells);
  for (int i = 0; i < cells; ++i) {
    const double s = -1.0 + 2.0 * (i + 0.5) / cells;
    layer.rects.push_back(Rect{l.legend_x + cell_w * static_cast<float>(i), l.legend_y, cell_w,
                               l.legend_h, strain_color(s, style.theme)});
  }
  const bool phi_c = style.threshold > 0;
  const double scale = phi_c ? style.threshold : style.strain_range;
  std::string ticks[3] = {(phi_c ? "−φ_c = " : "φ = ") + minus(format("%.3g", -scale)), "0",
                          (phi_c ? "+φ_c = " : "φ = +") + format("%.3g", scale)};
  if (per_spring) {  // each spring's own threshold: phi_j / phi_c,j = -1, 0, +1
    ticks[0] = "\u2212φ_{c,j}";
    ticks[2] = "+φ_{c,j}";
  }
  const float tick_y = l.legend_y + l.legend_h;
  const float label_y = tick_y + 0.6f * ts;
  for (int t = 0; t < 3; ++t) {
    const float x = l.legend_x + 0.5f * l.legend_w * static_cast<float>(t);
    layer.segments.push_back(Segment{x, tick_y, x, tick_y + 0.4f * ts, 1.0f, pal.dim_text});
    // Left-aligned, centred, right-aligned: the end labels never leave the bar's span.
    const float w = text_width(ticks[t], l.font_px);
    const float label_x = x - 0.5f * w * static_cast<float>(t);
    layer.labels.push_back(Label{ticks[t], label_x, label_y, l.font_px, pal.dim_text});
  }
  const float mid_y = l.legend_y + 0.5f * (l.legend_h - ts);
  const std::string left = "compression", right = "tension";
  layer.labels.push_back(Label{left, l.legend_x - 0.6f * ts - text_width(left, l.font_px), mid_y,
                               l.font_px, pal.text});
  layer.labels.push_back(
      Label{right, l.legend_x + l.legend_w + 0.6f * ts, mid_y, l.font_px, pal.text});
}

// Zoom: a thin bar standing for the whole chain (wall at its left), the drawn stretch marked
// on it in the accent colour, and which springs those are.
void add_overview(Layer& layer, const SnapshotLayout& l, int beads, const Palette& pal) {
  layer.rects.push_back(
      Rect{l.overview_x, l.overview_y, l.overview_w, l.overview_h, pal.rest_line});
  const float x0 = l.overview_x + l.overview_w * static_cast<float>(l.first_bead) / beads;
  const float x1 = l.overview_x + l.overview_w * static_cast<float>(l.last_bead) / beads;
  const float w = std::max(2.0f, x1 - x0);
  layer.rects.push_back(Rect{std::min(x0, l.overview_x + l.overview_w - w), l.overview_y - 1.0f, w,
                             l.overview_h + 2.0f, pal.marker});
  char text[96];
  std::snprintf(text, sizeof text, "springs %d\u2013%d of %d", l.first_bead + 1, l.last_bead,
                beads);
  const float tw = text_width(text, l.font_px);
  layer.labels.push_back(Label{text,
                               std::round(0.5f * (l.overview_x + l.overview_w - tw + l.overview_x)),
                               l.margin, l.font_px, pal.dim_text});
}

}  // namespace

SnapshotLayout snapshot_layout(const SnapshotStyle& style, const ChainParams& params) {
  return layout_for(style, params,
                    size_range(bead_area_ratios(params), spring_width_ratios(params)));
}

namespace snapshot_detail {

SizeRange size_range(const std::vector<double>& area_ratios,
                     const std::vector<double>& width_ratios) {
  SizeRange r;
  for (double a : area_ratios) r.max_area = std::max(r.max_area, a);
  for (double w : width_ratios) r.max_width = std::max(r.max_width, w);
  return r;
}

SnapshotLayout layout_for(const SnapshotStyle& style, const ChainParams& params,
                          const SizeRange& sizes) {
  assert(style.width > 0 && style.height > 0 && "frame size must be positive");
  assert(params.beads >= 1 && "a chain needs at least one bead");
  assert(style.psi_range > 0 && "psi_range sets the scale and must be positive");
  const double W = style.width, frame_h = style.height;
  SnapshotLayout l;
  // One text size for the whole frame (theme/fonts.h); the layout's unit is its cap height.
  const double font_px = frame_text_px(style.height);
  const double ts = std::round(Font::get(FontFace::Sans).cap_height(static_cast<float>(font_px)));
  const double margin = std::max(6.0, std::round(0.025 * std::min(W, frame_h)));
  // Below the chain's band the overlay draws: the legend and the panels stay above it.
  const double H =
      style.chain_height > 0 ? std::min(frame_h, static_cast<double>(style.chain_height)) : frame_h;
  l.text_size = static_cast<float>(ts);
  l.font_px = static_cast<float>(font_px);
  l.first_bead = 0;
  l.last_bead = params.beads;
  if (style.zoom_first > 0 && style.zoom_last > style.zoom_first) {
    l.first_bead = std::min(style.zoom_first - 1, params.beads - 1);
    l.last_bead = std::clamp(style.zoom_last, l.first_bead + 1, params.beads);
    l.last_bead_limited = l.last_bead < params.beads;
  }
  l.margin = static_cast<float>(margin);
  l.x_wall = static_cast<float>(margin + std::max(10.0, std::round(0.02 * W)));
  l.arrow_max = static_cast<float>(std::clamp(std::round(0.08 * W), 30.0, 160.0));
  l.string_length =
      params.pull_string ? static_cast<float>(std::clamp(std::round(0.03 * W), 12.0, 60.0)) : 0.0f;
  // Right of bead N: its radius, the string, the longest arrow and a gap.
  l.x_right =
      static_cast<float>(W - margin - l.arrow_max - l.string_length - 0.5 * ts - kMaxBeadRadius);
  if (style.view == View::Vertical) {  // below bead N: a frame is wide, so scale by its height
    l.arrow_max = static_cast<float>(std::clamp(std::round(0.12 * H), 20.0, 160.0));
    if (params.pull_string)
      l.string_length = static_cast<float>(std::clamp(std::round(0.05 * H), 12.0, 60.0));
  }

  l.legend_h = static_cast<float>(std::round(1.2 * ts));
  l.legend_y = static_cast<float>(H - margin - 1.6 * ts - l.legend_h);
  l.legend_w = static_cast<float>(std::round(std::min(0.36 * W, 34.0 * ts)));
  l.legend_x = static_cast<float>(std::round(0.5 * (W - l.legend_w)));

  const double top = margin + 2.2 * ts;  // below the time label
  if (l.zoomed()) {  // the overview bar: the whole chain, under the time label's row
    l.overview_x = l.x_wall;
    l.overview_w = l.x_right - l.x_wall;
    l.overview_h = static_cast<float>(std::max(3.0, std::round(0.35 * ts)));
    l.overview_y = static_cast<float>(std::round(margin + 1.55 * ts));
  }
  double bottom = std::max(top + 1.0, l.legend_y - 1.4 * ts);
  if (!style.caption.empty()) {  // a row for the caption between the chain and the colour bar
    l.caption_y = static_cast<float>(std::round(l.legend_y - 2.6 * ts));
    bottom = std::max(top + 1.0, l.caption_y - 1.2 * ts);
  }
  if (style.view == View::Both) {
    const double gap = ts;
    const double h = std::max(1.0, 0.5 * (bottom - top - gap));
    l.panels[0] =
        panel_layout(View::Longitudinal, top, top + h, true, l, style, params.beads, sizes);
    l.panels[1] =
        panel_layout(View::Transverse, bottom - h, bottom, true, l, style, params.beads, sizes);
    l.panel_count = 2;
  } else {
    l.panels[0] = panel_layout(style.view, top, bottom, false, l, style, params.beads, sizes);
    l.panel_count = 1;
  }
  // The ribbon is drawn in pixel columns, so only across the frame: a vertical chain keeps
  // its beads however close they come.
  for (int i = 0; i < l.panel_count; ++i)
    l.ribbon |= l.panels[i].view != View::Vertical && l.panels[i].spacing < kRibbonSpacing;
  return l;
}

Color to_color(Rgb8 c, float alpha) {
  return Color{c.r / 255.0f, c.g / 255.0f, c.b / 255.0f, alpha};
}

Palette palette(ThemeName name) {
  const Theme& t = theme(name);
  const auto mix = [](Rgb8 a, Rgb8 b, float w) {
    return Color{(a.r + (b.r - a.r) * w) / 255.0f, (a.g + (b.g - a.g) * w) / 255.0f,
                 (a.b + (b.b - a.b) * w) / 255.0f, 1.0f};
  };
  Palette p;
  p.background = to_color(t.background);
  p.text = to_color(t.text);
  p.dim_text = to_color(t.text_dim);
  p.wall = mix(t.background, t.wall, 0.35f);
  p.hatch = to_color(t.wall);
  p.wall_face = mix(t.wall, t.text, 0.5f);
  p.bead = to_color(t.bead);
  p.broken_half = Color{0.5f, 0.5f, 0.5f, 1.0f};  // neutral: carries no strain
  p.rest_line = to_color(t.rest_line);
  p.force = to_color(t.force);
  p.marker = to_color(t.marker);
  // The first break stands out in the accent colour; later ones recede (the marker colour
  // halfway to the background), so a cascade does not outshout the break that matters.
  p.first_break = to_color(t.accent);
  p.later_break = mix(t.marker, t.background, 0.45f);
  // The flash: a warm white glow on the dark theme; on white paper the marker's amber.
  p.flash = name == ThemeName::Light ? to_color(t.marker) : Color{1.0f, 0.94f, 0.78f, 1.0f};
  return p;
}

double Frame::break_age(int spring) const {
  // The latest recorded break of this spring (there is normally exactly one).
  const auto it = std::upper_bound(breaks_by_spring.begin(), breaks_by_spring.end(), spring,
                                   [](int j, const BreakEvent& b) { return j < b.spring; });
  if (it == breaks_by_spring.begin() || std::prev(it)->spring != spring) {
    return std::numeric_limits<double>::infinity();
  }
  return std::max(0.0, state.tau - std::prev(it)->tau);
}

}  // namespace snapshot_detail

void add_slow_motion_tag(RenderSnapshot& snap, double speed, ThemeName theme) {
  const SnapshotLayout& l = snap.layout;
  const Palette pal = palette(theme);
  char factor[32];
  std::snprintf(factor, sizeof factor, "%.2g", speed);
  const std::string text = "\u00D7" + std::string(factor) + " slow motion";
  const float w = text_width(text, l.font_px);
  const float x = static_cast<float>(snap.width) - l.margin - w;
  Layer& marks = snap.layers[kLayerMarks];
  marks.labels.push_back(Label{text, x, l.margin, l.font_px, pal.text});
  const float y = l.margin + 1.5f * l.text_size;
  marks.rects.push_back(
      Rect{x, y, w, std::max(2.0f, 0.2f * l.text_size), to_color(cb::theme(theme).accent)});
}

RenderSnapshot build_snapshot(const ChainState& state, const ChainParams& params, double force,
                              const SnapshotStyle& style) {
  assert(state.psi.size() == static_cast<std::size_t>(params.beads) && "state does not match N");
  assert(style.force_range > 0 && "force_range sets the arrow scale and must be positive");
  assert((style.threshold > 0 || style.strain_range > 0) && "the colour scale needs a range");
  RenderSnapshot out;
  out.width = style.width;
  out.height = style.height;
  const Palette pal = palette(style.theme);
  out.background = pal.background;
  out.tau = state.tau;
  out.force = force;
  out.beads = params.beads;
  std::vector<double> areas = bead_area_ratios(params), widths = spring_width_ratios(params);
  out.layout = layout_for(style, params, size_range(areas, widths));
  out.ribbon = out.layout.ribbon;
  out.layers.resize(kLayerCount);
  for (const BreakEvent& b : state.breaks) {
    if (b.tau <= state.tau) out.breaks_shown.push_back(b);
  }

  Frame frame{state,
              params,
              style,
              out.layout,
              pal,
              force,
              1.0,
              true,
              std::move(areas),
              std::move(widths),
              {},
              out.breaks_shown,
              out};
  frame.strain_scale = style.threshold > 0 ? style.threshold : style.strain_range;
  if (strain_per_spring(params)) {  // phi_j / phi_c,j (snapshot/strain_scale.h)
    frame.spring_scale.resize(static_cast<std::size_t>(params.beads));
    for (int j = 1; j <= params.beads; ++j)
      frame.spring_scale[j - 1] = spring_strain_scale(params, j, frame.strain_scale);
  }
  std::stable_sort(frame.breaks_by_spring.begin(), frame.breaks_by_spring.end(),
                   [](const BreakEvent& a, const BreakEvent& b) { return a.spring < b.spring; });
  frame.string_intact = !state.string_broken && (frame.breaks_by_spring.empty() ||
                                                 frame.breaks_by_spring.front().spring != 0);

  const SnapshotLayout& l = out.layout;
  Layer& back = frame.layer(kLayerFrame);
  for (int i = 0; i < l.panel_count; ++i) {
    const PanelLayout& p = l.panels[i];
    if (l.first_bead == 0) {
      if (p.view == View::Vertical) {
        add_ceiling(back, l, p, pal);
      } else {
        add_wall(back, l, p, pal);
      }
    }
    if (p.view == View::Transverse) {  // the rest line psi = 0, a reference for the eye
      back.segments.push_back(
          Segment{l.x_wall, p.centre_y, l.x_right, p.centre_y, 1.0f, pal.rest_line});
    }
    if (l.panel_count > 1) {
      const std::string caption = p.view == View::Longitudinal ? "longitudinal: x = j + ψ_j"
                                                               : "transverse: ψ_j drawn across";
      back.labels.push_back(Label{caption, l.margin, p.top, l.font_px, pal.dim_text});
    }
  }
  add_legend(back, l, style, strain_per_spring(params), pal);
  if (l.zoomed()) add_overview(back, l, params.beads, pal);
  if (!style.caption.empty()) {
    const float w = text_width(style.caption, l.font_px);
    back.labels.push_back(Label{style.caption, std::round(0.5f * (style.width - w)), l.caption_y,
                                l.font_px, pal.text});
  }
  frame.layer(kLayerMarks)
      .labels.push_back(
          Label{minus(format("τ = %.2f", state.tau)), l.margin, l.margin, l.font_px, pal.text});

  for (int i = 0; i < l.panel_count; ++i) draw_chain_panel(frame, l.panels[i]);
  return out;
}

}  // namespace cb
