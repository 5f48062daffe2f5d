#include "viewer/pacer.h"

#include <algorithm>
#include <cmath>

namespace cb {

void Pacer::reset(double now, std::int64_t frame, double tau_per_second, double tau_per_frame) {
  start_time_ = last_time_ = now;
  start_frame_ = last_frame_ = frame;
  frames_per_second_ = tau_per_frame > 0 ? tau_per_second / tau_per_frame : 0.0;
  ratio_ = 1.0;
}

std::int64_t Pacer::due(double now) const {
  const double frames = std::floor((now - start_time_) * frames_per_second_ + 1e-9);
  return start_frame_ + std::max<std::int64_t>(0, static_cast<std::int64_t>(frames));
}

void Pacer::reached(double now, std::int64_t frame, bool cut_short) {
  const double elapsed = now - last_time_;
  if (elapsed > 0 && frames_per_second_ > 0) {
    const double ratio = static_cast<double>(frame - last_frame_) / (elapsed * frames_per_second_);
    // An exponential average over about one second of displayed frames.
    const double weight = std::min(1.0, elapsed);
    ratio_ = std::min(1.0, (1.0 - weight) * ratio_ + weight * ratio);
  }
  last_time_ = now;
  last_frame_ = frame;
  if (cut_short) {
    // Drop the backlog: the next frames are due from here, at the requested speed.
    start_time_ = now;
    start_frame_ = frame;
  } else if (frame >= due(now)) {
    ratio_ = std::max(ratio_, 0.999);  // on time: whatever the average says
  }
}

}  // namespace cb
