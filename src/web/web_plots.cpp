#include "web/web_plots.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "figures/axis_ticks.h"
#include "snapshot/snapshot_internal.h"
#include "text/text_layout.h"
#include "theme/theme.h"

namespace cb {

namespace {

using snapshot_detail::to_color;

class Painter {
 public:
  Painter(Layer& layer, const Theme& theme, float font_px, float line_px)
      : layer_(layer), theme_(theme), font_px_(font_px), line_px_(line_px) {}

  void rect(const Box& b, Rgb8 c, float alpha = 1.0f) { rect(b, to_color(c, alpha)); }
  void rect(const Box& b, Color c) { layer_.rects.push_back({b.x, b.y, b.w, b.h, c}); }
  void picture(Picture pic) { layer_.pictures.push_back(std::move(pic)); }
  void line(float x0, float y0, float x1, float y1, Rgb8 c, float width, float alpha = 1.0f) {
    layer_.segments.push_back({x0, y0, x1, y1, width, to_color(c, alpha)});
  }
  void text(const std::string& s, float x, float y, Rgb8 c, float scale = 1.0f) {
    Label l;
    l.text = s;
    l.x = x;
    l.y = y;
    l.size = font_px_ * scale;
    l.color = to_color(c);
    layer_.labels.push_back(std::move(l));
  }
  // A polyline through (xs[i], ys[i]) for i < count, clipped to the mapping's y range; NaN
  // values break it.
  void curve(const PlotMapping& m, const std::vector<double>& xs, const std::vector<double>& ys,
             Rgb8 c, float width, float alpha = 1.0f) {
    const std::size_t count = std::min(xs.size(), ys.size());
    const double lo = std::min(m.y0, m.y1), hi = std::max(m.y0, m.y1);
    for (std::size_t i = 1; i < count; ++i) {
      const double a = ys[i - 1], b = ys[i];
      if (!std::isfinite(a) || !std::isfinite(b)) continue;
      if ((a < lo && b < lo) || (a > hi && b > hi)) continue;
      line(m.px(xs[i - 1]), m.py(std::clamp(a, lo, hi)), m.px(xs[i]), m.py(std::clamp(b, lo, hi)),
           c, width, alpha);
    }
  }
  // Panel, frame, ticks on both axes and a title line, laid out as the video's overlay lays
  // out its plots (overlay_plot.cpp, axes) with the same labels (figures/axis_ticks.h): the
  // y labels right-aligned left of the area, a power of ten they share at the right of the
  // title row, the x labels placed by x_tick_label_lefts, and `x_name` in the corner below
  // the y labels, where no tick label is.
  void axes(const Box& panel, const PlotMapping& m, const std::string& title,
            const std::string& x_name) {
    rect(panel, theme_.panel);
    const Box& a = m.area;
    const float label_px = font_px_ * 0.85f;
    text(title, panel.x + font_px_ * 0.5f, panel.y + font_px_ * 0.4f, theme_.text);
    const Ticks yt = nice_ticks(std::min(m.y0, m.y1), std::max(m.y0, m.y1), 4);
    const TickFormat yf = tick_format(yt);
    for (double v : yt.values) {
      const float y = m.py(v);
      line(a.x, y, a.right(), y, theme_.grid, 1.0f);
      const std::string s = tick_label(v, yf);
      text(s, a.x - font_px_ * 0.3f - text_width(s, label_px), y - font_px_ * 0.35f,
           theme_.text_dim, 0.85f);
    }
    const Ticks xt = nice_ticks(m.x0, m.x1, 5);
    std::vector<float> xs, widths;
    std::vector<std::string> labels;
    for (double v : xt.values) {
      xs.push_back(m.px(v));
      line(xs.back(), a.y, xs.back(), a.bottom(), theme_.grid, 1.0f);
      labels.push_back(x_tick_label(v, xt));
      widths.push_back(text_width(labels.back(), label_px));
    }
    const std::vector<float> lefts = x_tick_label_lefts(xs, widths, a.right(), font_px_);
    for (std::size_t i = 0; i < labels.size(); ++i)
      if (!std::isnan(lefts[i]))
        text(labels[i], lefts[i], a.bottom() + font_px_ * 0.4f, theme_.text_dim, 0.85f);
    text(x_name, panel.x + font_px_ * 0.45f, a.bottom() + font_px_ * 0.4f, theme_.text_dim, 0.85f);
    if (yf.exponent != 0) {
      const std::string e = power_of_ten_text(yf.exponent);
      const float title_right =
          panel.x + font_px_ * 0.5f + text_width(title, font_px_) + font_px_ * 0.6f;
      const float e_left = panel.right() - font_px_ * 0.45f - text_width(e, label_px);
      if (e_left >= title_right)  // else inside the plot's top-right corner
        text(e, e_left, panel.y + font_px_ * 0.4f, theme_.text_dim, 0.85f);
      else
        text(e, a.right() - font_px_ * 0.3f - text_width(e, label_px), a.y + font_px_ * 0.3f,
             theme_.text_dim, 0.85f);
    }
    for (const auto& [x0, y0, x1, y1] :
         {std::array<float, 4>{a.x, a.y, a.right(), a.y},
          std::array<float, 4>{a.x, a.bottom(), a.right(), a.bottom()},
          std::array<float, 4>{a.x, a.y, a.x, a.bottom()},
          std::array<float, 4>{a.right(), a.y, a.right(), a.bottom()}})
      line(x0, y0, x1, y1, theme_.axis, 1.0f);
  }
  // The current time and the breaks so far as vertical lines.
  void times(const PlotMapping& m, const OverlayData& d) {
    for (const OverlayBreak& b : d.breaks)
      line(m.px(b.tau), m.area.y, m.px(b.tau), m.area.bottom(), theme_.accent, 1.0f, 0.6f);
    line(m.px(d.tau), m.area.y, m.px(d.tau), m.area.bottom(), theme_.cursor, 1.0f);
  }
  float line_px() const { return line_px_; }
  const Theme& theme() const { return theme_; }

