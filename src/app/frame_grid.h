// FrameGrid: the one frame clock. Frame k of a video is the chain at integrator step step(k),
// tau = step(k) x dt, exactly on the integrator's grid. Built once from the scene, the flags
// and the breaks the pre-pass found; `render`, `snapshot --overlay`, the viewer and the
// sidecar's "frame_tau" all read it, so a rule such as slow motion is written here alone.
//
// Design note: a uniform video takes `substeps` steps a frame (speed / fps of tau). Slow
// motion by F takes F x substeps steps a frame within +-window of every break, so substeps is
// chosen to make F x substeps whole (the step only ever shrinks, as for uneven frame rates:
// accuracy can only improve). Between normal and slow speed the step per frame eases
// (smoothstep) over half a window on either side, outside the window, so the window itself
// runs at exactly F.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace cb {

struct SlowMotion {
  double factor = 1.0;  // F in (0, 1); 1: off
  double window = 2.0;  // W: slow within +-W tau of every break
  bool on() const { return factor < 1.0; }
};

class FrameGrid {
 public:
  FrameGrid() = default;
  // tau_per_frame = speed / fps; scene_dt the scene's integrator step (never exceeded).
  // Throws SceneError when F x substeps cannot be made a whole number of steps.
  FrameGrid(double tau_per_frame, double scene_dt, const SlowMotion& slow);

  std::int64_t substeps() const { return substeps_; }  // steps of a normal frame
  double dt() const { return dt_; }
  double tau_per_frame() const { return tau_per_frame_; }
  const SlowMotion& slow_motion() const { return slow_; }

  // Lays the frames out from tau = 0 through tau_stop, slowing around `breaks` (their tau).
  // Throws SceneError past kMaxFrames (resources.h), with the count's cause and the fix.
  void lay_out(double tau_stop, const std::vector<double>& breaks);
  std::int64_t frames() const { return static_cast<std::int64_t>(steps_.size()); }
  // Frame k's integrator step; past the laid-out frames it goes on at the normal pace (the
  // viewer plays past the end of a video).
  std::int64_t step(std::int64_t k) const;
  double tau(std::int64_t k) const { return static_cast<double>(step(k)) * dt_; }
  // The first frame whose tau is >= `tau` (frames() when none is).
  std::int64_t first_frame_at_or_after(double tau) const;
  // The frame showing exactly `tau` (within `slack` of a frame's tau), or -1.
  std::int64_t frame_at(double tau, double slack) const;
  // Frame k's speed relative to normal (1 outside slow motion, F inside its windows).
  double speed(std::int64_t k) const;
  // The frames' tau, for the sidecar.
  std::vector<double> taus() const;

 private:
  double tau_per_frame_ = 1.0, dt_ = 1.0;
  std::int64_t substeps_ = 1;
  SlowMotion slow_;
  std::vector<std::int64_t> steps_;
};

}  // namespace cb
