#include "app/zoom.h"

#include <algorithm>
#include <cmath>

#include "physics/energy.h"
#include "scene/scene.h"

namespace cb {

ZoomCamera::ZoomCamera(const ZoomSpec& spec, int beads, int break_spring, double break_tau)
    : spec_(spec),
      beads_(beads),
      break_spring_(break_spring),
      break_tau_(break_tau),
      centre_(beads - 0.5 * spec.width + 0.5) {}

void ZoomCamera::frame(const ChainState& state, int& first, int& last, bool settle) {
  if (spec_.mode == ZoomSpec::Mode::Off) {
    first = last = 0;
    return;
  }
  if (spec_.mode == ZoomSpec::Mode::Fixed) {
    first = spec_.first;
    last = spec_.last;
    return;
  }
  // Target: the breaking spring once its break is near (break mode), else the most strained
  // intact spring (ties: the one nearest the pulled end; at rest the camera stays put).
  double target = centre_;
  if (spec_.mode == ZoomSpec::Mode::Break && break_spring_ > 0 &&
      state.tau >= break_tau_ - kBreakLead) {
    target = break_spring_;
  } else {
    double best = 0.0;
    for (int j = 1; j <= beads_; ++j) {
      if (!spring_intact(state, j)) continue;
      const double a = std::abs(extension(state, j));
      if (a > best) {
        best = a;
        target = j;
      }
    }
  }
  // Ease a quarter of the way a frame, at most a tenth of the width: smooth, never a jump.
  const double limit = 0.1 * spec_.width;
  centre_ = settle ? target : centre_ + std::clamp(0.25 * (target - centre_), -limit, limit);
  const double half = 0.5 * spec_.width;
  const double lo = std::clamp(centre_ - half, 0.0, static_cast<double>(beads_ - spec_.width));
  first = static_cast<int>(std::lround(lo)) + 1;
  last = first + spec_.width - 1;
}

}  // namespace cb