 private:
  Layer& layer_;
  const Theme& theme_;
  float font_px_, line_px_;
};

std::string spring_name(int spring, int beads) {
  if (spring == 1) return "φ_1";
  if (spring == beads) return "φ_N";
  if (spring == beads / 2) return "φ_{N/2}";
  return "φ_{" + std::to_string(spring) + "}";
}

void phi_panel(Painter& p, const OverlayData& d, const OverlayLayout& layout) {
  const PlotMapping m = phi_mapping(layout, d);
  p.axes(layout.phi, m, d.exact ? "φ_j(τ): RK4 (thick), exact (thin)" : "φ_j(τ)", "τ");
  const Theme& t = p.theme();
  if (d.phi_c > 0) {
    p.line(m.area.x, m.py(d.phi_c), m.area.right(), m.py(d.phi_c), t.accent, 1.0f);
    if (d.threshold_both_signs)
      p.line(m.area.x, m.py(-d.phi_c), m.area.right(), m.py(-d.phi_c), t.accent, 1.0f);
  }
  p.times(m, d);
  for (int s = 0; s < d.spring_count; ++s) {
    p.curve(m, d.history_tau, d.phi[s], t.series[s], p.line_px() * 2.0f);
    if (d.exact) p.curve(m, d.exact_tau, d.exact_phi[s], t.text, 1.0f, 0.8f);
  }
  // The legend: each spring's name in its colour, along the top.
  float x = m.area.x + 4.0f;
  for (int s = 0; s < d.spring_count; ++s) {
    const std::string name = spring_name(d.springs[s], d.beads);
    p.text(name, x, m.area.y + 4.0f, t.series[s], 0.9f);
    x += layout.font_px * (1.0f + 0.55f * static_cast<float>(name.size()));
  }
}

void energy_panel(Painter& p, const OverlayData& d, const OverlayLayout& layout) {
  const PlotMapping m = energy_mapping(layout, d);
  p.axes(layout.energy, m, "energy E/N³: total, kinetic, potential", "τ");
  const Theme& t = p.theme();
  p.times(m, d);
  p.curve(m, d.history_tau, d.energy_kinetic, t.kinetic, p.line_px());
  p.curve(m, d.history_tau, d.energy_potential, t.potential, p.line_px());
  p.curve(m, d.history_tau, d.energy_total, t.total, p.line_px() * 2.0f);
}

void spacetime_panel(Painter& p, const OverlayData& d, const OverlayLayout& layout,
                     ThemeName theme) {
  const PlotMapping m = spacetime_mapping(layout, d);
  p.axes(layout.spacetime, m, "strain φ_j/φ_c (j across, τ up)", "j");
  const int rows = d.spacetime_rows(), columns = d.spacetime_columns;
  if (rows == 0 || columns == 0) return;
  // One picture of the plot area, a texel per column and per pixel row, painted row after row
  // as the rects of each row were (a later row over an earlier one; a broken spring leaves a
  // gap): 512 x 256 rects cost SwiftShader about 10 ms a frame, one picture under 1 ms.
  Picture pic;
  pic.x = m.area.x;
  pic.y = m.area.y;
  pic.w = m.area.w;
  pic.rows = std::max(1, static_cast<int>(std::lround(m.area.h)));
  pic.h = static_cast<float>(pic.rows);
  pic.columns = columns;
  pic.rgba.assign(static_cast<std::size_t>(pic.rows) * columns * 4, 0);
  const auto byte = [](float v) {
    return static_cast<std::uint8_t>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
  };
  for (int r = 0; r < rows; ++r) {
    const double tau0 = d.spacetime_tau[r];
    const double tau1 = r + 1 < rows ? d.spacetime_tau[r + 1] : d.tau;
    const float y1 = m.py(tau0), y0 = m.py(std::max(tau1, tau0));
    const float top = y0 - m.area.y, bottom = top + std::max(1.0f, y1 - y0);
    // The pixel rows whose centres the row's rect covers.
    const int k0 = std::max(0, static_cast<int>(std::ceil(top - 0.5f)));
    const int k1 = std::min(pic.rows, static_cast<int>(std::ceil(bottom - 0.5f)));
    for (int c = 0; c < columns; ++c) {
      const float s = d.spacetime[static_cast<std::size_t>(r) * columns + c];
      if (!std::isfinite(s)) continue;  // a broken spring: a gap
      // The strain colour map of the chain itself (snapshot.h), not a second one.
      const Color col = strain_color(s, theme);
      for (int k = k0; k < k1; ++k) {
        std::uint8_t* px = &pic.rgba[(static_cast<std::size_t>(k) * columns + c) * 4];
        px[0] = byte(col.r);
        px[1] = byte(col.g);
        px[2] = byte(col.b);
        px[3] = byte(col.a);
      }
    }
  }
  p.picture(std::move(pic));
}

void map_panel(Painter& p, const WebBreakMap& map, const OverlayLayout& layout) {
  const double hi = map.zeta.empty() ? 1.0 : map.zeta.back();
  const PlotMapping m{plot_area(layout.modes, layout.font_px), 0.0, hi, 0.0,
                      static_cast<double>(std::max(1, map.beads))};
  p.axes(layout.modes, m, "first break j vs ζ_c = φ_c/β (exact)", "ζ_c");
  const Theme& t = p.theme();
  const float size = std::max(2.0f, p.line_px() * 3.0f);
  for (std::size_t i = 0; i < map.zeta.size(); ++i) {
    if (map.spring[i] < 0) continue;
    const float x = m.px(map.zeta[i]), y = m.py(map.spring[i]);
    p.rect({x - size / 2, y - size / 2, size, size},
           map.spring[i] == map.beads ? t.series[2] : t.series[0]);
  }
  if (map.current >= 0 && map.current <= hi)
    p.line(m.px(map.current), m.area.y, m.px(map.current), m.area.bottom(), t.cursor, 2.0f);
}

}  // namespace

OverlaySwitches web_plot_switches() {
  OverlaySwitches s;
  s.hud = false;
  return s;
}

Layer web_plot_layer(const OverlayData& data, const WebBreakMap& map, const OverlayLayout& layout,
                     ThemeName theme_name) {
  Layer layer;
  Painter p(layer, theme(theme_name), layout.font_px, std::max(1.0f, layout.line_px));
  if (!layout.phi.empty()) phi_panel(p, data, layout);
  if (!layout.energy.empty()) energy_panel(p, data, layout);
  if (!layout.spacetime.empty()) spacetime_panel(p, data, layout, theme_name);
  if (!layout.modes.empty() && !map.zeta.empty()) map_panel(p, map, layout);
  return layer;
}

}  // namespace cb
