// Scripted input for the viewer (--script FILE): timed actions instead of a person, so tests
// and demos drive the window deterministically. In script mode the physics advances a fixed
// tau per displayed frame (not wall time), so a script gives the same frames on any machine.
//
// The format, one action per line ('#' starts a comment, blank lines are skipped):
//   FRAME ACTION [ARGUMENT]
// FRAME is the displayed frame (0, 1, 2, ...) before whose physics the action applies:
//   play | pause | step [K] | restart | quit
//   set KEY VALUE     KEY: speed, beads, gamma, threshold, beta, amplitude, period, t0, view
//   snapshot PATH     the frame (without the controls) as a PNG, after this frame's physics
//   screenshot PATH   the whole window, controls included, as a PNG
//   save PATH         the current settings as a scene file
//   record PATH       start writing the session to a video; `record stop` ends it
//   select SPRING     show spring SPRING's phi(tau) plot, as a click on it would
//   layout PATH       where this frame put everything, as JSON (window, picture, panels,
//                     the ImGui windows, the wall, beads, force arrow and marker): for tests
//   resize W H        the window's new size in pixels, as dragging its corner would
//   panels on|off     show or hide the docked controls and plot, as Tab does
//   present on|off    presentation mode (fullscreen, panels hidden), as F11 or F does
// Frames must not decrease. The viewer quits after the last action even without `quit`.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace cb {

// The window sizes `resize` accepts, pixels.
inline constexpr int kMinWindowSide = 64, kMaxWindowSide = 16384;

struct ScriptAction {
  std::int64_t frame = 0;
  std::string action;    // play, pause, step, ... (above)
  std::string key;       // set: the setting; resize: the width
  std::string argument;  // set: the value; snapshot/save/record/layout: the path; step/select:
                         // a number; resize: the height; panels/present: on or off
  int line = 0;          // in the file, for messages
};

// Parses the text; throws SceneError "FILE:LINE: what is wrong; e.g. ..." for a mistake.
std::vector<ScriptAction> parse_script(const std::string& text, const std::string& path);
std::vector<ScriptAction> load_script(const std::string& path);

// The actions of displayed frame `frame`, in file order, from a cursor that moves forward.
class ScriptPlayer {
 public:
  explicit ScriptPlayer(std::vector<ScriptAction> actions) : actions_(std::move(actions)) {}
  std::vector<ScriptAction> take(std::int64_t frame);
  bool finished() const { return next_ >= actions_.size(); }

 private:
  std::vector<ScriptAction> actions_;
  std::size_t next_ = 0;
};

}  // namespace cb
