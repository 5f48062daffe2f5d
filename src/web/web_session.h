// The page's run of the physics, and nothing of the browser: the scene as the page was given it
// (its TOML text, its name, and the `--set` style overrides from the URL and the controls), the
// integrator stepping at the scene's own dt (so its breaks are `chainbreak run`'s, bit for
// bit), and the frame layout `chainbreak snapshot` would choose for the scene.
//
// Design note: every change of the scene (a key set, a file opened) re-reads the text through
// the program's scene reader with the overrides, exactly as `--set` does, so the page's error
// messages are the command line's. A failed change leaves everything as it was.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/frames.h"
#include "overlay/overlay_history.h"
#include "physics/integrator.h"
#include "scene/scene.h"
#include "snapshot/snapshot.h"
#include "web/web_plots.h"

namespace cb {

class WebSession {
 public:
  // Reads `text` as the scene file `path` (a shipped scene: "/scenes/NAME.toml", where a table
  // drive's CSV is found relative to it) with `overrides` (--set), and restarts. Throws
  // SceneError (or DriveError, std::runtime_error) with the reader's message; nothing changes
  // then.
  void load(const std::string& text, const std::string& path, std::vector<Override> overrides);
  // `--set key=value`: replaces an earlier setting of the same key, re-reads the scene and
  // restarts. Throws as load() does, leaving the run as it was.
  void set(const std::string& key, const std::string& value);
  // Starts again from tau = 0 (the layout's pre-pass runs again).
  void restart();

  bool loaded() const { return sim_ != nullptr; }
  const SceneDesc& scene() const { return scene_; }
  const std::string& text() const { return text_; }
  const std::vector<Override>& overrides() const { return overrides_; }
  const std::string& path() const { return path_; }
  // The first break the layout's pre-pass found, or -1 (none, or past its end).
  double first_break_tau() const {
    return extent_.breaks.empty() ? -1.0 : extent_.breaks.front().tau;
  }
  const Integrator& sim() const { return *sim_; }
  double tau() const { return sim_->state().tau; }
  // The last step the run goes to: integrator.t_end, or the first break plus after_break
  // (`run`'s stop rule).
  std::int64_t last_step() const;
  bool at_end() const { return sim_->state().step >= last_step(); }
  // The physics stopped being finite: the message; the run stays where it was.
  const std::string& error() const { return error_; }

  // Advances by whole steps of the scene's dt up to `step` (never past last_step()). False on
  // a non-finite state (error()).
  bool advance_to(std::int64_t step);
  std::int64_t step_at(double tau) const;  // the first grid step at or after tau

  // The frame as `chainbreak snapshot` lays it out for this scene (size, theme, view); with
  // `plots`, the chain in the upper band and the overlay's plots below it (web_plots.h).
  RenderSnapshot snapshot(int width, int height, const std::string& theme, const std::string& view,
                          bool plots) const;

 private:
  void replace(SceneDesc scene, std::string text, std::string path, std::vector<Override> o);
  void start_history();
  const WebBreakMap& break_map() const;

  // The plots' histories (the overlay's physics side, overlay_history.h), recorded every
  // frame_steps_ steps of the run: frames on the scene's own step grid.
  std::int64_t frame_steps_ = 1;
  OverlaySetup setup_;
  std::unique_ptr<OverlayHistory> history_;
  mutable std::optional<WebBreakMap> break_map_;  // made on the first frame that shows it

  SceneDesc scene_;
  std::string text_, path_;
  std::vector<Override> overrides_;
  std::unique_ptr<Integrator> sim_;
  RunExtent extent_;
  std::string error_;
};

}  // namespace cb
