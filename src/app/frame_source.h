// The physics side of a video's frames: steps the chain to frame k (k x substeps steps of the
// plan's dt) and builds its snapshot, with the overlay's data when the plan has an overlay.
// `render` pulls every frame from one on its producer thread; `snapshot --overlay` pulls the
// frames it was asked for, so each of its PNGs is exactly the video's frame at that tau.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include "app/render_plan.h"
#include "app/zoom.h"
#include "overlay/overlay_history.h"
#include "physics/integrator.h"
#include "snapshot/snapshot.h"

namespace cb {

class FrameSource {
 public:
  FrameSource(const SceneDesc& scene, const RenderPlan& plan, int threads);
  // Frame k, for k increasing from call to call (every frame in between is still stepped
  // through and recorded: the overlay's histories need them all). Null after a non-finite
  // state; error() says why.
  std::optional<RenderSnapshot> frame(std::int64_t k);
  const std::string& error() const { return sim_.error(); }
  const ChainState& state() const { return sim_.state(); }

 private:
  bool record_through(std::int64_t k);
  const ChainParams& chain_;
  const RenderPlan& plan_;
  Integrator sim_;
  std::unique_ptr<OverlayHistory> history_;  // null: no overlay
  std::int64_t next_ = 0;                    // the next frame the history records
  ZoomCamera camera_;                        // moved once per recorded frame
  int zoom_first_ = 0, zoom_last_ = 0;       // the camera's stretch at the latest frame
};

}  // namespace cb
