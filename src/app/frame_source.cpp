#include "app/frame_source.h"

namespace cb {

FrameSource::FrameSource(const SceneDesc& scene, const RenderPlan& plan, int threads)
    : chain_(scene.chain),
      plan_(plan),
      sim_(scene.chain, make_forcing(scene.drive), {plan.dt, threads}) {
  if (plan.overlay_layout.enabled)
    history_ = std::make_unique<OverlayHistory>(scene.chain, scene.drive, plan.overlay_setup);
}

bool FrameSource::record_through(std::int64_t k) {
  for (; next_ <= k; ++next_) {
    if (!advance_watching(sim_, next_ * plan_.substeps)) return false;
    if (history_) history_->record(next_, sim_.state(), sim_.force_now());
  }
  return true;
}

std::optional<RenderSnapshot> FrameSource::frame(std::int64_t k) {
  if (!record_through(k)) return std::nullopt;
  RenderSnapshot snap = build_snapshot(sim_.state(), chain_, sim_.force_now(), plan_.style);
  if (history_) snap.overlay = history_->share();
  return snap;
}

}  // namespace cb
