#include "viewer/ui_context.h"

#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <stdexcept>

namespace cb {

UiContext::UiContext(GLFWwindow* window) {
  context_ = ImGui::CreateContext();
  ImGui::SetCurrentContext(context_);
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;  // no imgui.ini left in the user's folder
  ImGui::StyleColorsDark();
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
