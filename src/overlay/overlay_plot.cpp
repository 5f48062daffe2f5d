// Drawing primitives the overlay's panels share: the theme's colours, text (with subscripts),
// ticks at round numbers, axes, legends, and polylines thinned for llvmpipe. Internal to
// cb_overlay.
#include "overlay/overlay_plot.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

namespace cb::overlay_detail {

namespace {

// Squared distance from p to the segment a-b.
float distance2(const ImVec2& p, const ImVec2& a, const ImVec2& b) {
  const float dx = b.x - a.x, dy = b.y - a.y, len2 = dx * dx + dy * dy;
  float u = len2 > 0 ? ((p.x - a.x) * dx + (p.y - a.y) * dy) / len2 : 0.0f;
  u = std::clamp(u, 0.0f, 1.0f);
  const float ex = a.x + u * dx - p.x, ey = a.y + u * dy - p.y;
  return ex * ex + ey * ey;
}

}  // namespace

ImU32 col(const OverlayRgb& c, float alpha) {
  return IM_COL32(c.r, c.g, c.b, static_cast<int>(std::lround(alpha * 255.0f)));
}

std::string format(const char* fmt, ...) {
  char buffer[256];
  va_list args;
  va_start(args, fmt);
  std::vsnprintf(buffer, sizeof buffer, fmt, args);
  va_end(args);
  return buffer;
}

// "15" -> "₁₅" (UTF-8 subscript digits, in the fonts' glyph ranges).
std::string subscript(int value) {
  static const char* const kDigits[10] = {"\u2080", "\u2081", "\u2082", "\u2083", "\u2084",
                                          "\u2085", "\u2086", "\u2087", "\u2088", "\u2089"};
  std::string out;
  for (char ch : std::to_string(value)) out += ch == '-' ? "\u208B" : kDigits[ch - '0'];
  return out;
}

float text_width(ImFont* font, float size, const std::string& s) {
  return font->CalcTextSizeA(size, FLT_MAX, 0.0f, s.c_str()).x;
}

// Draws `s` with its top-left at (x, y); `align` 0 left, 0.5 centre, 1 right of x. Returns
// the x just right of the text.
float text(Canvas& c, ImFont* font, float x, float y, const OverlayRgb& colour,
           const std::string& s, float align, float scale) {
  const float size = c.layout.font_px * scale;
  const float w = text_width(font, size, s);
  x = std::round(x - align * w);
  c.draw->AddText(font, size, ImVec2(x, std::round(y)), col(colour), s.c_str());
  return x + w;
}

// Like text(), but "_x" draws the character x as a subscript (phi_c: Unicode has no
// subscript c). Only for our own strings: a scene's title may hold underscores.
float text_sub(Canvas& c, ImFont* font, float x, float y, const OverlayRgb& colour,
               const std::string& s, float align, float scale) {
  const float size = c.layout.font_px * scale, small = 0.72f * size;
  // Split into runs: {text, subscript?}.
  std::vector<std::pair<std::string, bool>> runs(1);
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s[i] == '_' && i + 1 < s.size()) {
      runs.push_back({std::string(1, s[++i]), true});
      runs.push_back({});
    } else {
      runs.back().first += s[i];
    }
  }
  float w = 0;
  for (const auto& [t, lowered] : runs) w += text_width(font, lowered ? small : size, t);
  x = std::round(x - align * w);
  for (const auto& [t, lowered] : runs) {
    if (t.empty()) continue;
    const float h = lowered ? small : size;
    c.draw->AddText(font, h, ImVec2(x, std::round(y + (lowered ? 0.42f * size : 0.0f))),
                    col(colour), t.c_str());
    x += text_width(font, h, t);
  }
  return x;
}

void dashed_hline(Canvas& c, float x0, float x1, float y, ImU32 colour, float width, float dash) {
  for (float x = x0; x < x1; x += 2.0f * dash)
    c.draw->AddLine(ImVec2(x, y), ImVec2(std::min(x + dash, x1), y), colour, width);
}
void dashed_vline(Canvas& c, float x, float y0, float y1, ImU32 colour, float width, float dash) {
  for (float y = y0; y < y1; y += 2.0f * dash)
    c.draw->AddLine(ImVec2(x, y), ImVec2(x, std::min(y + dash, y1)), colour, width);
}

