#include "viewer/spring_pick.h"

#include <algorithm>

namespace cb {

namespace {

// x of bead j (0: the wall) in the panel, as build_snapshot places it (snapshot.h).
float bead_x(const SnapshotLayout& layout, const PanelLayout& panel, const ChainState& state,
             int j) {
  const double psi = j > 0 && panel.view == View::Longitudinal ? state.psi[j - 1] : 0.0;
  return layout.x_wall + static_cast<float>((j + psi) * panel.spacing);
}

// y of bead j (0: the wall) in the panel, as build_snapshot places it.
float bead_y(const PanelLayout& panel, const ChainState& state, int j) {
  const double psi = j > 0 && panel.view == View::Transverse ? state.psi[j - 1] : 0.0;
  return panel.centre_y - static_cast<float>(psi * panel.psi_scale);
}

}  // namespace

int spring_at(const SnapshotLayout& layout, const ChainState& state, float x, float y) {
  const int beads = static_cast<int>(state.psi.size());
  for (int p = 0; p < layout.panel_count; ++p) {
    const PanelLayout& panel = layout.panels[p];
    if (panel.view == View::Vertical) continue;  // not pickable yet (issue #22)
    if (y < panel.top || y > panel.bottom) continue;
    for (int j = 1; j <= beads; ++j) {
      const SpringSpan span = spring_span(layout, state, p, j);
      if (x >= span.x0 && x <= span.x1) return j;
    }
  }
  return 0;
}

SpringSpan spring_span(const SnapshotLayout& layout, const ChainState& state, int panel,
                       int spring) {
  const PanelLayout& p = layout.panels[panel];
  const float a = bead_x(layout, p, state, spring - 1), b = bead_x(layout, p, state, spring);
  return {std::min(a, b), std::max(a, b), p.top, p.bottom};
}

SpringBox spring_marker(const SnapshotLayout& layout, const ChainState& state, int panel,
                        int spring, float pad) {
  const PanelLayout& p = layout.panels[panel];
  const float xa = bead_x(layout, p, state, spring - 1), xb = bead_x(layout, p, state, spring);
  const float ya = bead_y(p, state, spring - 1), yb = bead_y(p, state, spring);
  // A bead's disc, the coil's half width, or half the strain ribbon: whichever is larger.
  const float half = std::max({p.bead_radius, 0.5f * p.spring_width, 0.5f * p.ribbon_width});
  const float r = half + pad;
  return {std::min(xa, xb) - r, std::min(ya, yb) - r, std::max(xa, xb) + r, std::max(ya, yb) + r};
}

}  // namespace cb
