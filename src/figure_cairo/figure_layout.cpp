#include "figure_cairo/figure_layout.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace cb {

namespace {

// Code points, not bytes: labels hold Greek letters and minus signs.
double glyphs(const std::string& s) {
  return static_cast<double>(
      std::count_if(s.begin(), s.end(), [](char ch) { return (ch & 0xC0) != 0x80; }));
}

// A generous width estimate: DejaVu Sans digits and most lowercase letters are 0.5-0.64 em,
// the minus sign 0.84 em.
double text_width(const std::string& s, double size, double em = 0.66) {
  return em * size * glyphs(s);
}

FigurePanelLayout panel_layout(const Panel& p, const FigureBox& region, const FigureMetrics& m) {
  FigurePanelLayout l;
  l.box = {std::round(region.x + p.left * region.w), std::round(region.y + p.top * region.h),
           std::round(p.width * region.w), std::round(p.height * region.h)};
  l.x_ticks = axis_ticks(p.x, 10);
  l.y_ticks = axis_ticks(p.y, 8);
  const double fs = m.font, pad = 0.4 * fs;
  double widest = 0;
  for (const std::string& label : l.y_ticks.labels)
    widest = std::max(widest, text_width(label, m.small));
  const double y_label = p.y.label.empty() ? 0.0 : 1.4 * fs;
  const double left = pad + y_label + widest + 0.3 * fs + m.tick;
  const double top = (p.title.empty() ? 0.5 * fs : 1.9 * fs) + 0.5 * m.small;
  const double x_label = p.x.label.empty() ? 0.0 : 0.4 * fs + fs;
  const double bottom = m.tick + 0.3 * fs + m.small + x_label + pad;
  double right = 0.8 * fs;
  if (!l.x_ticks.labels.empty())
    right = std::max(right, 0.5 * text_width(l.x_ticks.labels.back(), m.small) + 0.3 * fs);
  if (!p.heatmap.empty()) right += 1.0 * fs + 1.0 * fs + 4.0 * m.small;  // the colour bar
  FigureBox& a = l.mapping.area;
  a.x = std::round(l.box.x + left);
  a.y = std::round(l.box.y + top);
  a.w = std::round(l.box.right() - right - a.x);
  a.h = std::round(l.box.bottom() - bottom - a.y);
  l.mapping.x0 = axis_value(p.x, p.x.lo);
  l.mapping.x1 = axis_value(p.x, p.x.hi);
  l.mapping.y0 = p.y.lo;
  l.mapping.y1 = p.y.hi;
  l.title_y = l.box.y + 0.3 * fs + 0.5 * fs;
  l.x_label_y = a.bottom() + m.tick + 0.3 * fs + m.small + 0.4 * fs + 0.5 * fs;
  l.y_label_x = l.box.x + pad + 0.5 * fs;
  if (!p.heatmap.empty()) {
    // The bar's label sits above it, inside the area's height.
    const double label = 2.2 * m.small;
    l.colour_bar = {a.right() + 1.0 * fs, a.y + label, 1.0 * fs, a.h - label};
  }
  return l;
}

}  // namespace

FigureMetrics figure_metrics(int height) {
  const double h = static_cast<double>(height);
  FigureMetrics m;
  m.font = std::round(0.024 * h);
  m.small = std::round(0.85 * m.font);
  m.caption = std::round(0.8 * m.font);
  m.line = std::max(1.5, 0.0025 * h);
  m.tick = std::round(0.35 * m.font);
  m.point = 0.22 * m.font;
  return m;
}

FigureLayout figure_layout(const Figure& figure, int width, int height) {
  const FigureMetrics m = figure_metrics(height);
  const double w = width, h = height, margin = 0.6 * m.font;
  FigureLayout out;
  FigureBox region{0, 0, w, h};
  if (!figure.caption.empty()) {
    // Lines at an estimated 0.6 em a glyph (prose); the drawer wraps at the measured width and
    // shrinks the text a little in the rare case it needs more lines than reserved here.
    const double line_width = w - 2 * margin;
    out.caption_lines = std::max(
        1, static_cast<int>(std::ceil(text_width(figure.caption, m.caption, 0.6) / line_width)));
    const double lines_h = 1.3 * m.caption * out.caption_lines;
    out.caption = {margin, h - margin - lines_h, line_width, lines_h};
    region.h = out.caption.y - 0.3 * m.font;
  }
  for (const Panel& p : figure.panels) out.panels.push_back(panel_layout(p, region, m));
  return out;
}

}  // namespace cb
