// Drawing primitives the overlay's panels share (overlay_plot.cpp). Internal to cb_overlay.
#pragma once

#include <string>
#include <vector>

#include "figures/axis_ticks.h"
#include "overlay/overlay_panels.h"

namespace cb::overlay_detail {

ImU32 col(const OverlayRgb& c, float alpha = 1.0f);
std::string format(const char* fmt, ...) __attribute__((format(printf, 1, 2)));
std::string subscript(int value);  // "15" -> "\u2081\u2085" (UTF-8 subscript digits)
float text_width(ImFont* font, float size, const std::string& s);
// Text with its top-left at (x, y); `align` 0 left, 0.5 centre, 1 right of x; `scale` of the
// font size. Returns the x just right of the text.
float text(Canvas& c, ImFont* font, float x, float y, const OverlayRgb& colour,
           const std::string& s, float align = 0.0f, float scale = 1.0f);
// Like text(), but "_x" draws the character x as a subscript (phi_c).
float text_sub(Canvas& c, ImFont* font, float x, float y, const OverlayRgb& colour,
               const std::string& s, float align = 0.0f, float scale = 1.0f);

// Ticks and nice_ticks live with the figures (figures/axis_ticks.h): one rule for both.
using cb::nice_ticks;
using cb::Ticks;

void dashed_hline(Canvas& c, float x0, float x1, float y, ImU32 colour, float width, float dash);
void dashed_vline(Canvas& c, float x, float y0, float y1, ImU32 colour, float width, float dash);
// A panel's outline and title (c.title_right: where the title ends).
void panel(Canvas& c, const Box& box, const std::string& title);
// A small note right-aligned in the title row; false (nothing drawn) when it would touch the
// title.
bool title_note(Canvas& c, const Box& box, const std::string& note);
// Grid (optional), frame and tick labels of a plot in `box`; `x_name` below the y labels.
void axes(Canvas& c, const Box& box, const PlotMapping& m, const Ticks& xt, const Ticks& yt,
          const std::string& x_name, bool grid);
struct LegendEntry {
  OverlayRgb colour;
  std::string label;
  bool dot;  // a dot (points) rather than a dash (a line)
};
// A row of legend entries inside the plot's top-left corner, on a translucent box.
void legend(Canvas& c, const Box& a, float y, const std::vector<LegendEntry>& entries);
// A polyline through (t[i], v[i]), thinned (overlay_plot.cpp says how and why).
void polyline(Canvas& c, const PlotMapping& m, const std::vector<double>& t,
              const std::vector<double>& v, ImU32 colour, float width);
void time_cursor(Canvas& c, const PlotMapping& m);  // a faint vertical line at the frame's tau

}  // namespace cb::overlay_detail
