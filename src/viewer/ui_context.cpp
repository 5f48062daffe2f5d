#include "viewer/ui_context.h"

#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <string>

#include "overlay/overlay.h"
#include "theme/fonts.h"

namespace cb {

UiContext::UiContext(GLFWwindow* window, ThemeName theme) {
  const std::string font = font_path(FontFace::Sans);  // before anything needs undoing
  context_ = ImGui::CreateContext();
  ImGui::SetCurrentContext(context_);
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;  // no imgui.ini left in the user's folder
  if (theme == ThemeName::Light) {
    ImGui::StyleColorsLight();
  } else {
    ImGui::StyleColorsDark();
  }
  // The project's one typeface, DejaVu Sans, at 17 px: readable from the back of a lecture
  // hall. ImGui's built-in bitmap font is never used: a missing file is an error (font_path
  // names the package). Latin, Greek and the math signs the controls write (τ, φ_c, γ, β).
  static const ImWchar kRanges[] = {0x0020, 0x00FF, 0x0391, 0x03C9, 0x2070, 0x209C,
                                    0x2190, 0x21FF, 0x2200, 0x22FF, 0};
  if (!io.Fonts->AddFontFromFileTTF(font.c_str(), 17.0f, nullptr, kRanges)) {
    this->~UiContext();
    throw std::runtime_error("Dear ImGui could not load the font " + font);
  }
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
