#include "overlay/figure_layout.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace cb {

namespace {

// Code points, not bytes: tick labels hold Greek letters and minus signs.
std::size_t glyphs(const std::string& s) {
  return static_cast<std::size_t>(
      std::count_if(s.begin(), s.end(), [](char ch) { return (ch & 0xC0) != 0x80; }));
}

}  // namespace

float figure_font_px(int height) {
  return std::round(0.024f * static_cast<float>(height));
}

double figure_axis_value(const Axis& axis, double value) {
  return axis.log ? std::log10(value) : value;
}

FigurePanelLayout figure_panel_layout(const Panel& panel, int width, int height) {
  const float fs = figure_font_px(height);
  const float w = static_cast<float>(width), h = static_cast<float>(height);
  FigurePanelLayout l;
  l.box = {std::round(panel.left * w), std::round(panel.top * h), std::round(panel.width * w),
           std::round(panel.height * h)};
  // Tick labels are DejaVu Sans Mono at 0.85 of the font size: 0.6 em a glyph.
  std::size_t widest = 6;
  for (const AxisTick& t : panel.y.ticks) widest = std::max(widest, glyphs(t.label));
  const float left = 0.85f * 0.61f * fs * static_cast<float>(widest) + 1.0f * fs;
  const float top = 2.9f * fs;     // the title row, then the y label's row
  const float bottom = 2.8f * fs;  // tick labels, then the x label
  float right = 1.2f * fs;
  if (!panel.heatmap.empty()) right += 5.5f * fs;  // the colour bar and its labels
  Box area{std::round(l.box.x + left), std::round(l.box.y + top), 0, 0};
  area.w = std::round(l.box.right() - right - area.x);
  area.h = std::round(l.box.bottom() - bottom - area.y);
  l.mapping.area = area;
  l.mapping.x0 = figure_axis_value(panel.x, panel.x.lo);
  l.mapping.x1 = figure_axis_value(panel.x, panel.x.hi);
  l.mapping.y0 = panel.y.lo;
  l.mapping.y1 = panel.y.hi;
  if (!panel.heatmap.empty()) l.colour_bar = {area.right() + 1.2f * fs, area.y, 1.0f * fs, area.h};
  return l;
}

}  // namespace cb
