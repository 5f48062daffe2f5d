// The overlay's plots in the page, drawn by the program's renderer: the overlay (src/overlay)
// draws them with Dear ImGui, which has no WebAssembly build here (PLATFORM-NOTES.md), so the
// page turns the same OverlayData, laid out by the same overlay_layout() and mapped by the same
// PlotMapping, into one more snapshot layer of lines, rectangles and labels.
#pragma once

#include "overlay/overlay_data.h"
#include "overlay/overlay_layout.h"
#include "snapshot/snapshot.h"

namespace cb {

// Which spring breaks first against zeta_c = phi_c / beta for a ramp (the paper's Fig. 4 map
// for one N and gamma), by the exact solution (figures/break_maps.h, ramp_first_break), and
// where the scene's own setting lies.
struct WebBreakMap {
  std::vector<double> zeta;
  std::vector<int> spring;  // first-breaking spring at each zeta (-1: none)
  double current = -1.0;    // the scene's zeta_c
  int beads = 0;
};

// The page's panels: the plots (phi_1, phi_N/2, phi_N with the exact lines; the energy), the
// space-time picture, and the breaking map in the place of the overlay's mode bars; the HUD
// and the breaks are HTML beside the canvas.
OverlaySwitches web_plot_switches();

// A layer drawing `data` (and `map`, when it has points) into the panels of `layout`.
Layer web_plot_layer(const OverlayData& data, const WebBreakMap& map, const OverlayLayout& layout,
                     ThemeName theme);

}  // namespace cb
