#include "viewer/ui_context.h"

#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <string>

#include "overlay/overlay.h"

namespace cb {

UiContext::UiContext(GLFWwindow* window) {
  context_ = ImGui::CreateContext();
  ImGui::SetCurrentContext(context_);
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;  // no imgui.ini left in the user's folder
  ImGui::StyleColorsDark();
  // The overlay's DejaVu Sans, larger than ImGui's built-in 13 px bitmap font: readable from
  // the back of a lecture hall. Without the font file the built-in one does.
  const char* dir = std::getenv("CHAINBREAK_FONT_DIR");
  const std::string font =
      (std::filesystem::path(dir && *dir ? dir : kOverlayFontDir) / "DejaVuSans.ttf").string();
  if (std::filesystem::is_regular_file(font)) io.Fonts->AddFontFromFileTTF(font.c_str(), 17.0f);
  platform_ = ImGui_ImplGlfw_InitForOpenGL(window, true);
  renderer_ = platform_ && ImGui_ImplOpenGL3_Init("#version 330");
  if (!renderer_) {
    this->~UiContext();
    throw std::runtime_error("Dear ImGui's GLFW or OpenGL3 backend did not start");
  }
}

UiContext::~UiContext() {
  if (!context_) return;
  ImGui::SetCurrentContext(context_);
  if (renderer_) ImGui_ImplOpenGL3_Shutdown();
  if (platform_) ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext(context_);
  context_ = nullptr;
}

void UiContext::begin_frame() {
  ImGui::SetCurrentContext(context_);
  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  ImGui::NewFrame();
}

void UiContext::end_frame() {
  ImGui::SetCurrentContext(context_);
  ImGui::Render();
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

}  // namespace cb
