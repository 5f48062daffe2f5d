// Everything `render` decides before drawing a frame: size, frame times, the integrator step
// that lands on them, the layout, where the output goes; and the JSON that describes it.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "app/commands.h"
#include "app/frame_grid.h"
#include "app/frames.h"
#include "overlay/overlay_history.h"
#include "overlay/overlay_layout.h"

namespace cb {

struct RenderPlan {
  RenderDesc frame;  // size, fps, speed, view after options
  // The frame clock: frame k shows the chain at the integrator's step grid.step(k), with the
  // step dt = grid.dt() (never above the scene's). Laid out by measure_plan.
  FrameGrid grid;
  std::int64_t title_frames = 0;  // title card frames before the grid's first (--title-card)
  RunExtent extent;               // what keeps the chain in the frame; where the run stops
  SnapshotStyle style;
  // The overlay: the parts asked for (scene [render], then --overlay / --no-overlay), where
  // they go (disabled when none is on or the frame is under 640x360) and what the physics
  // side needs to fill them.
  OverlaySwitches overlay;
  OverlayLayout overlay_layout;
  OverlaySetup overlay_setup;
  std::string output;      // the video path, or the PNG folder
  std::string codec;       // "h264", "vp9", "gif" or "png"
  std::string scene_hash;  // of the scene file and the overrides
};

// Validates the options against the scene: size, frame times, output and codec. Cheap, so
// that mistakes surface before any work. Throws SceneError for a user mistake.
RenderPlan plan_render(const SceneDesc& scene, const RenderOptions& options);
// Measures the run (the physics pre-pass): where it stops, the frame count, the layout.
void measure_plan(const SceneDesc& scene, RenderPlan& plan);
// The measured plan's frame laid out at width x height: the overlay's panels and the chain's
// style, as measure_plan lays out the plan's own size. The viewer gives it the part of its
// window the docked panels leave free, so the picture there is `render`'s at that size.
void lay_out_frame(const SceneDesc& scene, RenderPlan& plan, int width, int height);

// The JSON sidecar: scene, parameters after overrides, frames, timing, codec, GL, breaks.
std::string plan_json(const SceneDesc& scene, const RenderPlan& plan, const std::string& gl,
                      const std::vector<BreakEvent>& breaks);
// The breaks as the sidecar lists them: spring, tau and the first video frame that shows it.
std::string breaks_json(const RenderPlan& plan, const std::vector<BreakEvent>& breaks);
// The sidecar's path for a plan: "<video stem>.json" or "<folder>/<scene>.json".
std::string sidecar_path(const SceneDesc& scene, const RenderPlan& plan);

}  // namespace cb
