// Keyboard shortcuts (controls.h, kShortcuts). Dear ImGui 1.86's GLFW backend indexes
// io.KeysDown by GLFW key codes, hence GLFW's header here.
#define GLFW_INCLUDE_NONE  // the key codes only
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>

#include "viewer/controls.h"

namespace cb {

void handle_shortcuts(ViewerModel& model, SceneDesc& draft, ViewerRequests& requests) {
  const ImGuiIO& io = ImGui::GetIO();
  if (io.WantTextInput) return;
  auto pressed = [](int key) { return ImGui::IsKeyPressed(key, false); };
  if (pressed(GLFW_KEY_SPACE)) model.playing = !model.playing;
  if (pressed(GLFW_KEY_S) && io.KeyCtrl) {
    requests.save = true;
  } else if (ImGui::IsKeyPressed(GLFW_KEY_S) || ImGui::IsKeyPressed(GLFW_KEY_RIGHT)) {
    requests.step += 1;  // with key repeat: hold to step on
  }
  if (pressed(GLFW_KEY_R)) requests.restart = true;
  if (pressed(GLFW_KEY_EQUAL) || pressed(GLFW_KEY_KP_ADD)) {
    model.speed = std::min(model.speed * 2.0, kMaxSpeed);
    requests.speed_changed = true;
  }
  if (pressed(GLFW_KEY_MINUS) || pressed(GLFW_KEY_KP_SUBTRACT)) {
    model.speed = std::max(model.speed * 0.5, kMinSpeed);
    requests.speed_changed = true;
  }
  if (pressed(GLFW_KEY_V)) {
    draft.render.view = next_view(draft.render.view);
    requests.view_changed = true;
  }
  if (pressed(GLFW_KEY_P)) requests.snapshot = true;
  if (pressed(GLFW_KEY_M)) requests.record = true;
  if (pressed(GLFW_KEY_TAB)) model.show_controls = !model.show_controls;
  if (pressed(GLFW_KEY_H) || pressed(GLFW_KEY_F1)) model.show_help = !model.show_help;
  if (pressed(GLFW_KEY_F11) || pressed(GLFW_KEY_F)) requests.present = model.presenting ? 0 : 1;
  // In front of an audience Esc leaves presentation mode rather than the program.
  if (pressed(GLFW_KEY_ESCAPE) && model.presenting) {
    requests.present = 0;
  } else if (pressed(GLFW_KEY_ESCAPE) || pressed(GLFW_KEY_Q)) {
    requests.quit = true;
  }
}

}  // namespace cb
