#include "app/run_set.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "app/csv.h"
#include "app/json_text.h"
#include "snapshot/stack.h"

namespace cb {

namespace {

// The parameters a label may name, as "symbol = value" (glyphs, not names).
std::vector<std::pair<std::string, std::string>> parameters(const SceneDesc& s) {
  const auto n = [](double v) { return number_text(v); };
  std::vector<std::pair<std::string, std::string>> p = {
      {"N", "N = " + std::to_string(s.chain.beads)},
      {"gamma", "γ = " + n(s.chain.gamma)},
      {"threshold", s.chain.breakable() ? "φ_c = " + n(s.chain.threshold) : "unbreakable"},
      {"drive", std::string("f: ") + drive_type_name(s.drive.type)}};
  switch (s.drive.type) {
    case DriveType::Ramp:
      p.push_back({"beta", "β = " + n(s.drive.beta)});
      break;
    case DriveType::Step:
      p.push_back({"amplitude", "f₀ = " + n(s.drive.amplitude)});
      break;
    case DriveType::Sine:
      p.push_back({"amplitude", "f₀ = " + n(s.drive.amplitude)});
      p.push_back({"period", "T = " + n(s.drive.period)});
      break;
    default:
      break;
  }
  return p;
}

}  // namespace

std::vector<std::string> side_by_side_labels(const std::vector<SceneDesc>& scenes) {
  std::vector<std::vector<std::pair<std::string, std::string>>> all;
  for (const SceneDesc& s : scenes) all.push_back(parameters(s));
  std::vector<std::string> labels;
  for (std::size_t i = 0; i < scenes.size(); ++i) {
    std::string differs;
    for (const auto& [key, text] : all[i]) {
      bool same = true;
      for (const auto& other : all)
        for (const auto& [k2, t2] : other)
          if (k2 == key && t2 != text) same = false;
      if (!same) differs += (differs.empty() ? "" : ", ") + text;
    }
    const std::string title = scenes[i].title.empty() ? scenes[i].name : scenes[i].title;
    labels.push_back(differs.empty() ? title : title + "   " + differs);
  }
  return labels;
}

RunSet::RunSet(std::vector<SceneDesc> scenes, const RenderOptions& o) : scenes_(std::move(scenes)) {
  if (scenes_.empty() || scenes_.size() > static_cast<std::size_t>(kMaxSideBySide))
    throw SceneError("render: give 1 to " + std::to_string(kMaxSideBySide) +
                     " scenes (side by side), not " + std::to_string(scenes_.size()));
  plan_ = plan_render(scenes_[0], o);
  if (scenes_.size() == 1) {
    plans_.push_back(plan_);
  } else {
    // Each run in a band of the frame, without the overlay (its plots need the height).
    const int bands = static_cast<int>(scenes_.size());
    RenderOptions band = o;
    band.no_overlay = true;
    band.overlay.clear();
    band.frame.size = std::to_string(plan_.frame.width) + "x" +
                      std::to_string(std::max(16, plan_.frame.height / bands));
    band.frame.quality.clear();
    band.fps = plan_.frame.fps;
    band.speed = plan_.frame.speed;
    for (const SceneDesc& s : scenes_) plans_.push_back(plan_render(s, band));
    plan_.overlay = OverlaySwitches{false, false, false, false};
    plan_.overlay_layout = OverlayLayout{};
    labels_ = side_by_side_labels(scenes_);
  }
  plan_.title_frames =
      static_cast<std::int64_t>(std::llround(plan_.frame.title_card * plan_.frame.fps));
  title_ = scenes_.size() == 1 ? scenes_[0].title : "Which part of a chain breaks?";
  if (scenes_.size() == 1) {
    for (const auto& [key, text] : parameters(scenes_[0])) title_lines_.push_back(text);
  } else {
    title_lines_ = labels_;
  }
}

RunSet::~RunSet() = default;

void RunSet::measure() {
  // The shared clock: the speed and frame rate of the video, the smallest step any scene
  // asks for, slowed around every run's breaks, to the latest stop.
  double dt = scenes_[0].integrator.dt, stop = 0.0;
  std::vector<double> breaks;
  for (std::size_t i = 0; i < scenes_.size(); ++i) {
    dt = std::min(dt, scenes_[i].integrator.dt);
    measure_plan(scenes_[i], plans_[i]);
    stop = std::max(stop, plans_[i].extent.tau_stop);
    for (const BreakEvent& b : plans_[i].extent.breaks) breaks.push_back(b.tau);
  }
  if (scenes_.size() == 1) {  // the run's own plan is the video's; the title card stays
    const std::int64_t title_frames = plan_.title_frames;
    plan_ = plans_[0];
    plan_.title_frames = title_frames;
    return;
  }
  FrameGrid grid(plan_.frame.speed / plan_.frame.fps, dt, plan_.grid.slow_motion());
  grid.lay_out(stop, breaks);
  plan_.grid = grid;
  plan_.extent = plans_[0].extent;
  plan_.extent.tau_stop = stop;
  plan_.style = plans_[0].style;
  for (RenderPlan& p : plans_) {
    p.grid = grid;
    last_frame_.push_back(grid.first_frame_at_or_after(p.extent.tau_stop + 1e-9) - 1);
  }
}

void RunSet::start(int threads) {
  for (std::size_t i = 0; i < scenes_.size(); ++i)
    sources_.push_back(std::make_unique<FrameSource>(scenes_[i], plans_[i], threads));
}

std::optional<RenderSnapshot> RunSet::frame(std::int64_t k) {
  if (k < plan_.title_frames)
    return title_card(plan_.frame.width, plan_.frame.height, plan_.style.theme, title_,
                      title_lines_, "Which spring breaks first?");
  k -= plan_.title_frames;
  if (sources_.size() == 1) {
    auto snap = sources_[0]->frame(k);
    if (!snap) error_ = sources_[0]->error();
    return snap;
  }
  std::vector<RenderSnapshot> parts;
  for (std::size_t i = 0; i < sources_.size(); ++i) {
    auto snap = sources_[i]->frame(std::min(k, last_frame_[i]));
    if (!snap) {
      error_ = scenes_[i].name + ": " + sources_[i]->error();
      return std::nullopt;
    }
    parts.push_back(std::move(*snap));
  }
  return stack_snapshots(std::move(parts), labels_, plan_.frame.width, plan_.frame.height,
                         plan_.style.theme);
}

std::vector<BreakEvent> RunSet::breaks(std::size_t run) const {
  // Before the run (a dry run): the breaks the pre-pass found.
  if (run >= sources_.size()) return plans_[run].extent.breaks;
  return sources_[run]->state().breaks;
}

std::string RunSet::json(const std::string& gl) const {
  Json j = plan_json(scenes_[0], plan_, gl, breaks(0));
  if (scenes_.size() > 1) {
    Json runs = Json::array();
    for (std::size_t i = 0; i < scenes_.size(); ++i)
      runs.push_back({{"scene", scenes_[i].path},
                      {"title", scenes_[i].title},
                      {"label", labels_[i]},
                      {"breaks", breaks_json(plan_, breaks(i))}});
    j["runs"] = std::move(runs);
  }
  return json_text(j);
}

}  // namespace cb
