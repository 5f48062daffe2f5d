#include "viewer/pacer.h"

#include <algorithm>
#include <cmath>

namespace cb {

void Pacer::reset(double now, std::int64_t frame, double tau_per_second, double tau_per_frame) {
  start_time_ = last_time_ = now;
  start_frame_ = last_frame_ = last_due_ = frame;
  frames_per_second_ = tau_per_frame > 0 ? tau_per_second / tau_per_frame : 0.0;
  ratio_ = 1.0;
}

std::int64_t Pacer::due(double now) const {
  const double frames = std::floor((now - start_time_) * frames_per_second_ + 1e-9);
  return start_frame_ + std::max<std::int64_t>(0, static_cast<std::int64_t>(frames));
}

void Pacer::reached(double now, std::int64_t frame, bool cut_short) {
  // Achieved against due over this displayed frame, both in whole grid frames, so that a
  // display rate that is no multiple of the grid's does not look like falling behind.
  const std::int64_t due_now = due(now);
  const std::int64_t expected = due_now - last_due_;
  if (expected > 0) {
    const double sample =
        std::min(1.0, static_cast<double>(frame - last_frame_) / static_cast<double>(expected));
    const double weight = std::clamp(now - last_time_, 0.0, 1.0);  // about a second's average
    ratio_ = (1.0 - weight) * ratio_ + weight * sample;
  }
  if (!cut_short && frame >= due_now) ratio_ = std::max(ratio_, 0.999);  // on time
  if (cut_short) {
    // Drop the backlog: the next frames are due from here, at the requested speed.
    start_time_ = now;
    start_frame_ = frame;
  }
  last_time_ = now;
  last_frame_ = frame;
  last_due_ = due(now);
}

}  // namespace cb
