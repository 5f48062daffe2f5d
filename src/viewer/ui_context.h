// UiContext: the viewer's own Dear ImGui context, driven by the window (the GLFW platform
// backend: mouse, keyboard, display size, time) and drawn with the OpenGL3 renderer backend,
// both thin adapters from libimgui-dev. The video overlay (src/overlay) keeps its own
// headless context; Overlay::draw makes it current and restores this one afterwards, so
// the two never see each other's state.
#pragma once

#include <string>

#include "theme/theme.h"
#include "viewer/dock_layout.h"

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

  // The panels' size (dock_layout.h): before begin_frame; a new scale re-rasterises the font.
  void set_scale(const UiScale& scale);
  const UiScale& scale() const { return scale_; }
  void begin_frame();  // makes this context current, polls nothing (the caller polls events)
  void end_frame();    // renders the widgets into the bound (default) framebuffer

 private:
  void style();  // the theme's colours, sizes times the scale

  ImGuiContext* context_ = nullptr;
  bool platform_ = false, renderer_ = false;
  ThemeName theme_;
  std::string font_;
  UiScale scale_;
  long frames_ = 0;
};

}  // namespace cb
