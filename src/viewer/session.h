// Session: the viewer's run of the physics, and nothing of GL or windows. It owns the scene as
// the user has edited it, the render plan `render` would make for it (frame size, the frame
// grid, the layout, the overlay's axes), the integrator and the overlay's histories.
//
// Design note: time advances on the video's frame grid (frame k at tau = k * tau_per_frame,
// reached in whole integrator steps, exactly as `render` does), so a frame shown in the
// window is the frame `render` and `snapshot` would draw at that tau. How many grid frames
// pass per displayed frame is the pacer's business (pacer.h), not the session's.
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "app/commands.h"
#include "app/render_plan.h"
#include "overlay/overlay_history.h"
#include "physics/integrator.h"
#include "viewer/phi_history.h"

namespace cb {

class Session {
 public:
  // `options` carries what `render` would take from the command line: --size, -q, --view,
  // --overlay. Runs the physics pre-pass (measure_plan); throws SceneError for bad settings.
  Session(SceneDesc scene, RenderOptions options);
  ~Session();

  // Starts again from tau = 0 with the scene as edited (re-plans: the pre-pass runs again).
  // Throws (SceneError, DriveError, std::runtime_error) with the run left as it was; the
  // caller then puts the scene back (scene() = what it was).
  void restart();
  // Only the view changed: new layout, same run.
  void set_view(const std::string& view);

  SceneDesc& scene() { return scene_; }  // edit, then restart()
  const SceneDesc& scene() const { return scene_; }
  const RenderPlan& plan() const { return plan_; }
  const ChainState& state() const { return sim_->state(); }
  double tau() const { return plan_.grid.tau(frame_); }
  std::int64_t frame() const { return frame_; }
  bool at_end() const { return frame_ >= plan_.grid.frames() - 1; }
  // The physics stopped being finite: the message, and the run stays where it was.
  const std::string& error() const { return error_; }

  // Advances up to `count` grid frames (fewer at the end of the run or on an error).
  void advance(std::int64_t count);
  // The plan laid out for a frame of width x height (the window's picture beside its panels):
  // `render`'s layout at that size (lay_out_frame), for the same run.
  RenderPlan plan_at(int width, int height) const;
  // The current frame as `render` would draw it, with the overlay's data when it is on; in
  // the plan's style, or in another one (plan_at(...).style).
  RenderSnapshot snapshot() const;
  RenderSnapshot snapshot(const SnapshotStyle& style) const;
  // phi_j(tau) of every spring so far (the hover plot).
  const PhiHistory& phi_history() const { return phi_history_; }

 private:
  void record();

  SceneDesc scene_;
  RenderOptions options_;
  RenderPlan plan_;
  std::unique_ptr<Integrator> sim_;
  std::unique_ptr<OverlayHistory> history_;
  PhiHistory phi_history_;
  std::int64_t frame_ = 0;
  std::string error_;
};

}  // namespace cb
