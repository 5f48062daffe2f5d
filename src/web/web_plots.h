// The overlay's plots in the page, drawn by the program's renderer: the overlay (src/overlay)
// draws them with Dear ImGui, which has no WebAssembly build here (PLATFORM-NOTES.md), so the
// page turns the same OverlayData, laid out by the same overlay_layout() and mapped by the same
// PlotMapping, into one more snapshot layer of lines, rectangles and labels.
#pragma once

#include "overlay/overlay_data.h"
#include "overlay/overlay_layout.h"
#include "snapshot/snapshot.h"

namespace cb {

// The page's panels: the plots (phi_1, phi_N/2, phi_N with the exact lines; the energy) and
// the space-time picture; the HUD and the breaks are HTML beside the canvas.
OverlaySwitches web_plot_switches();

// A layer drawing `data` into the panels of `layout`, in the theme's colours.
Layer web_plot_layer(const OverlayData& data, const OverlayLayout& layout, ThemeName theme);

}  // namespace cb
