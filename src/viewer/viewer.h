// The real-time viewer (issue #6): a window with the renderer and overlay of the videos and,
// docked beside them, Dear ImGui controls (issue #27: never over the chain). Each displayed
// frame: read input (person or script), apply the requests, advance the physics by the pacer
// (or a fixed tau per frame in script and benchmark modes), lay out the window (dock_layout.h),
// draw `render`'s frame at the picture's size into the renderer's framebuffer, copy it 1:1
// into the window, draw the panels beside it.
#pragma once

#include <atomic>
#include <cstdint>
#include <string>
#include <vector>

#include "app/commands.h"

namespace cb {

struct ViewerOptions {
  std::string scene;
  std::vector<Override> overrides;
  RenderOptions render;  // --size, -q, --view, --overlay, --no-overlay, as `render` reads them
  double speed = 0;      // tau per second; 0: the scene's [render] speed
  std::string script;    // --script FILE (script.h)
  std::int64_t benchmark_frames = 0;  // > 0: play this many frames flat out, print timings
  std::string out_dir = "renders";
  bool play = false;      // start playing
  float ui_scale = 1.0f;  // --ui-scale: the panels' size, times the window's content scale
  // Set by a signal handler (Ctrl-C): the loop ends as if the window were closed, so a video
  // being recorded is finished, not left as a temporary file.
  const std::atomic<bool>* stop = nullptr;
};

// The exit status: 0 on quit, 1 when the physics failed in a script or benchmark run.
// Throws NoDisplayError (window.h) without a display, SceneError for bad settings.
int run_viewer(const ViewerOptions& options);

}  // namespace cb