void panel(Canvas& c, const Box& box, const std::string& title) {
  const float fs = c.layout.font_px;
  c.draw->AddRect(ImVec2(box.x + 0.5f, box.y + 0.5f),
                  ImVec2(box.right() - 0.5f, box.bottom() - 0.5f), col(c.theme.border), 0.3f * fs,
                  0, 1.0f);
  c.title_right =
      text_sub(c, c.fonts.bold, box.x + 0.45f * fs, box.y + 0.3f * fs, c.theme.text, title);
}

// A small note right-aligned in the title row; false (nothing drawn) when it would touch the
// title, as on small frames.
bool title_note(Canvas& c, const Box& box, const std::string& note) {
  const float fs = c.layout.font_px, right = box.right() - 0.45f * fs;
  if (right - text_width(c.fonts.sans, 0.8f * fs, note) < c.title_right + 0.6f * fs) return false;
  text(c, c.fonts.sans, right, box.y + 0.4f * fs, c.theme.text_dim, note, 1.0f, 0.8f);
  return true;
}

// ---- Axes ----------------------------------------------------------------------------------

// Background, grid, frame and tick labels of a plot in `box`; `x_name` goes in the corner
// below the y labels, a shared power of ten of the y labels at the right of the title row.
// The data are drawn after, clipped to the area.
void axes(Canvas& c, const Box& box, const PlotMapping& m, const Ticks& xt, const Ticks& yt,
          const std::string& x_name, bool grid) {
  const float fs = c.layout.font_px;
  const Box& a = m.area;
  const TickFormat yf = tick_format(yt);
  for (std::size_t i = 0; i < yt.values.size(); ++i) {
    const double v = yt.values[i];
    const float y = std::round(m.py(v)) + 0.5f;
    if (grid) c.draw->AddLine(ImVec2(a.x, y), ImVec2(a.right(), y), col(c.theme.grid), 1.0f);
    const std::string label = yt.labels.empty() ? tick_label(v, yf) : yt.labels[i];
    text(c, c.fonts.sans, a.x - 0.3f * fs, y - 0.55f * fs, c.theme.text_dim, label, 1.0f, 0.85f);
  }
  std::vector<float> xs, widths;
  std::vector<std::string> labels;
  for (std::size_t i = 0; i < xt.values.size(); ++i) {
    const double v = xt.values[i];
    const float x = std::round(m.px(v)) + 0.5f;
    if (grid) c.draw->AddLine(ImVec2(x, a.y), ImVec2(x, a.bottom()), col(c.theme.grid), 1.0f);
    labels.push_back(xt.labels.empty() ? x_tick_label(v, xt) : xt.labels[i]);
    xs.push_back(x);
    widths.push_back(text_width(c.fonts.sans, 0.85f * fs, labels.back()));
  }
  const std::vector<float> lefts = x_tick_label_lefts(xs, widths, a.right(), fs);
  for (std::size_t i = 0; i < labels.size(); ++i)
    if (!std::isnan(lefts[i]))
      text(c, c.fonts.sans, lefts[i], a.bottom() + 0.2f * fs, c.theme.text_dim, labels[i], 0.0f,
           0.85f);
  c.draw->AddRect(ImVec2(a.x, a.y), ImVec2(a.right(), a.bottom()), col(c.theme.axis), 0.0f, 0,
                  1.0f);
  text(c, c.fonts.sans, box.x + 0.45f * fs, a.bottom() + 0.2f * fs, c.theme.text_dim, x_name, 0.0f,
       0.85f);
  if (yf.exponent != 0 && yt.labels.empty()) {  // "×10⁻³" above the y labels
    const std::string e = power_of_ten_text(yf.exponent);
    if (!title_note(c, box, e))  // else inside the plot's top-right corner
      text(c, c.fonts.sans, a.right() - 0.3f * fs, a.y + 0.2f * fs, c.theme.text_dim, e, 1.0f,
           0.8f);
  }
}

