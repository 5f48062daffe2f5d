// Shared between the snapshot builder's files: the frame being filled, the theme, and the
// text metrics used to place labels. Not part of the library's interface.
#pragma once

#include <string>
#include <vector>

#include "snapshot/snapshot.h"

namespace cb::snapshot_detail {

// The snapshot's colours, from the theme's roles (theme/theme.h): the same drawing code makes
// the dark (projector) and the light (paper) frame.
struct Palette {
  Color background, text, dim_text;
  Color wall, hatch, wall_face;  // the wall's fill, its hatching and its face
  Color bead, broken_half, rest_line, force, marker, flash;
  Color first_break, later_break;  // pointers and leaders: the theme's accent; muted marker
};
Palette palette(ThemeName theme);
Color to_color(Rgb8 c, float alpha = 1.0f);

// Timing of the break animation, in tau units.
inline constexpr double kRecoilTime = 2.0;  // halves shorten from 50% to 30% of the gap
inline constexpr double kFlashTime = 1.5;   // the flash fades out

// The largest bead area ratio and spring width ratio of a chain (bead_area_ratios,
// spring_width_ratios; 1 when they are empty): the layout sizes beads and springs by them.
struct SizeRange {
  double max_area = 1.0, max_width = 1.0;
};
SizeRange size_range(const std::vector<double>& area_ratios,
                     const std::vector<double>& width_ratios);
// snapshot_layout() with the ratios' range already known.
SnapshotLayout layout_for(const SnapshotStyle& style, const ChainParams& params,
                          const SizeRange& sizes);

struct Point {
  double x = 0, y = 0;
};

// Everything a panel drawer needs, filled by build_snapshot.
struct Frame {
  const ChainState& state;
  const ChainParams& params;
  const SnapshotStyle& style;
  const SnapshotLayout& layout;
  const Palette& pal;
  double force = 0.0;
  double strain_scale = 1.0;  // |phi| at the ends of the colour scale
  bool string_intact = true;  // the pull string still holds (or there is none)
  // Per bead and per spring (index j-1), empty for the uniform chain: area and width ratios
  // (chain_sizes.cpp) and the scale that maps phi_j to the colour map, phi_c,j.
  std::vector<double> bead_area;
  std::vector<double> spring_width;
  std::vector<double> spring_scale;
  // The scale of spring j's colour: phi_j / strain_scale_of(j) in [-1, 1].
  double strain_scale_of(int spring) const {
    return spring_scale.empty() ? strain_scale : spring_scale[spring - 1];
  }
  // (spring, tau) of every break in breaks_shown, sorted by spring, for the age lookup.
  std::vector<BreakEvent> breaks_by_spring;
  RenderSnapshot& out;

  Layer& layer(SnapshotLayer id) { return out.layers[id]; }
  // Time since spring `j` broke; +inf when the state has it broken without a recorded event.
  double break_age(int spring) const;
};


// Appends beads, springs (or the strain ribbon), broken halves, break flashes and markers and
// the force arrow of one panel.
void draw_chain_panel(Frame& frame, const PanelLayout& panel);

}  // namespace cb::snapshot_detail
