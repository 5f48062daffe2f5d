// The viewer's Dear ImGui panels: the control panel (run, speed, chain, drive, view, outputs,
// status), the help panel (shortcuts), and the keyboard shortcuts themselves. They edit a
// draft of the scene; the loop applies it (restarting the run) when an edit is finished,
// so dragging a slider does not restart the run on every pixel.
#pragma once

#include <imgui.h>

#include "scene/scene.h"
#include "viewer/dock_layout.h"
#include "viewer/viewer_model.h"

namespace cb {

class Session;

// One line per shortcut: (keys, what they do). The help panel and README list these.
struct Shortcut {
  const char* keys;
  const char* action;
};
inline constexpr Shortcut kShortcuts[] = {
    {"Space", "play / pause"},
    {"S or Right", "one frame forward (paused)"},
    {"R", "restart from tau = 0"},
    {"+ / -", "speed x2 / x0.5"},
    {"V", "cycle the view: longitudinal, transverse, both"},
    {"P", "snapshot: the frame as a PNG"},
    {"M", "record: start / stop a video (MP4)"},
    {"Ctrl+S", "save the settings as a scene file"},
    {"Click a spring", "pin its phi(tau) plot (click empty space to unpin)"},
    {"Tab", "hide / show the panels (the picture takes the window)"},
    {"F11 or F", "presentation mode: fullscreen, no panels (again or Esc: back)"},
    {"H or F1", "this help"},
    {"Esc or Q", "quit (Esc in presentation mode: leave it)"},
};

// A docked panel: placed and sized by the dock layout every frame, never moved or resized
// by hand (dock_layout.h).
inline constexpr int kDockedWindow = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                                     ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings;
// The next window at `rect` (framebuffer pixels); false, and nothing to draw, when empty.
bool dock_next_window(const PixelRect& rect);

// The control panel in its docked rectangle (nothing when empty: the panels are hidden).
void draw_controls(ViewerModel& model, SceneDesc& draft, const Session& session,
                   ViewerRequests& requests, const PixelRect& rect);
// The help panel, when asked for: in the middle of the picture.
void draw_help(ViewerModel& model, const PixelRect& picture);
// Shortcuts pressed this frame (ignored while a text field has the keyboard).
void handle_shortcuts(ViewerModel& model, SceneDesc& draft, ViewerRequests& requests);

// "longitudinal" -> "transverse" -> "both" -> "longitudinal".
const char* next_view(const std::string& view);

}  // namespace cb
