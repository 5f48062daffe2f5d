#include "app/frame_grid.h"

#include <algorithm>
#include <cmath>

#include "app/csv.h"
#include "resources/resources.h"
#include "scene/scene.h"

namespace cb {

namespace {

double smoothstep(double t) {
  t = std::clamp(t, 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}

}  // namespace

FrameGrid::FrameGrid(double tau_per_frame, double scene_dt, const SlowMotion& slow)
    : tau_per_frame_(tau_per_frame), slow_(slow) {
  // The fewest steps per frame that keep dt <= the scene's, times the least multiplier that
  // makes a slow frame (F x substeps) whole.
  const auto base = std::max<std::int64_t>(
      1, static_cast<std::int64_t>(std::ceil(tau_per_frame / scene_dt - 1e-9)));
  substeps_ = base;
  if (slow.on()) {
    bool found = false;
    for (std::int64_t m = 1; m <= 1000 && !found; ++m) {
      const double slow_steps = slow.factor * static_cast<double>(base * m);
      if (slow_steps >= 1.0 - 1e-9 && std::abs(slow_steps - std::round(slow_steps)) < 1e-9 * slow_steps) {
        substeps_ = base * m;
        found = true;
      }
    }
    if (!found)
      throw SceneError("--slowmo " + number_text(slow.factor) +
                       ": slow motion needs a simple fraction of normal speed, such as 0.1, "
                       "0.25 or 0.2 (a frame must be a whole number of integrator steps)");
  }
  dt_ = tau_per_frame / static_cast<double>(substeps_);
}

void FrameGrid::lay_out(double tau_stop, const std::vector<double>& breaks) {
  steps_.clear();
  const auto last = static_cast<std::int64_t>(std::floor(tau_stop / dt_ + 1e-9));
  const auto slow_steps = static_cast<std::int64_t>(std::llround(slow_.factor * substeps_));
  const double ease = 0.5 * slow_.window;
  std::int64_t s = 0;
  while (s <= last) {
    // The planner's budget counted the normal pace; slow windows add frames only the breaks
    // decide, so the real count is checked here, before a frame is drawn (issue #12).
    if (static_cast<double>(steps_.size()) >= kMaxFrames)
      throw SceneError(
          "render: slow motion ×" + number_text(slow_.factor) + " within " +
          number_text(slow_.window) + " tau of " + std::to_string(breaks.size()) +
          " break(s) makes more than the limit of " +
          std::to_string(static_cast<std::int64_t>(kMaxFrames)) +
          " frames (stopped counting at tau " + number_text(static_cast<double>(s) * dt_) +
          " of " + number_text(tau_stop) +
          "); raise --slowmo (e.g. 0.1), narrow --slowmo-window, or raise --speed");
    steps_.push_back(s);
    std::int64_t h = substeps_;
    if (slow_.on()) {
      // The slowest pace any break asks for at this tau: F inside a window, eased to 1 over
      // `ease` outside it.
      const double tau = static_cast<double>(s) * dt_;
      double speed = 1.0;
      for (double b : breaks) {
        const double d = std::abs(tau - b) - slow_.window;  // <= 0 inside the window
        const double w = d <= 0.0 ? 0.0 : smoothstep(d / ease);
        speed = std::min(speed, slow_.factor + (1.0 - slow_.factor) * w);
      }
      h = std::clamp(static_cast<std::int64_t>(std::llround(speed * substeps_)), slow_steps,
                     substeps_);
    }
    s += h;
  }
}

std::int64_t FrameGrid::step(std::int64_t k) const {
  if (k < frames()) return steps_[static_cast<std::size_t>(k)];
  const std::int64_t last = steps_.empty() ? 0 : steps_.back();
  const std::int64_t past = k - frames() + (steps_.empty() ? 0 : 1);
  return last + past * substeps_;
}

std::int64_t FrameGrid::first_frame_at_or_after(double tau) const {
  const auto it = std::lower_bound(steps_.begin(), steps_.end(), tau, [&](std::int64_t s, double t) {
    return static_cast<double>(s) * dt_ < t - 1e-9 * std::max(1.0, std::abs(t));
  });
  return static_cast<std::int64_t>(it - steps_.begin());
}

std::int64_t FrameGrid::frame_at(double tau, double slack) const {
  const std::int64_t k = first_frame_at_or_after(tau - slack);
  if (k < frames() && std::abs(this->tau(k) - tau) <= slack) return k;
  return -1;
}

double FrameGrid::speed(std::int64_t k) const {
  const std::int64_t next = step(k + 1), here = step(k);
  return static_cast<double>(next - here) / static_cast<double>(substeps_);
}

std::vector<double> FrameGrid::taus() const {
  std::vector<double> out;
  out.reserve(steps_.size());
  for (std::int64_t s : steps_) out.push_back(static_cast<double>(s) * dt_);
  return out;
}

}  // namespace cb
