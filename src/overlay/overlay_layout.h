// Where the overlay's panels go and how each plot maps data to pixels. Plain geometry (no GL):
// the app uses it to leave the chain its band (SnapshotStyle::chain_height), the overlay to
// draw, and the tests to find the pixel a data point lands on.
//
// Design note: the chain keeps the full width of the frame's upper part (a chain of N beads
// wants width) and the panels share the band below it in columns, side by side (two rows on
// a portrait frame). Sizes follow the frame's height like the snapshot's text does, so a 4K
// frame is a 1080p frame at twice the scale.
#pragma once

#include <vector>

#include "overlay/overlay_data.h"

namespace cb {

struct Box {
  float x = 0, y = 0, w = 0, h = 0;  // pixels, origin top-left, y down (panels: whole pixels)
  float right() const { return x + w; }
  float bottom() const { return y + h; }
  bool empty() const { return !(w > 0 && h > 0); }
};

// Smaller frames get no overlay: its text and plots would be unreadable there.
inline constexpr int kOverlayMinWidth = 640, kOverlayMinHeight = 360;

struct OverlayLayout {
  bool enabled = false;  // false: every part is off, or the frame is too small
  int chain_height = 0;  // for SnapshotStyle::chain_height (0 when not enabled)
  float font_px = 0;     // text height of the overlay's fonts: 1.8% of the frame's height
  float line_px = 0;     // thickness of the plotted lines, whole pixels
  Box band;              // the overlay's part of the frame, below the chain
  Box hud, phi, energy, spacetime, modes;  // the panels; empty when switched off
};

OverlayLayout overlay_layout(int width, int height, const OverlaySwitches& switches);

// The data rectangle inside a plot panel: `header` text lines above (the title), tick labels
// left and below.
Box plot_area(const Box& panel, float font_px, int header = 1);

// Where the x tick labels of a plot go, left to right, given each tick's x and its label's
// width: centred under the tick, except a last label that would run past the area's right
// edge by more than half a font, which is right-aligned at its tick so it stays in the panel;
// and a label that would come within half a font of the label right of it is left out, so no
// two touch (the end of the axis keeps its label). Each label's left edge, NaN when left out.
std::vector<float> x_tick_label_lefts(const std::vector<float>& x, const std::vector<float>& width,
                                      float area_right, float font_px);

// Data to pixels: x0 .. x1 across the area, y0 at its bottom edge, y1 at its top edge.
struct PlotMapping {
  Box area;
  double x0 = 0, x1 = 1, y0 = 0, y1 = 1;
  float px(double x) const { return static_cast<float>(area.x + (x - x0) / (x1 - x0) * area.w); }
  float py(double y) const {
    return static_cast<float>(area.bottom() - (y - y0) / (y1 - y0) * area.h);
  }
};

// x: tau from 0 to tau_end; y: the data's fixed axis.
PlotMapping phi_mapping(const OverlayLayout& layout, const OverlayData& data);
PlotMapping energy_mapping(const OverlayLayout& layout, const OverlayData& data);
// x: springs, 0 (the wall) .. N (the pulled end), column c spanning its springs' block;
// y: tau from 0 to tau_end.
PlotMapping spacetime_mapping(const OverlayLayout& layout, const OverlayData& data);
// x: mode index n centred on n, from -0.5 to count - 0.5; y: A_n / mode_scale from 0 to 1.
PlotMapping modes_mapping(const OverlayLayout& layout, const OverlayData& data);

}  // namespace cb
