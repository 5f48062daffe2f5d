// RunSet: the runs one video shows, on one frame clock. One scene is one run, drawn as it
// always was; 2-4 scenes are stacked top to bottom, each in its band of the frame, labelled
// with its title and the parameters in which the scenes differ ("β = 0.075"), all stepping to
// the same frame times (the shared FrameGrid: the smallest step any scene asks for, slowed
// around the breaks of every run). A run that stops earlier (after_break) holds its last
// frame. The title card (--title-card S) opens the video with S seconds of text.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/commands.h"
#include "app/frame_source.h"
#include "app/render_plan.h"

namespace cb {

inline constexpr int kMaxSideBySide = 4;

// Each run's label: its title and the parameters in which the runs differ ("β = 0.075").
std::vector<std::string> side_by_side_labels(const std::vector<SceneDesc>& scenes);

class RunSet {
 public:
  // Plans every run (cheap: options and scenes checked). Throws SceneError.
  RunSet(std::vector<SceneDesc> scenes, const RenderOptions& options);
  ~RunSet();
  // The physics pre-pass of every run, then the shared frame clock.
  void measure();

  const RenderPlan& plan() const { return plan_; }  // the video's: size, fps, clock, output
  const SceneDesc& scene(std::size_t i) const { return scenes_[i]; }
  std::size_t size() const { return scenes_.size(); }
  std::int64_t frames() const { return plan_.title_frames + plan_.grid.frames(); }
  const std::vector<std::string>& labels() const { return labels_; }

  // Frame k of the video, k increasing from call to call (after start()). Null after a
  // non-finite state (error() says why).
  void start(int threads);
  std::optional<RenderSnapshot> frame(std::int64_t k);
  const std::string& error() const { return error_; }
  std::vector<BreakEvent> breaks(std::size_t run) const;  // so far
  // The sidecar: the first run's plan_json, with "runs" for side-by-side videos.
  std::string json(const std::string& gl) const;

 private:
  std::vector<SceneDesc> scenes_;
  std::vector<RenderPlan> plans_;  // one per run (side by side: its band of the frame)
  RenderPlan plan_;                // the video's
  std::vector<std::string> labels_;
  std::vector<std::unique_ptr<FrameSource>> sources_;
  std::vector<std::int64_t> last_frame_;  // each run's last frame on the shared clock
  std::string title_;
  std::vector<std::string> title_lines_;
  std::string error_;
};

}  // namespace cb
