// The control and help panels (controls.h). Keyboard shortcuts are in shortcuts.cpp.
#include "viewer/controls.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "viewer/session.h"

namespace cb {

namespace {

// A slider over a double; true when an edit is finished (released or typed in), the moment
// the loop applies it.
bool slider(const char* label, double& value, double lo, double hi, bool logarithmic,
            const char* format = "%.4g") {
  ImGui::SliderScalar(label, ImGuiDataType_Double, &value, &lo, &hi, format,
                      logarithmic ? ImGuiSliderFlags_Logarithmic : 0);
  return ImGui::IsItemDeactivatedAfterEdit();
}

bool drive_controls(DriveDesc& d) {
  bool done = false;
  static constexpr DriveType kEditable[] = {DriveType::Step, DriveType::Ramp, DriveType::Sine};
  if (ImGui::BeginCombo("drive", drive_type_name(d.type))) {
    for (DriveType t : kEditable)
      if (ImGui::Selectable(drive_type_name(t), t == d.type) && t != d.type) {
        d.type = t;
        done = true;
      }
    ImGui::EndCombo();
  }
  switch (d.type) {
    case DriveType::Ramp:
      done |= slider("beta", d.beta, 1e-4, 10.0, true);
      break;
    case DriveType::Step:
      done |= slider("amplitude", d.amplitude, 1e-3, 10.0, true);
      break;
    case DriveType::Sine:
      done |= slider("amplitude", d.amplitude, 1e-3, 10.0, true);
      done |= slider("period", d.period, 0.5, 1000.0, true);
      break;
    default:
      ImGui::TextDisabled("(this drive's parameters: edit the scene file)");
      break;
  }
  done |= slider("t0", d.t0, 0.0, 100.0, false);
  return done;
}

bool chain_controls(ChainParams& c) {
  bool done = false;
  ImGui::SliderInt("N", &c.beads, 1, 5000, "%d", ImGuiSliderFlags_Logarithmic);
  done |= ImGui::IsItemDeactivatedAfterEdit();
  done |= slider("gamma", c.gamma, 0.0, 1.0, false);
  bool breakable = c.breakable();
  if (ImGui::Checkbox("breakable", &breakable)) {
    c.threshold = breakable ? 1.0 : std::numeric_limits<double>::infinity();
    done = true;
  }
  if (c.breakable()) done |= slider("phi_c", c.threshold, 0.01, 100.0, true);
  return done;
}

void status_lines(const ViewerModel& model, const Session& session) {
  const ChainState& s = session.state();
  ImGui::Text("tau %.2f / %.2f   frame %lld", session.tau(),
              session.plan().grid.tau(session.plan().grid.frames() - 1),
              static_cast<long long>(session.frame()));
  if (!s.breaks.empty())
    ImGui::Text("first break: spring %d at tau %.3f", s.breaks.front().spring,
                s.breaks.front().tau);
  ImGui::Text("%.0f fps%s", model.display_fps,
              model.script ? "  (script: fixed tau per frame)" : "");
  if (model.behind)
    ImGui::TextColored(ImVec4(1.0f, 0.35f, 0.3f, 1.0f),
                       "Cannot keep up: running at %.0f%% of the requested speed.\n"
                       "Lower the speed or N.",
                       100.0 * model.achieved_ratio);
  if (session.at_end()) ImGui::TextColored(ImVec4(1, 0.8f, 0.3f, 1), "End of the run (R restarts)");
  if (!session.error().empty())
    ImGui::TextColored(ImVec4(1, 0.35f, 0.3f, 1), "%s", session.error().c_str());
  if (!model.status.empty()) ImGui::TextWrapped("%s", model.status.c_str());
}

}  // namespace

const char* next_view(const std::string& view) {
  if (view == "longitudinal") return "transverse";
  if (view == "transverse") return "both";
  if (view == "both") return "vertical";
  return "longitudinal";
}

bool dock_next_window(const PixelRect& rect) {
  if (rect.empty()) return false;
  const ImVec2 to_ui(1.0f / ImGui::GetIO().DisplayFramebufferScale.x,
                     1.0f / ImGui::GetIO().DisplayFramebufferScale.y);
  ImGui::SetNextWindowPos(ImVec2(rect.x * to_ui.x, rect.y * to_ui.y), ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(rect.w * to_ui.x, rect.h * to_ui.y), ImGuiCond_Always);
  return true;
}

void draw_controls(ViewerModel& model, SceneDesc& draft, const Session& session,
                   ViewerRequests& requests, const PixelRect& rect) {
  if (!dock_next_window(rect)) return;
  ImGui::Begin("chainbreak", nullptr, kDockedWindow);
  // Sliders take the column's width less their labels' (the longest, "speed (tau/s)").
  const float item_width =
      std::max(ImGui::GetFontSize() * 4.0f, ImGui::GetContentRegionAvail().x -
                                                ImGui::CalcTextSize("speed (tau/s)").x -
                                                ImGui::GetStyle().ItemInnerSpacing.x);
  if (ImGui::Button(model.playing ? "Pause" : "Play")) model.playing = !model.playing;
  ImGui::SameLine();
  if (ImGui::Button("Step")) requests.step += 1;
  ImGui::SameLine();
  if (ImGui::Button("Restart")) requests.restart = true;
  ImGui::SameLine();
  if (ImGui::Button("Help")) model.show_help = !model.show_help;
  ImGui::SetNextItemWidth(item_width);
  if (slider("speed (tau/s)", model.speed, kMinSpeed, kMaxSpeed, true))
    requests.speed_changed = true;

  ImGui::PushItemWidth(item_width);
  if (ImGui::CollapsingHeader("Chain and drive", ImGuiTreeNodeFlags_DefaultOpen)) {
    requests.apply_settings |= chain_controls(draft.chain);
    requests.apply_settings |= drive_controls(draft.drive);
  }
  if (ImGui::CollapsingHeader("View", ImGuiTreeNodeFlags_DefaultOpen)) {
    for (const char* v : {"longitudinal", "transverse", "both", "vertical"}) {
      if (ImGui::RadioButton(v, draft.render.view == v) && draft.render.view != v) {
        draft.render.view = v;
        requests.view_changed = true;
      }
      ImGui::SameLine();
    }
    ImGui::NewLine();
  }
  ImGui::PopItemWidth();
  if (ImGui::Button("Snapshot")) requests.snapshot = true;
  ImGui::SameLine();
  if (ImGui::Button(model.recording ? "Stop recording" : "Record")) requests.record = true;
  ImGui::SameLine();
  if (ImGui::Button("Save scene")) requests.save = true;
  ImGui::Separator();
  status_lines(model, session);
  ImGui::End();
}

void draw_help(ViewerModel& model, const PixelRect& picture) {
  if (!model.show_help) return;
  // Asked for (H), so over the picture, in its middle: closed again with H or its button.
  const ImVec2 scale = ImGui::GetIO().DisplayFramebufferScale;
  ImGui::SetNextWindowPos(
      ImVec2((picture.x + 0.5f * picture.w) / scale.x, (picture.y + 0.5f * picture.h) / scale.y),
      ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
  ImGui::Begin("Help: keyboard and mouse", &model.show_help, ImGuiWindowFlags_AlwaysAutoResize);
  if (ImGui::BeginTable("shortcuts", 2, ImGuiTableFlags_RowBg)) {
    for (const Shortcut& s : kShortcuts) {
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(s.keys);
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(s.action);
    }
    ImGui::EndTable();
  }
  ImGui::TextWrapped(
      "Chain and drive edits restart the run when you release the slider. "
      "Outputs go to --out-dir (default renders/).");
  ImGui::End();
}

}  // namespace cb
