#include "viewer/script_actions.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace cb {

namespace {

// A script's `set KEY VALUE`, as the matching control would do it.
void apply_setting(const ScriptAction& a, SceneDesc& draft, ViewerModel& model,
                   ViewerRequests& requests) {
  if (a.key == "view") {
    draft.render.view = a.argument;
    requests.view_changed = true;
    return;
  }
  char* end = nullptr;
  const double v = std::strtod(a.argument.c_str(), &end);
  if (*end != '\0' || !std::isfinite(v))
    throw SceneError("script line " + std::to_string(a.line) + ": set " + a.key +
                     " needs a number, got '" + a.argument + "'");
  if (a.key == "speed") {
    model.speed = v;
    requests.speed_changed = true;
    return;
  }
  // A drive's parameter on a drive that has none of that name would silently do nothing.
  const DriveType t = draft.drive.type;
  const bool fits = (a.key != "beta" || t == DriveType::Ramp) &&
                    (a.key != "amplitude" || t == DriveType::Step || t == DriveType::Sine) &&
                    (a.key != "period" || t == DriveType::Sine);
  if (!fits)
    throw SceneError("script line " + std::to_string(a.line) + ": set " + a.key +
                     ": the drive is " + drive_type_name(t) + ", which has no " + a.key +
                     " (beta: ramp; amplitude: step, sine; period: sine)");
  if (a.key == "beads") draft.chain.beads = static_cast<int>(v);
  if (a.key == "gamma") draft.chain.gamma = v;
  if (a.key == "threshold") draft.chain.threshold = v;
  if (a.key == "beta") draft.drive.beta = v;
  if (a.key == "amplitude") draft.drive.amplitude = v;
  if (a.key == "period") draft.drive.period = v;
  if (a.key == "t0") draft.drive.t0 = v;
  requests.apply_settings = true;
}

}  // namespace

void apply_script(const std::vector<ScriptAction>& actions, SceneDesc& draft, ViewerModel& model,
                  ViewerRequests& r) {
  for (const ScriptAction& a : actions) {
    if (a.action == "play") model.playing = true;
    if (a.action == "pause") model.playing = false;
    if (a.action == "step") r.step += std::max(1, std::atoi(a.argument.c_str()));
    if (a.action == "restart") r.restart = true;
    if (a.action == "quit") r.quit = true;
    if (a.action == "set") apply_setting(a, draft, model, r);
    if (a.action == "select") model.pinned_spring = std::atoi(a.argument.c_str());
    if (a.action == "snapshot") r.snapshot = true, r.snapshot_path = a.argument;
    if (a.action == "save") r.save = true, r.save_path = a.argument;
    if (a.action == "screenshot") r.screenshot_path = a.argument;
    if (a.action == "layout") r.layout_path = a.argument;
    if (a.action == "panels") model.show_controls = a.argument == "on";
    if (a.action == "present") r.present = a.argument == "on" ? 1 : 0;
    if (a.action == "resize") {
      r.resize_width = std::atoi(a.key.c_str());
      r.resize_height = std::atoi(a.argument.c_str());
    }
    if (a.action == "record" && (a.argument == "stop") == model.recording)
      r.record = true, r.record_path = a.argument == "stop" ? "" : a.argument;
  }
}

}  // namespace cb
