// The zoom camera: which stretch of springs a frame draws across its panel, following the
// ZoomSpec (scene/zoom_spec.h: `--zoom`, [render] zoom). The camera moves at most a tenth of its
// width per frame and eases towards its target, so it never jumps between frames; it starts at the
// pulled end, where every run starts.
#pragma once

#include <string>

#include "physics/chain.h"
#include "scene/zoom_spec.h"

namespace cb {

class ZoomCamera {
 public:
  // break_spring / break_tau: the first break the pre-pass found (spring 0 or tau < 0: none).
  ZoomCamera(const ZoomSpec& spec, int beads, int break_spring, double break_tau);
  // The stretch to draw at this state (springs first..last), moving the camera one frame on.
  // With `settle` the camera goes straight to its target (a single snapshot has no past).
  void frame(const ChainState& state, int& first, int& last, bool settle = false);

 private:
  ZoomSpec spec_;
  int beads_;
  int break_spring_;
  double break_tau_;
  double centre_;
  // The lead time before the break at which `break` mode turns to the breaking spring.
  static constexpr double kBreakLead = 6.0;
};

}  // namespace cb
