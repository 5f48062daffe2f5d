#include "viewer/window.h"

// Our loader declares the GL functions (glcorearb.h); GLFW must not include <GL/gl.h> too.
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <algorithm>
#include <string>

#include "gl/gl_loader.h"
#include "viewer/keep_gl_driver.h"

namespace cb {

namespace {

std::string g_last_error;  // GLFW reports errors through a callback; the last one, for messages

void on_glfw_error(int, const char* description) {
  g_last_error = description ? description : "unknown error";
}

void* proc_address(const char* name) {
  return reinterpret_cast<void*>(glfwGetProcAddress(name));
}

}  // namespace

Window::Window(int frame_width, int frame_height, const std::string& title, bool vsync) {
  glfwSetErrorCallback(on_glfw_error);
  if (!glfwInit()) throw NoDisplayError("GLFW could not start: " + g_last_error);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  // The frame fits the screen's work area with its aspect kept; never enlarged.
  int width = frame_width, height = frame_height;
  if (GLFWmonitor* monitor = glfwGetPrimaryMonitor()) {
    int x = 0, y = 0, area_w = 0, area_h = 0;
    glfwGetMonitorWorkarea(monitor, &x, &y, &area_w, &area_h);
    if (area_w > 0 && area_h > 0) {
      const double scale = std::min({1.0, static_cast<double>(area_w) / frame_width,
                                     static_cast<double>(area_h) / frame_height});
      width = std::max(1, static_cast<int>(frame_width * scale));
      height = std::max(1, static_cast<int>(frame_height * scale));
    }
  }
  window_ = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
  if (!window_) {
    const std::string why = g_last_error;
    glfwTerminate();
    throw std::runtime_error("cannot open an OpenGL 3.3 core window: " + why);
  }
  glfwMakeContextCurrent(window_);
  keep_gl_driver_loaded();  // ASan builds only: keep_gl_driver.h says why
  glfwSwapInterval(vsync ? 1 : 0);
  std::string missing;
  if (!load_gl_functions(proc_address, missing)) {
    glfwDestroyWindow(window_);
    glfwTerminate();
    throw std::runtime_error("the window's OpenGL lacks " + missing);
  }
}

Window::~Window() {
  glfwDestroyWindow(window_);
  glfwTerminate();
}

bool Window::should_close() const {
  return glfwWindowShouldClose(window_);
}

void Window::poll() {
  glfwPollEvents();
}

void Window::close() {
  glfwSetWindowShouldClose(window_, GLFW_TRUE);
}

void Window::swap() {
  glfwSwapBuffers(window_);
}

void Window::framebuffer_size(int& width, int& height) const {
  glfwGetFramebufferSize(window_, &width, &height);
}

void Window::window_size(int& width, int& height) const {
  glfwGetWindowSize(window_, &width, &height);
}

float Window::content_scale() const {
  float x = 1.0f, y = 1.0f;
  glfwGetWindowContentScale(window_, &x, &y);
  return x > 0.0f ? x : 1.0f;
}

void Window::resize(int width, int height) {
  glfwSetWindowSize(window_, width, height);
}

void Window::set_fullscreen(bool on) {
  if (on == fullscreen_) return;
  if (on) {
    GLFWmonitor* monitor = glfwGetWindowMonitor(window_);
    if (!monitor) monitor = glfwGetPrimaryMonitor();
    const GLFWvidmode* mode = monitor ? glfwGetVideoMode(monitor) : nullptr;
    if (!mode) return;  // no monitor to fill: stay a window
    glfwGetWindowPos(window_, &windowed_[0], &windowed_[1]);
    glfwGetWindowSize(window_, &windowed_[2], &windowed_[3]);
    glfwSetWindowMonitor(window_, monitor, 0, 0, mode->width, mode->height, mode->refreshRate);
  } else {
    glfwSetWindowMonitor(window_, nullptr, windowed_[0], windowed_[1], windowed_[2], windowed_[3],
                         GLFW_DONT_CARE);
  }
  fullscreen_ = on;
}

Image Window::read_back_buffer() const {
  int width = 0, height = 0;
  framebuffer_size(width, height);
  Image image(width, height);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glReadBuffer(GL_BACK);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, image.rgba.data());
  // GL's rows are bottom-up, an Image's top-down.
  const std::size_t row = static_cast<std::size_t>(width) * 4;
  for (int y = 0; y < height / 2; ++y)
    std::swap_ranges(image.pixel(0, y), image.pixel(0, y) + row, image.pixel(0, height - 1 - y));
  for (std::size_t i = 3; i < image.rgba.size(); i += 4) image.rgba[i] = 255;  // opaque
  return image;
}

double Window::now() {
  return glfwGetTime();
}

}  // namespace cb
