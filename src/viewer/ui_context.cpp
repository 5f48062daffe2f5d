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

namespace {

// The project's one typeface, DejaVu Sans: ImGui's built-in bitmap font is never used, and a
// missing file is an error (font_path names the package). Latin, Greek and the math signs
// the controls write (τ, φ_c, γ, β).
bool load_font(ImGuiIO& io, const std::string& font, float px) {
  static const ImWchar kRanges[] = {0x0020, 0x00FF, 0x0391, 0x03C9, 0x2070, 0x209C,
                                    0x2190, 0x21FF, 0x2200, 0x22FF, 0};
  io.Fonts->Clear();
  return io.Fonts->AddFontFromFileTTF(font.c_str(), px, nullptr, kRanges) != nullptr;
}

}  // namespace

UiContext::UiContext(GLFWwindow* window, ThemeName theme) : theme_(theme) {
  font_ = font_path(FontFace::Sans);  // before anything needs undoing
  context_ = ImGui::CreateContext();
  ImGui::SetCurrentContext(context_);
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;  // no imgui.ini left in the user's folder
  // 17 px at scale 1: readable from the back of a lecture hall; set_scale follows the
  // window's content scale.
  if (!load_font(io, font_, UiScale{}.font_px())) {
    this->~UiContext();
    throw std::runtime_error("Dear ImGui could not load the font " + font_);
  }
  style();
  platform_ = ImGui_ImplGlfw_InitForOpenGL(window, true);
  renderer_ = platform_ && ImGui_ImplOpenGL3_Init("#version 330");
  if (!renderer_) {
    this->~UiContext();
    throw std::runtime_error("Dear ImGui's GLFW or OpenGL3 backend did not start");
  }
}

void UiContext::style() {
  ImGuiStyle fresh;  // ScaleAllSizes multiplies: always from the unscaled sizes
  ImGui::GetStyle() = fresh;
  if (theme_ == ThemeName::Light) {
    ImGui::StyleColorsLight();
  } else {
    ImGui::StyleColorsDark();
  }
  ImGui::GetStyle().ScaleAllSizes(scale_.window_units());
  ImGui::GetIO().FontGlobalScale = 1.0f / scale_.framebuffer;
}

void UiContext::set_scale(const UiScale& scale) {
  ImGui::SetCurrentContext(context_);
  if (scale.pixel == scale_.pixel && scale.framebuffer == scale_.framebuffer) return;
  const bool new_font = scale.pixel != scale_.pixel;
  scale_ = scale;
  style();
  if (!new_font) return;
  // The atlas again at the new raster size (crisp text, not a stretched 17 px one), and its
  // texture once the backend has made its first one.
  if (!load_font(ImGui::GetIO(), font_, scale_.font_px()))
    throw std::runtime_error("Dear ImGui could not load the font " + font_);
  if (frames_ > 0) {
    ImGui_ImplOpenGL3_DestroyFontsTexture();
    ImGui_ImplOpenGL3_CreateFontsTexture();
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
  ++frames_;
}

void UiContext::end_frame() {
  ImGui::SetCurrentContext(context_);
  ImGui::Render();
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

}  // namespace cb
