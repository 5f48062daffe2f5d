// Zoom: which stretch of springs a frame draws across its panel (`--zoom`, [render] zoom).
//   "J0:J1"        springs J0..J1, fixed;
//   "auto[:W]"     W springs (default 60) following the most strained spring, smoothly;
//   "break[:W]"    as auto, then centred on the first break's spring once it is near.
// The camera moves at most a tenth of its width per frame and eases towards its target, so it
// never jumps between frames; it starts at the pulled end, where every run starts.
#pragma once

#include <string>

#include "physics/chain.h"

namespace cb {

struct ZoomSpec {
  enum class Mode { Off, Fixed, Auto, Break } mode = Mode::Off;
  int first = 0, last = 0;  // Fixed: springs first..last
  int width = 60;           // Auto, Break: springs in view
};

// Throws SceneError naming the forms above when `text` is none of them or out of 1..N.
ZoomSpec parse_zoom(const std::string& text, int beads, const std::string& where);

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
