// Window: the viewer's GLFW window with a current OpenGL 3.3 core context, and our GL function
// table (gl/gl_loader.h) loaded from glfwGetProcAddress. The only file that includes GLFW
// besides the ImGui platform backend.
#pragma once

#include <stdexcept>
#include <string>

#include "output/image.h"

struct GLFWwindow;

namespace cb {

// No display to open (no X server, no Wayland compositor): the caller says what to use instead.
struct NoDisplayError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class Window {
 public:
  // A window for a frame of `frame_width` x `frame_height`, shrunk to fit the screen with
  // its aspect kept. Throws NoDisplayError without a display, std::runtime_error otherwise.
  Window(int frame_width, int frame_height, const std::string& title, bool vsync);
  ~Window();
  Window(const Window&) = delete;
  Window& operator=(const Window&) = delete;

  GLFWwindow* handle() const { return window_; }
  bool should_close() const;
  void poll();  // input events, into the current ImGui context through its GLFW backend
  void close();
  void swap();
  // The drawable size in pixels (may differ from the window's size on high-DPI screens).
  void framebuffer_size(int& width, int& height) const;
  // The window's size in screen coordinates (Dear ImGui's units).
  void window_size(int& width, int& height) const;
  // How large the desktop wants UI drawn here (glfwGetWindowContentScale, horizontal): 1 on
  // a plain screen, 2 on a HiDPI one.
  float content_scale() const;
  // As a person dragging the window's corner would leave it (the script's `resize`).
  void resize(int width, int height);
  // Fullscreen on the window's monitor (the primary one when unknown), or back to the window
  // it was; nothing when already so.
  void set_fullscreen(bool on);
  static double now();  // seconds, monotonic
  // What the window shows, controls included: the back buffer, read before swap().
  Image read_back_buffer() const;

 private:
  GLFWwindow* window_ = nullptr;
  bool fullscreen_ = false;
  int windowed_[4] = {0, 0, 0, 0};  // x, y, width, height before fullscreen
};

}  // namespace cb
