// FrameTimes: where each displayed frame's time went, for --benchmark-frames. Phases: the
// physics (grid frames and the overlay's histories), drawing the frame (snapshot, renderer,
// overlay, finished with glFinish in benchmark runs so the software rasteriser's work lands
// here and not in the next phase), and presenting it (the copy into the window, the
// controls, the buffer swap).
#pragma once

#include <string>
#include <vector>

namespace cb {

struct FrameTimes {
  std::vector<double> physics, draw, present, total;  // seconds, one entry per frame

  // One JSON line: the medians in milliseconds, skipping the first `warmup` frames (shader
  // compilation, the font atlas).
  std::string report(std::size_t warmup) const;
};

}  // namespace cb
