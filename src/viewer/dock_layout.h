// Where the viewer's parts go in its window (issue #27): the picture, which is the frame
// `render` draws at the picture's size (Session::plan_at), and beside it, on the right, a
// column with the controls above and the spring plot below. The panels are docked, never
// over the picture, so nothing of the chain is hidden behind them; Tab (or presentation mode)
// hides the column and the picture takes the whole window. Framebuffer pixels, origin top
// left. No GL: tested on its own.
#pragma once

namespace cb {

struct PixelRect {
  int x = 0, y = 0, w = 0, h = 0;
  int right() const { return x + w; }
  int bottom() const { return y + h; }
  bool empty() const { return w <= 0 || h <= 0; }
  bool overlaps(const PixelRect& o) const {
    return !empty() && !o.empty() && x < o.right() && o.x < right() && y < o.bottom() &&
           o.y < bottom();
  }
};

// How large the panels are drawn. `pixel`: framebuffer pixels per unit of the panels' design
// (17 px text): the window's content scale (glfwGetWindowContentScale: 2 on a HiDPI laptop,
// set by the desktop for a 4K projector) times --ui-scale. `framebuffer`: framebuffer pixels
// per window coordinate, which Dear ImGui works in (2 on a Retina Mac, 1 on X11 and Windows,
// where the content scale alone says the pixels are small).
struct UiScale {
  float pixel = 1.0f;
  float framebuffer = 1.0f;
  float font_px() const { return 17.0f * pixel; }  // the text's raster size, framebuffer pixels
  float window_units() const { return pixel / framebuffer; }  // ImGui sizes: window coordinates
};
UiScale ui_scale(float content_scale, float user_scale, int window_width, int framebuffer_width);

// The column's width and the plot's height at scale 1; the column never takes more than
// kMaxColumnFraction of the window's width, the plot never more than kMaxPlotFraction of its
// height.
inline constexpr float kColumnWidth = 400.0f, kPlotHeight = 320.0f;
inline constexpr float kMaxColumnFraction = 0.4f, kMaxPlotFraction = 0.4f;

struct DockLayout {
  PixelRect window;    // the whole framebuffer
  PixelRect picture;   // the chain's frame, drawn at this size
  PixelRect controls;  // empty when the panels are hidden
  PixelRect plot;      // empty when hidden or when no spring is plotted
};

DockLayout dock_layout(int window_width, int window_height, float pixel_scale, bool panels,
                       bool plot);

}  // namespace cb
