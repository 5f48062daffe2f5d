// Zoom: which stretch of springs a frame draws across its panel (`--zoom`, [render] zoom).
//   "J0:J1"        springs J0..J1, fixed;
//   "auto[:W]"     W springs (default 60) following the most strained spring, smoothly;
//   "break[:W]"    as auto, then centred on the first break's spring once it is near.
// Parsed here, beside the scene, so validate() checks [render] zoom against the chain like every
// other key; the camera that follows it is the app's (app/zoom.h).
#pragma once

#include <string>

namespace cb {

struct ZoomSpec {
  enum class Mode { Off, Fixed, Auto, Break } mode = Mode::Off;
  int first = 0, last = 0;  // Fixed: springs first..last
  int width = 60;           // Auto, Break: springs in view
};

// Throws SceneError naming the forms above when `text` is none of them or out of 1..N.
ZoomSpec parse_zoom(const std::string& text, int beads, const std::string& where);

}  // namespace cb
