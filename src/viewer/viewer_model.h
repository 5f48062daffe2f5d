// What the viewer's controls show and change (ViewerModel), and the one-shot requests a
// frame collects from the controls, the keyboard and the script (ViewerRequests). Plain data:
// the loop (viewer.cpp) acts on the requests once per displayed frame.
#pragma once

#include <string>

namespace cb {

// The speed's range, for the slider, the + and - keys and scripts alike: below it the run's
// pre-pass (at a step shrunk to the frame time) takes seconds; above it a frame is the run.
inline constexpr double kMinSpeed = 0.1, kMaxSpeed = 1000.0;

struct ViewerModel {
  bool playing = false;
  double speed = 10.0;  // tau per second of wall time (script mode: per 1/fps of a frame)
  bool show_help = false;
  bool show_controls = true;  // the docked panels; Tab hides them: the chain alone, as on the video
  bool presenting = false;    // presentation mode: fullscreen, panels hidden (F11 or F)
  int hovered_spring = 0;     // under the mouse (0: none)
  int pinned_spring = 0;      // clicked, or `select` in a script; the plot shows it before hover
  bool recording = false;
  // Reported by the loop, shown by the controls.
  bool script = false;          // driven by --script: fixed tau per frame
  bool behind = false;          // the machine cannot keep up with `speed`
  double achieved_ratio = 1.0;  // achieved / requested speed
  double display_fps = 0.0;
  std::string status;  // the last thing written, or the last error
};

struct ViewerRequests {
  int step = 0;                 // grid frames to advance while paused
  bool restart = false;         // from tau = 0 with the current settings
  bool apply_settings = false;  // the draft scene replaces the session's (then restart)
  bool view_changed = false;    // the draft's view: new layout, same run
  bool speed_changed = false;   // re-base the pacer
  bool snapshot = false, save = false, record = false, quit = false;  // record: start or stop
  std::string snapshot_path, save_path, record_path;                  // empty: a name in --out-dir
  std::string screenshot_path;  // script only: the whole window
  std::string layout_path;      // script only: where everything went, as JSON (script.h)
  int resize_width = 0, resize_height = 0;  // script only: > 0, the window's new size
  int present = -1;                         // presentation mode: 1 enter, 0 leave, -1 no change
};

}  // namespace cb
