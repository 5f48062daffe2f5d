// UiContext: the viewer's own Dear ImGui context, driven by the window (the GLFW platform
// backend: mouse, keyboard, display size, time) and drawn with the OpenGL3 renderer backend,
// both thin adapters from libimgui-dev. The video overlay (src/overlay) keeps its own
// headless context; Overlay::draw makes it current and restores this one afterwards, so
// the two never see each other's state.
#pragma once

#include "theme/theme.h"

struct GLFWwindow;
struct ImGuiContext;

namespace cb {

class UiContext {
 public:
  // Throws std::runtime_error if a backend fails or the font is missing.
  UiContext(GLFWwindow* window, ThemeName theme);
  ~UiContext();
  UiContext(const UiContext&) = delete;
  UiContext& operator=(const UiContext&) = delete;

  void begin_frame();  // makes this context current, polls nothing (the caller polls events)
  void end_frame();    // renders the widgets into the bound (default) framebuffer

 private:
  ImGuiContext* context_ = nullptr;
  bool platform_ = false, renderer_ = false;
};

}  // namespace cb
