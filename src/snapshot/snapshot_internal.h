// Shared between the snapshot builder's files: the frame being filled, the theme, and the
// text metrics used to place labels. Not part of the library's interface.
#pragma once

#include <string>
#include <vector>

#include "snapshot/snapshot.h"

namespace cb::snapshot_detail {

// The theme: a dark background, because the strain scale is brightest where it matters
// most (tension about to break) and would vanish on white; the dark compression end keeps
// its saturated blue against near-black.
inline constexpr Color kBackground{0.09f, 0.094f, 0.11f, 1.0f};
inline constexpr Color kText{0.88f, 0.88f, 0.90f, 1.0f};
inline constexpr Color kDimText{0.62f, 0.63f, 0.66f, 1.0f};
inline constexpr Color kWall{0.30f, 0.30f, 0.32f, 1.0f};
inline constexpr Color kHatch{0.55f, 0.55f, 0.58f, 1.0f};
inline constexpr Color kWallFace{0.75f, 0.75f, 0.78f, 1.0f};
inline constexpr Color kBead{0.82f, 0.83f, 0.86f, 1.0f};
inline constexpr Color kBrokenHalf{0.50f, 0.50f, 0.50f, 1.0f};  // neutral: carries no strain
inline constexpr Color kRestLine{0.22f, 0.23f, 0.26f, 1.0f};
inline constexpr Color kForce{0.92f, 0.92f, 0.95f, 1.0f};
inline constexpr Color kMarker{1.00f, 0.78f, 0.35f, 1.0f};
inline constexpr Color kFlash{1.00f, 0.94f, 0.78f, 1.0f};  // alpha set per frame

// Timing of the break animation, in tau units.
inline constexpr double kRecoilTime = 2.0;  // halves shorten from 50% to 30% of the gap
inline constexpr double kFlashTime = 1.5;   // the flash fades out

struct Point {
  double x = 0, y = 0;
};

// Everything a panel drawer needs, filled by build_snapshot.
struct Frame {
  const ChainState& state;
  const ChainParams& params;
  const SnapshotStyle& style;
  const SnapshotLayout& layout;
  double force = 0.0;
  double strain_scale = 1.0;  // |phi| at the ends of the colour scale
  bool string_intact = true;  // the pull string still holds (or there is none)
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
