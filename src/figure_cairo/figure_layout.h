// Where a Figure's panels, axes, labels and caption go, and how data map to positions. Plain
// geometry (no cairo): the drawing function (figure_draw.h) places everything with it, the
// tests find the pixel a data point lands on and where a label's text is.
//
// Design note: one layout in figure units for every output: a PNG pixel is one unit, an SVG
// user unit is one unit, a PDF page is the same layout scaled to points (figure_output.h).
// Text sizes follow the figure's height; text widths are estimated here (DejaVu Sans digits
// are 0.64 em wide), so the layout needs no font and is the same for every surface.
#pragma once

#include <vector>

#include "figures/axis_ticks.h"
#include "figures/figure.h"

namespace cb {

// The size `chainbreak figures` draws at: large enough to read a spring index off the
// breaking map, small enough for goldens in the repository (tests/golden/figures).
inline constexpr int kFigureWidth = 1200, kFigureHeight = 800;

struct FigureBox {
  double x = 0, y = 0, w = 0, h = 0;
  double right() const { return x + w; }
  double bottom() const { return y + h; }
  bool empty() const { return w <= 0 || h <= 0; }
};

// Data -> figure units in a plot area (y grows upwards in data, downwards in the picture).
// x0, x1 are in the axis' mapping units: log10 of the data on a log axis (axis_value()).
struct FigureMapping {
  FigureBox area;
  double x0 = 0, x1 = 1, y0 = 0, y1 = 1;
  double px(double x) const { return area.x + (x - x0) / (x1 - x0) * area.w; }
  double py(double y) const { return area.bottom() - (y - y0) / (y1 - y0) * area.h; }
};

// Text sizes and strokes, in figure units, for a figure of this height.
struct FigureMetrics {
  double font = 0;     // titles, axis labels (2.4% of the height: 19 px of 800)
  double small = 0;    // tick labels, legends, notes, colour bar
  double caption = 0;  // the caption under the panels
  double line = 0;     // data lines
  double tick = 0;     // tick marks' length
  double point = 0;    // a data point's radius
};
FigureMetrics figure_metrics(int height);

struct FigurePanelLayout {
  FigureBox box;          // the panel's outline (an inset's background)
  FigureMapping mapping;  // mapping.area: the data rectangle
  FigureBox colour_bar;   // beside the area when the panel has a heatmap, else empty
  Ticks x_ticks, y_ticks;
  double title_y = 0;    // the vertical middle of the title's row
  double x_label_y = 0;  // the vertical middle of the x axis' label
  double y_label_x = 0;  // the horizontal middle of the (rotated) y axis' label
};

struct FigureLayout {
  std::vector<FigurePanelLayout> panels;  // one per Figure::panels, in order
  FigureBox caption;                      // the caption's lines; empty without a caption
  int caption_lines = 0;                  // the lines reserved for it
};

FigureLayout figure_layout(const Figure& figure, int width, int height);

}  // namespace cb
