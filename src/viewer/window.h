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
  static double now();  // seconds, monotonic
  // What the window shows, controls included: the back buffer, read before swap().
  Image read_back_buffer() const;

 private:
  GLFWwindow* window_ = nullptr;
};

}  // namespace cb
