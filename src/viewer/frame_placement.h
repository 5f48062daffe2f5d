// Where the rendered frame sits in the window: as large as fits with its aspect kept, centred
// (letterboxed). Maps between the frame's pixels (what snapshots and picking use) and the
// window's framebuffer pixels, both with the origin top-left. No GL: tested on its own.
#pragma once

namespace cb {

struct FramePlacement {
  int window_width = 0, window_height = 0;  // the window's framebuffer, pixels
  int frame_width = 0, frame_height = 0;    // the rendered frame, pixels
  int x = 0, y = 0, width = 0, height = 0;  // the frame's rectangle in the window

  bool fills_window() const {
    return x == 0 && y == 0 && width == window_width && height == window_height;
  }
  bool one_to_one() const { return width == frame_width && height == frame_height; }
  // GL's rectangle for glBlitFramebuffer: rows count from the bottom.
  int gl_bottom() const { return window_height - y - height; }
  // Window pixel -> frame pixel, and back.
  float frame_x(float window_x) const { return (window_x - x) * frame_width / width; }
  float frame_y(float window_y) const { return (window_y - y) * frame_height / height; }
  float window_x(float frame_x) const { return x + frame_x * width / frame_width; }
  float window_y(float frame_y) const { return y + frame_y * height / frame_height; }
};

FramePlacement place_frame(int frame_width, int frame_height, int window_width, int window_height);

}  // namespace cb
