// Everything `render` decides before drawing a frame: size, frame times, the integrator step
// that lands on them, the layout, where the output goes; and the JSON that describes it.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "app/commands.h"
#include "app/frames.h"
#include "overlay/overlay_history.h"
#include "overlay/overlay_layout.h"

namespace cb {

struct RenderPlan {
  RenderDesc frame;            // size, fps, speed, view after options
  double tau_per_frame = 0.0;  // speed / fps
  std::int64_t substeps = 1;   // integrator steps per frame
  double dt = 0.0;             // tau_per_frame / substeps (never above the scene's dt)
  std::int64_t frames = 0;     // frame k shows tau = k * tau_per_frame
  RunExtent extent;            // what keeps the chain in the frame; where the run stops
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

// The JSON sidecar: scene, parameters after overrides, frames, timing, codec, GL, breaks.
std::string plan_json(const SceneDesc& scene, const RenderPlan& plan, const std::string& gl,
                      const std::vector<BreakEvent>& breaks);
// Where the JSON sidecar of the plan's output goes (out.mp4 -> out.json; a PNG folder ->
// FOLDER/<scene>.json). Also the name `render` locks (output/output_lock.h).
std::string sidecar_path(const SceneDesc& scene, const RenderPlan& plan);
// Writes plan_json there.
void write_sidecar(const SceneDesc& scene, const RenderPlan& plan, const std::string& gl,
                   const std::vector<BreakEvent>& breaks);

}  // namespace cb
