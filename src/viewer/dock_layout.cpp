#include "viewer/dock_layout.h"

#include <algorithm>
#include <cmath>

namespace cb {

UiScale ui_scale(float content_scale, float user_scale, int window_width, int framebuffer_width) {
  UiScale s;
  const float content = content_scale > 0.0f ? content_scale : 1.0f;
  s.pixel = content * (user_scale > 0.0f ? user_scale : 1.0f);
  if (window_width > 0 && framebuffer_width > 0)
    s.framebuffer = static_cast<float>(framebuffer_width) / static_cast<float>(window_width);
  return s;
}

DockLayout dock_layout(int window_width, int window_height, float pixel_scale, bool panels,
                       bool plot) {
  DockLayout d;
  const int W = std::max(1, window_width), H = std::max(1, window_height);
  d.window = PixelRect{0, 0, W, H};
  d.picture = d.window;
  if (!panels) return d;
  const int column = std::min(static_cast<int>(std::lround(kColumnWidth * pixel_scale)),
                              static_cast<int>(kMaxColumnFraction * static_cast<float>(W)));
  if (column <= 0) return d;
  d.picture.w = W - column;
  // The controls keep at least 60 % of the height: at 720 p their status lines still show.
  const int plot_h = plot ? std::min(static_cast<int>(std::lround(kPlotHeight * pixel_scale)),
                                     static_cast<int>(kMaxPlotFraction * static_cast<float>(H)))
                          : 0;
  d.controls = PixelRect{W - column, 0, column, H - plot_h};
  if (plot_h > 0) d.plot = PixelRect{W - column, H - plot_h, column, plot_h};
  return d;
}

}  // namespace cb
