// Where a Figure's panels go in a picture and how their data map to pixels. Plain geometry
// (no GL): the FigureDrawer draws with it, the tests find the pixel a data point lands on.
//
// Design note: a figure is a still picture read closely, not a corner of a video, so its text
// is larger than the overlay's (2.4% of the height). The y label sits above the y axis rather
// than rotated beside it: ImGui draws text horizontally only.
#pragma once

#include "figures/figure.h"
#include "overlay/overlay_layout.h"

namespace cb {

// The size `chainbreak figures` draws at: large enough to read a spring index off the
// breaking map, small enough for goldens in the repository (tests/golden/figures).
inline constexpr int kFigureWidth = 1200, kFigureHeight = 800;

struct FigurePanelLayout {
  Box box;              // the panel's outline
  PlotMapping mapping;  // mapping.area: the data rectangle; log axes map log10(x)
  Box colour_bar;       // beside the area when the panel has a heatmap, else empty
};

float figure_font_px(int height);
FigurePanelLayout figure_panel_layout(const Panel& panel, int width, int height);
// A data x in the mapping's units: log10(x) on a log axis.
double figure_axis_value(const Axis& axis, double value);

}  // namespace cb
