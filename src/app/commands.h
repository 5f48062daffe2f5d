// The command-line commands. Each returns the process exit status:
// 0 success, 1 a run that failed (non-finite state, write error), 2 a user error in the
// scene or the options, 130 interrupted (SIGINT/SIGTERM).
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "app/frames.h"
#include "scene/scene.h"

namespace cb {

extern std::atomic<bool> g_interrupted;  // set by the signal handler; long loops poll it

struct RunOptions {
  std::string scene;
  std::vector<Override> overrides;
  std::string solver = "rk4";  // rk4 | exact | continuum
  std::string csv;             // empty: no CSV
  int every = 1;
  bool psi = false;
  bool quiet = false;
  int threads = 1;
};
int run_command(const RunOptions& options);

struct SweepOptions {
  std::string scene;
  std::vector<Override> overrides;
  std::string vary;            // KEY=LO:HI:COUNT[:log]
  std::string solver = "rk4";  // rk4 | exact
  int jobs = 0;                // 0: all cores
  std::string shard = "1/1";   // I/S, I in 1..S
  std::string csv;
  bool quiet = false;
};
int sweep_command(const SweepOptions& options);

struct SnapshotOptions {
  std::string scene;
  std::vector<Override> overrides;
  std::string at;  // "T1,T2,..."
  std::string out_dir = "renders";
  FrameOptions frame;
  // Overlay parts ("hud,plots", "all"); empty: the chain alone. With an overlay each PNG is
  // the `render` video's frame at that tau (same plan, same pixels), so tau must be a frame
  // time, k x speed / fps.
  std::string overlay;  // frame times follow the scene's [render] fps and speed (or --set)
};
int snapshot_command(const SnapshotOptions& options);

struct RenderOptions {
  std::string scene;
  std::vector<Override> overrides;
  std::string output;      // video file; empty: renders/<scene>.mp4
  std::string frames_dir;  // PNG sequence here instead of a video
  int crf = -1;            // x264 CRF; -1: the encoder's default
  std::string preset;      // x264 preset; empty: the encoder's default
  bool dry_run = false;
  double fps = 0;    // 0: from the scene or -q
  double speed = 0;  // tau per second of video; 0: from the scene
  int threads = 1;
  bool quiet = false;
  FrameOptions frame;
  bool no_overlay = false;  // --no-overlay
  std::string overlay;      // --overlay hud,plots,spacetime,modes; empty: the scene's [render]
  // Called on the drawing thread after each frame (the Python module's progress callback).
  std::function<void(std::int64_t done, std::int64_t total)> on_frame;
};
int render_command(const RenderOptions& options);
// The same for a scene already read (render_command loads options.scene and calls this).
int render_scene(const SceneDesc& scene, const RenderOptions& options);

struct FiguresOptions {
  std::string out_dir = "renders/figures";
  std::string only;  // comma-separated figure names; empty: all
  int jobs = 0;      // threads for the RK4 maps; 0: all cores
  bool quiet = false;
  FrameOptions frame;  // only .gl is used: the figures have a fixed size
};
int figures_command(const FiguresOptions& options);

// `view`: everything after the word goes to the viewer executable (src/viewer), which parses
// it. Exit status 1 when there is no display (kNoDisplayMessage) or the viewer is missing.
struct ViewOptions {
  std::vector<std::string> args;
};
int view_command(const ViewOptions& options);
inline constexpr const char* kNoDisplayMessage =
    "chainbreak view: no display (neither DISPLAY nor WAYLAND_DISPLAY is set, or the display "
    "cannot be opened). The viewer needs a window. Without a display, use `chainbreak render "
    "SCENE` for a video or `chainbreak snapshot SCENE --at TAU` for PNGs; or run the viewer "
    "under a virtual display: xvfb-run -a chainbreak view SCENE\n";

}  // namespace cb
