#include "figures/figure.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

#include "figures/figure_specs.h"

namespace cb {

const char* series_style_name(SeriesStyle style) {
  switch (style) {
    case SeriesStyle::Line:
      return "line";
    case SeriesStyle::Points:
      return "points";
    case SeriesStyle::Band:
      return "band";
    case SeriesStyle::XSpans:
      return "xspans";
    case SeriesStyle::VLines:
      return "vlines";
    case SeriesStyle::HLines:
      return "hlines";
  }
  return "?";
}

std::vector<double> linspace(double lo, double hi, int count) {
  std::vector<double> out;
  for (int i = 0; i < count; ++i) out.push_back(count == 1 ? lo : lo + (hi - lo) * i / (count - 1));
  return out;
}

std::vector<double> logspace(double lo, double hi, int count) {
  std::vector<double> out = linspace(std::log(lo), std::log(hi), count);
  for (double& v : out) v = std::exp(v);
  return out;
}

Series make_series(std::string label, SeriesStyle style, FigureColour colour, std::vector<double> x,
                   std::vector<double> y) {
  Series s;
  s.label = std::move(label);
  s.style = style;
  s.colour = colour;
  s.x = std::move(x);
  s.y = std::move(y);
  return s;
}

std::string fixed(double value, int decimals) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f", decimals, value);
  return buffer;
}

void fit_y(Panel& panel, double pad) {
  double lo = INFINITY, hi = -INFINITY;
  for (const Series& s : panel.series)
    for (double v : s.y)
      if (std::isfinite(v)) {
        lo = std::min(lo, v);
        hi = std::max(hi, v);
      }
  if (!(hi > lo)) return;
  panel.y.lo = lo - pad * (hi - lo);
  panel.y.hi = hi + pad * (hi - lo);
}

const Series* find_series(const Panel& panel, const std::string& label) {
  for (const Series& s : panel.series)
    if (s.label == label) return &s;
  return nullptr;
}

const std::vector<FigureEntry>& figure_entries() {
  static const std::vector<FigureEntry> entries = {
      {"fig3a", figure_3a},
      {"fig3b", figure_3b},
      {"fig3c", figure_3c},
      {"fig3d", figure_3d},
      {"fig4a", figure_4a},
      {"fig4b", figure_4b},
      {"fig4c", figure_4c},
      {"fig4d", figure_4d},
      {"fig5", figure_5},
      {"breaking_map", figure_breaking_map},
      {"one_body_map", figure_one_body_map},
      {"gravity_map", figure_gravity_map},
      {"hanging_map", figure_hanging_map},
      {"fput_map", figure_fput_map},
      {"flaw_map", figure_flaw_map},
  };
  return entries;
}

}  // namespace cb
