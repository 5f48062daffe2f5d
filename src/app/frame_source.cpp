#include "app/frame_source.h"

#include "physics/run_loop.h"

namespace cb {

FrameSource::FrameSource(const SceneDesc& scene, const RenderPlan& plan, int threads)
    : chain_(scene.chain),
      plan_(plan),
      sim_(scene.chain, make_forcing(scene.drive), {plan.grid.dt(), threads}),
      camera_(parse_zoom(plan.frame.zoom, scene.chain.beads, "--zoom"), scene.chain.beads,
              plan.extent.breaks.empty() ? 0 : plan.extent.breaks.front().spring,
              plan.extent.breaks.empty() ? -1.0 : plan.extent.breaks.front().tau) {
  if (plan.overlay_layout.enabled)
    history_ = std::make_unique<OverlayHistory>(scene.chain, scene.drive, plan.overlay_setup);
}

bool FrameSource::record_through(std::int64_t k) {
  for (; next_ <= k; ++next_) {
    if (!advance_watching(sim_, plan_.grid.step(next_))) return false;
    if (history_) history_->record(next_, sim_.state(), sim_.force_now());
    camera_.frame(sim_.state(), zoom_first_, zoom_last_);  // every frame: the camera is smooth
  }
  return true;
}

std::optional<RenderSnapshot> FrameSource::frame(std::int64_t k) {
  if (!record_through(k)) return std::nullopt;
  SnapshotStyle style = plan_.style;
  if (zoom_first_ > 0) {
    style.zoom_first = zoom_first_;
    style.zoom_last = zoom_last_;
  }
  RenderSnapshot snap = build_snapshot(sim_.state(), chain_, sim_.force_now(), style);
  // Slow motion shows as a tag while it lasts (this frame's pace is below normal).
  if (const double speed = plan_.grid.speed(k); speed < 1.0 - 1e-9)
    add_slow_motion_tag(snap, speed, plan_.style.theme);
  if (history_) snap.overlay = history_->share();
  return snap;
}

}  // namespace cb
