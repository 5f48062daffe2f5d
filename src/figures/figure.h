// A figure as plain data: panels of series over axes, with no GL and no cairo. Built by
// figure_specs.h (the paper's Figs. 3-5 and the maps of which part breaks), drawn into PNG,
// SVG and PDF by one function of the cairo backend (figure_cairo/figure_draw.h), written as
// CSV by the app: one struct, every output, so the pictures and the CSV cannot disagree.
#pragma once

#include <cmath>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "theme/theme.h"

namespace cb {

// A series' or note's colour as a role of the theme (theme/theme.h), not as a colour: the same
// figure is drawn black on white (light) and light on dark, so "ink" is black on paper and
// near-white on a projector. figure_rgb() resolves a role under a theme.
enum class FigureColour {
  Ink,      // the theme's text colour: the exact solution, totals, notes
  Muted,    // the theme's secondary text colour: continuum bands, guides
  Accent,   // thresholds, switches (Okabe-Ito vermillion)
  Series0,  // the theme's three data series (Okabe-Ito: told apart by colour-blind readers)
  Series1,
  Series2,
  Kinetic,    // the energy plot's kinetic (reddish purple), also windows of a second kind
  Potential,  // the energy plot's potential (yellow; a darker gold on white)
};
inline Rgb8 figure_rgb(FigureColour colour, const Theme& t) {
  switch (colour) {
    case FigureColour::Ink:
      return t.text;
    case FigureColour::Muted:
      return t.text_dim;
    case FigureColour::Accent:
      return t.accent;
    case FigureColour::Series0:
      return t.series[0];
    case FigureColour::Series1:
      return t.series[1];
    case FigureColour::Series2:
      return t.series[2];
    case FigureColour::Kinetic:
      return t.kinetic;
    case FigureColour::Potential:
      return t.potential;
  }
  return t.text;
}

enum class SeriesStyle {
  Line,    // a polyline through (x[i], y[i]); NaN in y breaks it
  Points,  // a dot at each (x[i], y[i])
  Band,    // filled between y[i] and y2[i] over x (translucent)
  XSpans,  // shaded columns x[i] .. x2[i], the whole height (translucent)
  VLines,  // dashed vertical lines at x[i]
  HLines,  // dashed horizontal lines at y[i]
};
const char* series_style_name(SeriesStyle style);

struct Series {
  std::string label;  // the legend entry and the CSV's series name; empty: no legend entry
  SeriesStyle style = SeriesStyle::Line;
  FigureColour colour = FigureColour::Ink;
  std::vector<double> x, y;
  std::vector<double> x2, y2;  // XSpans: right edges; Band: upper edges
};

// How a heatmap's value / scale becomes a colour.
enum class HeatmapColours {
  Strain,      // the chain's diverging strain colour map over -1 .. 1 (signed fields)
  Sequential,  // 0 .. 1 from the background to full ink, lightness monotonic: reads in greyscale
};

// A scalar field over a grid of cells: value(column, row) = values[row * columns + column],
// column 0 at x_lo, row 0 at y_lo, coloured at value / scale. With x_log the columns are
// equally wide in log10 x (for a log x axis), else in x.
struct Heatmap {
  int columns = 0, rows = 0;
  double x_lo = 0, x_hi = 1, y_lo = 0, y_hi = 1;
  std::vector<float> values;
  double scale = 1.0;
  std::string label;  // what the colour bar shows
  HeatmapColours colours = HeatmapColours::Strain;
  bool x_log = false;
  bool empty() const { return columns == 0 || rows == 0; }
  double x_at(int column) const {
    const double f = (column + 0.5) / columns;
    return x_log ? std::pow(10.0, std::log10(x_lo) + f * (std::log10(x_hi) - std::log10(x_lo)))
                 : x_lo + f * (x_hi - x_lo);
  }
  double y_at(int row) const { return y_lo + (row + 0.5) * (y_hi - y_lo) / rows; }
};

struct AxisTick {
  double value = 0;
  std::string label;
};

struct Axis {
  std::string label;
  double lo = 0, hi = 1;
  bool log = false;             // log10 scale (lo > 0)
  std::vector<AxisTick> ticks;  // empty: round numbers chosen by the drawer
};
inline Axis axis(std::string label, double lo, double hi, bool log = false) {
  return Axis{std::move(label), lo, hi, log, {}};
}

// Text at a data point (the left end of the text at x, its vertical middle at y).
struct Note {
  double x = 0, y = 0;
  std::string text;
  FigureColour colour = FigureColour::Ink;
};

struct Panel {
  std::string title;
  Axis x, y;
  std::vector<Series> series;  // drawn in order, after the heatmap
  Heatmap heatmap;
  std::vector<Note> notes;
  enum class Legend { TopLeft, BottomRight } legend = Legend::TopLeft;  // clear of the data
  // Where the panel goes, as fractions of the figure. An inset is a small later panel drawn
  // over an earlier one, on its own background.
  float left = 0, top = 0, width = 1, height = 1;
  bool inset = false;
};

struct Figure {
  std::string name;     // file stem: fig4a -> fig4a.png, .svg, .pdf, .csv
  std::string caption;  // what it shows and with which parameters (drawn under the panels)
  std::vector<Panel> panels;
};

}  // namespace cb
