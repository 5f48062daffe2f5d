#include "scene/zoom_spec.h"

#include <algorithm>
#include <cstdio>

#include "scene/scene.h"

namespace cb {

ZoomSpec parse_zoom(const std::string& text, int beads, const std::string& where) {
  ZoomSpec z;
  if (text.empty() || text == "off" || text == "none") return z;
  const auto fail = [&](const std::string& why) {
    throw SceneError(where + " " + text + ": " + why +
                     "; expected J0:J1 (springs, 1 <= J0 < J1 <= N = " + std::to_string(beads) +
                     "), auto[:W] or break[:W] (W springs in view), e.g. --zoom 480:540");
  };
  int a = 0, b = 0;
  char tail = 0;
  const auto mode_with_width = [&](const char* name, ZoomSpec::Mode mode) {
    const std::string prefix = name;
    if (text.rfind(prefix, 0) != 0) return false;
    z.mode = mode;
    if (text.size() > prefix.size()) {
      if (std::sscanf(text.c_str() + prefix.size(), ":%d%c", &a, &tail) != 1 || a < 2)
        fail("the width must be a whole number of springs, at least 2");
      z.width = a;
    }
    z.width = std::min(z.width, beads);
    if (z.width < 2) fail("a chain of one spring cannot be zoomed");
    return true;
  };
  if (mode_with_width("auto", ZoomSpec::Mode::Auto) ||
      mode_with_width("break", ZoomSpec::Mode::Break))
    return z;
  if (std::sscanf(text.c_str(), "%d:%d%c", &a, &b, &tail) != 2) fail("not a zoom");
  if (a < 1 || b > beads || a >= b) fail("springs out of range");
  z.mode = ZoomSpec::Mode::Fixed;
  z.first = a;
  z.last = b;
  return z;
}

}  // namespace cb
