// Which spring is under a point of the frame: plain geometry on the snapshot's layout and
// the chain's state (no GL), for the viewer's hover and click.
#pragma once

#include "physics/chain.h"
#include "snapshot/snapshot.h"

namespace cb {

// Spring j (1..N) whose span between beads j-1 and j contains x, in the chain panel that
// contains y (frame pixels, origin top-left); 0 when the point is on no chain.
int spring_at(const SnapshotLayout& layout, const ChainState& state, float x, float y);

// Where spring j is drawn in panel p: between x0 and x1 (beads j-1 and j), over the panel's
// height; for the viewer's highlight of the picked spring.
struct SpringSpan {
  float x0 = 0, x1 = 0, top = 0, bottom = 0;
};
SpringSpan spring_span(const SnapshotLayout& layout, const ChainState& state, int panel,
                       int spring);

// The selected spring's marker in panel p: a box around spring j where it is drawn, both of
// its beads (discs of the panel's bead radius) and the coil between them, `pad` pixels
// beyond them, so that the outline sits on that spring and crosses none of its beads.
struct SpringBox {
  float x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // frame pixels, origin top-left
};
SpringBox spring_marker(const SnapshotLayout& layout, const ChainState& state, int panel,
                        int spring, float pad);

}  // namespace cb