// A line of legend entries inside the plot's top-left corner, on a translucent box.
void legend(Canvas& c, const Box& a, float y, const std::vector<LegendEntry>& entries) {
  const float fs = c.layout.font_px, size = 0.85f * fs;
  float width = 0.4f * fs;
  for (const auto& e : entries) width += 1.5f * fs + text_width(c.fonts.sans, size, e.label);
  c.draw->AddRectFilled(ImVec2(a.x + 0.3f * fs, y), ImVec2(a.x + 0.3f * fs + width, y + 1.2f * fs),
                        col(c.theme.background, 0.85f), 0.2f * fs);
  float x = a.x + 0.6f * fs;
  const float mid = y + 0.6f * fs;
  for (const auto& e : entries) {
    if (e.dot) {
      const float h = 0.5f * c.marker.size;
      c.draw->AddImage(c.marker.texture, ImVec2(x + 0.4f * fs - h, mid - h),
                       ImVec2(x + 0.4f * fs + h, mid + h), c.marker.uv0, c.marker.uv1,
                       col(e.colour));
    } else {
      c.draw->AddLine(ImVec2(x, mid), ImVec2(x + 0.9f * fs, mid), col(e.colour), c.layout.line_px);
    }
    x = text(c, c.fonts.sans, x + 1.15f * fs, y + 0.1f * fs, c.theme.text, e.label, 0.0f, 0.85f) +
        0.35f * fs;
  }
}

// A polyline through (t[i], v[i]), clipped by the caller's clip rectangle, with few vertices
// but short segments. llvmpipe pays per triangle (the histories hold several samples per
// pixel), and per 16x16 block of a triangle's bounding box, which for a long diagonal
// segment is mostly empty. So: M4 decimation first (per pixel column only the first, lowest,
// highest and last sample), then a greedy pass that drops points within a third of a pixel of
// the chord, keeping segments under kSegment pixels (and runs short, so the cost is linear).
void polyline(Canvas& c, const PlotMapping& m, const std::vector<double>& t,
              const std::vector<double>& v, ImU32 colour, float width) {
  std::vector<ImVec2> dense;
  dense.reserve(std::min<std::size_t>(t.size(), 4 * static_cast<std::size_t>(m.area.w) + 8));
  for (std::size_t i = 0; i < t.size();) {
    const float column = std::floor(m.px(t[i]));
    std::size_t end = i + 1, lo = i, hi = i;
    for (; end < t.size() && std::floor(m.px(t[end])) == column; ++end) {
      if (v[end] < v[lo]) lo = end;
      if (v[end] > v[hi]) hi = end;
    }
    const std::size_t keep[4] = {i, std::min(lo, hi), std::max(lo, hi), end - 1};
    for (int k = 0; k < 4; ++k)
      if (k == 0 || keep[k] != keep[k - 1])
        dense.push_back(ImVec2(m.px(t[keep[k]]), m.py(v[keep[k]])));
    i = end;
  }
  constexpr float kTolerance2 = 0.33f * 0.33f, kSegment = 12.0f;
  constexpr std::size_t kRun = 32;
  std::vector<ImVec2> points;
  std::size_t anchor = 0;
  if (!dense.empty()) points.push_back(dense[0]);
  for (std::size_t end = 2; end < dense.size(); ++end) {
    const float dx = dense[end].x - dense[anchor].x, dy = dense[end].y - dense[anchor].y;
    bool fits = end - anchor <= kRun && dx * dx + dy * dy <= kSegment * kSegment;
    for (std::size_t k = anchor + 1; fits && k < end; ++k)
      fits = distance2(dense[k], dense[anchor], dense[end]) <= kTolerance2;
    if (!fits) {
      anchor = end - 1;
      points.push_back(dense[anchor]);
    }
  }
  if (dense.size() >= 2) points.push_back(dense.back());
  if (points.size() >= 2)
    c.draw->AddPolyline(points.data(), static_cast<int>(points.size()), colour, 0, width);
}

void time_cursor(Canvas& c, const PlotMapping& m) {
  const float x = std::round(m.px(c.data.tau)) + 0.5f;
  c.draw->AddLine(ImVec2(x, m.area.y), ImVec2(x, m.area.bottom()), col(c.theme.cursor, 0.7f), 1.0f);
}

}  // namespace cb::overlay_detail
