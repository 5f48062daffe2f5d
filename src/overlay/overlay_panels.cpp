// The overlay's panels. Index: helpers (colours, text, ticks); axes; the HUD; the phi plot
// (Fig. 4(a)); the energy plot (Fig. 4(b)); the space-time picture; the mode bars.
//
// Every plot maps data to pixels through overlay_layout.h's PlotMapping, the same functions
// the tests use to find where a point lands.
#include "overlay/overlay_panels.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <string>
#include <vector>

namespace cb::overlay_detail {

namespace {

// ---- Helpers -------------------------------------------------------------------------------

constexpr OverlayRgb kText{224, 224, 230};
constexpr OverlayRgb kDim{150, 153, 160};
constexpr OverlayRgb kBorder{58, 60, 67};
constexpr OverlayRgb kGrid{40, 42, 48};
constexpr OverlayRgb kFrame{78, 80, 88};
constexpr OverlayRgb kThreshold{213, 94, 0};  // Okabe-Ito vermillion
constexpr OverlayRgb kCursor{110, 112, 120};
constexpr OverlayRgb kTotal{236, 236, 240};
constexpr OverlayRgb kKinetic{204, 121, 167};    // Okabe-Ito reddish purple
constexpr OverlayRgb kPotential{240, 228, 66};   // Okabe-Ito yellow
constexpr OverlayRgb kBar{86, 180, 233};

ImU32 col(const OverlayRgb& c, float alpha = 1.0f) {
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
           const std::string& s, float align = 0.0f, float scale = 1.0f) {
  const float size = c.layout.font_px * scale;
  const float w = text_width(font, size, s);
  x = std::round(x - align * w);
  c.draw->AddText(font, size, ImVec2(x, std::round(y)), col(colour), s.c_str());
  return x + w;
}

// Ticks at 1, 2 or 5 times a power of ten, at most about `count` of them in [lo, hi].
struct Ticks {
  std::vector<double> values;
  double step = 1.0;
};
Ticks nice_ticks(double lo, double hi, int count) {
  Ticks t;
  const double raw = (hi - lo) / std::max(1, count);
  if (!(raw > 0) || !std::isfinite(raw)) return t;
  const double mag = std::pow(10.0, std::floor(std::log10(raw)));
  const double norm = raw / mag;
  t.step = (norm <= 1.0 ? 1.0 : norm <= 2.0 ? 2.0 : norm <= 5.0 ? 5.0 : 10.0) * mag;
  for (double v = std::ceil(lo / t.step) * t.step; v <= hi + 1e-9 * t.step; v += t.step)
    t.values.push_back(std::abs(v) < 1e-9 * t.step ? 0.0 : v);
  return t;
}

// Tick labels; very small or large values share a power of ten shown once by the axis.
struct TickFormat {
  int exponent = 0;  // labels are value / 10^exponent
  int decimals = 0;
};
TickFormat tick_format(const Ticks& t) {
  TickFormat f;
  double largest = 0;
  for (double v : t.values) largest = std::max(largest, std::abs(v));
  if (largest > 0 && (largest < 1e-2 || largest >= 1e4))
    f.exponent = static_cast<int>(std::floor(std::log10(largest)));
  const double step = t.step / std::pow(10.0, f.exponent);
  f.decimals = std::max(0, static_cast<int>(std::ceil(-std::log10(step) - 1e-9)));
  return f;
}
std::string tick_label(double v, const TickFormat& f) {
  const std::string s = format("%.*f", f.decimals, v / std::pow(10.0, f.exponent));
  return s == "-0" ? "0" : s[0] == '-' ? "\u2212" + s.substr(1) : s;  // a true minus sign
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
  c.draw->AddRect(ImVec2(box.x + 0.5f, box.y + 0.5f), ImVec2(box.right() - 0.5f, box.bottom() - 0.5f),
                  col(kBorder), 0.3f * fs, 0, 1.0f);
  c.title_right = text(c, c.fonts.bold, box.x + 0.45f * fs, box.y + 0.3f * fs, kText, title);
}

// A small note right-aligned in the title row; false (nothing drawn) when it would touch the
// title, as on small frames.
bool title_note(Canvas& c, const Box& box, const std::string& note) {
  const float fs = c.layout.font_px, right = box.right() - 0.45f * fs;
  if (right - text_width(c.fonts.sans, 0.8f * fs, note) < c.title_right + 0.6f * fs) return false;
  text(c, c.fonts.sans, right, box.y + 0.4f * fs, kDim, note, 1.0f, 0.8f);
  return true;
}

// ---- Axes ----------------------------------------------------------------------------------

// Background, grid, frame and tick labels of a plot in `box`; `x_name` goes in the corner
// below the y labels, a shared power of ten of the y labels at the right of the title row.
// The data are drawn after, clipped to the area.
void axes(Canvas& c, const Box& box, const PlotMapping& m, const Ticks& xt, const Ticks& yt,
          const std::string& x_name) {
  const float fs = c.layout.font_px;
  const Box& a = m.area;
  const TickFormat yf = tick_format(yt), xf = tick_format(xt);
  for (double v : yt.values) {
    const float y = std::round(m.py(v)) + 0.5f;
    c.draw->AddLine(ImVec2(a.x, y), ImVec2(a.right(), y), col(kGrid), 1.0f);
    text(c, c.fonts.mono, a.x - 0.3f * fs, y - 0.55f * fs, kDim, tick_label(v, yf), 1.0f, 0.85f);
  }
  for (double v : xt.values) {
    const float x = std::round(m.px(v)) + 0.5f;
    c.draw->AddLine(ImVec2(x, a.y), ImVec2(x, a.bottom()), col(kGrid), 1.0f);
    // The last label may not run past the panel: right-align it at the edge.
    const std::string label = tick_label(v, xf);
    const float w = text_width(c.fonts.mono, 0.85f * fs, label);
    const float align = x + 0.5f * w > a.right() + 0.5f * fs ? 1.0f : 0.5f;
    text(c, c.fonts.mono, x, a.bottom() + 0.2f * fs, kDim, label, align, 0.85f);
  }
  c.draw->AddRect(ImVec2(a.x, a.y), ImVec2(a.right(), a.bottom()), col(kFrame), 0.0f, 0, 1.0f);
  text(c, c.fonts.sans, box.x + 0.45f * fs, a.bottom() + 0.2f * fs, kDim, x_name, 0.0f, 0.85f);
  if (yf.exponent != 0) {  // "×10⁻³" above the y labels
    std::string e = "\u00D710";
    for (char ch : std::to_string(yf.exponent)) {
      static const char* const kSup[10] = {"\u2070", "\u00B9", "\u00B2", "\u00B3", "\u2074",
                                           "\u2075", "\u2076", "\u2077", "\u2078", "\u2079"};
      e += ch == '-' ? "\u207B" : kSup[ch - '0'];
    }
    if (!title_note(c, box, e))  // else inside the plot's top-right corner
      text(c, c.fonts.sans, a.right() - 0.3f * fs, a.y + 0.2f * fs, kDim, e, 1.0f, 0.8f);
  }
}

// A line of legend entries inside the plot's top-left corner, on a translucent box.
struct LegendEntry {
  OverlayRgb colour;
  std::string label;
  bool dot;  // a dot (points) rather than a dash (a line)
};
void legend(Canvas& c, const Box& a, float y, const std::vector<LegendEntry>& entries) {
  const float fs = c.layout.font_px, size = 0.85f * fs;
  float width = 0.4f * fs;
  for (const auto& e : entries) width += 1.5f * fs + text_width(c.fonts.sans, size, e.label);
  c.draw->AddRectFilled(ImVec2(a.x + 0.3f * fs, y), ImVec2(a.x + 0.3f * fs + width, y + 1.2f * fs),
                        col(kOverlayBackground, 0.85f), 0.2f * fs);
  float x = a.x + 0.6f * fs;
  const float mid = y + 0.6f * fs;
  for (const auto& e : entries) {
    if (e.dot) {
      const float h = 0.5f * c.marker.size;
      c.draw->AddImage(c.marker.texture, ImVec2(x + 0.4f * fs - h, mid - h),
                       ImVec2(x + 0.4f * fs + h, mid + h), c.marker.uv0, c.marker.uv1, col(e.colour));
    } else {
      c.draw->AddLine(ImVec2(x, mid), ImVec2(x + 0.9f * fs, mid), col(e.colour), c.layout.line_px);
    }
    x = text(c, c.fonts.sans, x + 1.15f * fs, y + 0.1f * fs, kText, e.label, 0.0f, 0.85f) +
        0.35f * fs;
  }
}

// Squared distance from p to the segment a-b.
float distance2(const ImVec2& p, const ImVec2& a, const ImVec2& b) {
  const float dx = b.x - a.x, dy = b.y - a.y, len2 = dx * dx + dy * dy;
  float u = len2 > 0 ? ((p.x - a.x) * dx + (p.y - a.y) * dy) / len2 : 0.0f;
  u = std::clamp(u, 0.0f, 1.0f);
  const float ex = a.x + u * dx - p.x, ey = a.y + u * dy - p.y;
  return ex * ex + ey * ey;
}

// A polyline through (t[i], v[i]), clipped by the caller's clip rectangle, with as few
// vertices as keep it within a third of a pixel: llvmpipe pays per triangle, and the
// histories hold several samples per pixel (the exact lines are piecewise almost straight).
// First M4 decimation (per pixel column only the first, lowest, highest and last sample),
// then a greedy pass that drops points within the tolerance of the chord (runs of at most
// 32 points, so the cost stays linear).
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
  constexpr float kTolerance2 = 0.33f * 0.33f;
  constexpr std::size_t kRun = 32;
  std::vector<ImVec2> points;
  std::size_t anchor = 0;
  if (!dense.empty()) points.push_back(dense[0]);
  for (std::size_t end = 2; end < dense.size(); ++end) {
    bool fits = end - anchor <= kRun;
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
  c.draw->AddLine(ImVec2(x, m.area.y), ImVec2(x, m.area.bottom()), col(kCursor, 0.7f), 1.0f);
}

}  // namespace

// ---- The HUD -----------------------------------------------------------------------------

void draw_hud(Canvas& c) {
  const Box& box = c.layout.hud;
  const OverlayData& d = c.data;
  const float fs = c.layout.font_px, line = 1.38f * fs;
  c.draw->AddRect(ImVec2(box.x + 0.5f, box.y + 0.5f), ImVec2(box.right() - 0.5f, box.bottom() - 0.5f),
                  col(kBorder), 0.3f * fs, 0, 1.0f);
  c.draw->PushClipRect(ImVec2(box.x, box.y), ImVec2(box.right(), box.bottom()), true);
  const float x = box.x + 0.6f * fs, value_x = x + 2.2f * fs;
  float y = box.y + 0.45f * fs;
  {  // the title, wrapped to the panel (a long one takes two lines)
    const std::string title = d.title.empty() ? std::string("chainbreak") : d.title;
    const float size = 1.15f * fs, wrap = box.right() - x - 0.4f * fs;
    c.draw->AddText(c.fonts.bold, size, ImVec2(std::round(x), std::round(y)), col(kText),
                    title.c_str(), nullptr, wrap);
    y += c.fonts.bold->CalcTextSizeA(size, FLT_MAX, wrap, title.c_str()).y + 0.35f * line;
  }
  std::string params = format("N = %d   \u03B3 = %g", d.beads, d.gamma);
  params += d.phi_c > 0 ? format("   \u03C6_c = %g", d.phi_c) : std::string("   unbreakable");
  text(c, c.fonts.sans, x, y, kDim, params, 0.0f, 0.9f);
  y += line;
  // Label in the proportional font, value in the monospaced one so digits do not jitter.
  const auto row = [&](const std::string& label, const std::string& value) {
    text(c, c.fonts.sans, x, y, kText, label);
    text(c, c.fonts.mono, value_x, y, kText, value);
    y += line;
  };
  row("\u03C4", format("%.2f", d.tau));
  if (std::isfinite(d.seconds)) row("t", format("%.5g s", d.seconds));
  row("f", format("%.4g", d.force));
  row("\u03B5", format("%.4g", d.energy));  // Eq. (energy), per particle
  const auto part = [&](const char* label, double value) {
    text(c, c.fonts.sans, value_x, y, kDim, label, 0.0f, 0.85f);
    text(c, c.fonts.mono, value_x + 5.2f * fs, y, kDim, format("%.4g", value), 0.0f, 0.85f);
    y += 0.9f * line;
  };
  part("kinetic", d.kinetic);
  part("potential", d.potential);
  y += 0.1f * line;
  text(c, c.fonts.sans, x, y, kText, d.breaks.empty() ? "no break yet" : "breaks");
  y += line;
  // As many breaks as fit; the last line counts the rest.
  const int fit = std::max(1, static_cast<int>((box.bottom() - y - 0.3f * fs) / line));
  const int count = static_cast<int>(d.breaks.size());
  for (int i = 0; i < count && i < fit; ++i) {
    const OverlayBreak& b = d.breaks[i];
    std::string s = b.spring == 0 ? std::string("pull string")
                                  : "spring " + std::to_string(b.spring);
    s += format(" at \u03C4 = %.2f", b.tau);
    if (i == fit - 1 && count > fit) s = format("+%d more", count - i);
    text(c, c.fonts.mono, x + 0.6f * fs, y, OverlayRgb{255, 200, 90}, s, 0.0f, 0.9f);
    y += line;
  }
  c.draw->PopClipRect();
}

// ---- phi_1, phi_N/2, phi_N vs tau: the paper's Fig. 4(a) -----------------------------------

void draw_phi_plot(Canvas& c) {
  const OverlayData& d = c.data;
  const float fs = c.layout.font_px;
  panel(c, c.layout.phi, "Extension \u03C6\u2C7C(\u03C4)");
  const PlotMapping m = phi_mapping(c.layout, d);
  const Box& a = m.area;
  axes(c, c.layout.phi, m, nice_ticks(0.0, d.tau_end, 6), nice_ticks(d.phi_lo, d.phi_hi, 5),
       "\u03C4");
  c.draw->PushClipRect(ImVec2(a.x, a.y), ImVec2(a.right(), a.bottom()), true);
  time_cursor(c, m);
  if (d.phi_c > 0) {  // Eq. (break): the threshold
    const float w = std::max(1.0f, 0.6f * c.layout.line_px);
    for (double level : {d.phi_c, -d.phi_c}) {
      if (level < 0 && !d.threshold_both_signs) continue;
      if (level < d.phi_lo || level > d.phi_hi) continue;
      const float y = m.py(level);
      dashed_hline(c, a.x, a.right(), y, col(kThreshold), w, 0.5f * fs);
      text(c, c.fonts.sans, a.right() - 0.3f * fs, level > 0 ? y - 1.05f * fs : y + 0.1f * fs,
           kThreshold, level > 0 ? "\u03C6_c" : "\u2212\u03C6_c", 1.0f, 0.85f);
    }
  }
  // The exact lines under the RK4 points, each in its spring's colour, dimmed so that the
  // points stand out on them.
  for (int s = 0; d.exact && s < d.spring_count; ++s)
    polyline(c, m, d.exact_tau, d.exact_phi[s], col(kOverlaySeries[s], kOverlayExactLineAlpha),
             c.layout.line_px);
  if (std::isfinite(d.exact_end)) {  // the exact solution is the unbroken chain's
    const float x = m.px(d.exact_end);
    dashed_vline(c, x, a.y, a.bottom(), col(kThreshold, 0.8f), 1.0f, 0.3f * fs);
    const std::string note = format("exact lines end: first break, \u03C4 = %.2f", d.exact_end);
    const bool left = x + text_width(c.fonts.sans, 0.8f * fs, note) + 0.5f * fs > a.right();
    text(c, c.fonts.sans, left ? x - 0.3f * fs : x + 0.3f * fs, a.bottom() - 1.3f * fs, kDim, note,
         left ? 1.0f : 0.0f, 0.8f);
  }
  // The points, newest first so the newest always shows; one every ~1.5 diameters at most.
  const float h = 0.5f * c.marker.size, spacing = 1.5f * c.marker.size;
  for (int s = 0; s < d.spring_count; ++s) {
    const std::vector<double>& v = d.phi[s];
    float last_x = FLT_MAX;
    for (std::size_t i = d.history_tau.size(); i-- > 0;) {
      const float x = m.px(d.history_tau[i]);
      if (std::abs(last_x - x) < spacing) continue;
      last_x = x;
      const float y = m.py(v[i]);
      c.draw->AddImage(c.marker.texture, ImVec2(x - h, y - h), ImVec2(x + h, y + h),
                       c.marker.uv0, c.marker.uv1, col(kOverlaySeries[s]));
    }
  }
  c.draw->PopClipRect();
  std::vector<LegendEntry> entries;
  for (int s = 0; s < d.spring_count; ++s)
    entries.push_back({kOverlaySeries[s], "\u03C6" + subscript(d.springs[s]), true});
  legend(c, a, a.y + 0.3f * fs, entries);
  text(c, c.fonts.sans, a.x + 0.6f * fs, a.y + 1.65f * fs, kDim,
       d.exact ? "dots: RK4 \u00B7 lines: exact" : "dots: RK4 (no exact lines above N = 1024)",
       0.0f, 0.8f);
}

// ---- Energy per particle vs tau: Fig. 4(b), Eq. (energy) -----------------------------------

void draw_energy_plot(Canvas& c) {
  const OverlayData& d = c.data;
  const float fs = c.layout.font_px;
  panel(c, c.layout.energy, "Energy per particle \u03B5(\u03C4)");
  const PlotMapping m = energy_mapping(c.layout, d);
  const Box& a = m.area;
  axes(c, c.layout.energy, m, nice_ticks(0.0, d.tau_end, 4), nice_ticks(0.0, d.energy_hi, 5),
       "\u03C4");
  c.draw->PushClipRect(ImVec2(a.x, a.y), ImVec2(a.right(), a.bottom()), true);
  time_cursor(c, m);
  const float w = c.layout.line_px;
  polyline(c, m, d.history_tau, d.energy_kinetic, col(kKinetic), w);
  polyline(c, m, d.history_tau, d.energy_potential, col(kPotential), w);
  polyline(c, m, d.history_tau, d.energy_total, col(kTotal), w);
  c.draw->PopClipRect();
  legend(c, a, a.y + 0.3f * fs,
         {{kTotal, "total", false}, {kKinetic, "kin.", false}, {kPotential, "pot.", false}});
}

// ---- The space-time picture: strain over springs and time ----------------------------------

std::uint32_t spacetime_texel(float s) {
  return col(overlay_strain_rgb(s));
}

unsigned char marker_coverage(int x, int y, int size, float radius) {
  // The area of the texel inside the disc, approximated by the distance of its centre from
  // the edge (a 1-texel ramp): the usual antialiased edge, the interior exactly opaque.
  const float c = 0.5f * static_cast<float>(size);
  const float d = std::hypot(x + 0.5f - c, y + 0.5f - c);
  return static_cast<unsigned char>(std::lround(255.0f * std::clamp(radius + 0.5f - d, 0.0f, 1.0f)));
}

void draw_spacetime(Canvas& c, ImTextureID texture, int texture_rows) {
  const OverlayData& d = c.data;
  panel(c, c.layout.spacetime, "Strain \u03C6\u2C7C/\u03C6_c");
  const PlotMapping m = spacetime_mapping(c.layout, d);
  const Box& a = m.area;
  Ticks xt = nice_ticks(0.0, d.beads, 4);
  axes(c, c.layout.spacetime, m, xt, nice_ticks(0.0, d.tau_end, 5), "j");
  const int rows = d.spacetime_rows();
  if (rows > 0 && texture_rows > 0) {
    // Row r covers tau_r +- half a row: tau runs up, the newest row on top.
    const double half = 0.5 * d.spacetime_stride * d.tau_per_frame;
    const float top = m.py(d.spacetime_tau.back() + half);
    const float bottom = m.py(d.spacetime_tau.front() - half);
    const float v_top = static_cast<float>(rows) / static_cast<float>(texture_rows);
    c.draw->PushClipRect(ImVec2(a.x, a.y), ImVec2(a.right(), a.bottom()), true);
    c.draw->AddImage(texture, ImVec2(a.x, top), ImVec2(a.right(), bottom), ImVec2(0.0f, v_top),
                     ImVec2(1.0f, 0.0f));
    c.draw->PopClipRect();
    c.draw->AddRect(ImVec2(a.x, a.y), ImVec2(a.right(), a.bottom()), col(kFrame), 0.0f, 0, 1.0f);
  }
  title_note(c, c.layout.spacetime, "wall \u2192 pulled end");
}

// ---- Normal modes ---------------------------------------------------------------------------

void draw_modes(Canvas& c) {
  const OverlayData& d = c.data;
  const float fs = c.layout.font_px;
  panel(c, c.layout.modes, "Normal modes A\u2099");
  const PlotMapping m = modes_mapping(c.layout, d);
  const Box& a = m.area;
  const int count = static_cast<int>(d.mode_amplitude.size());
  Ticks xt;
  xt.step = count > 8 ? 5.0 : 1.0;
  for (int n = 0; n < count; n += static_cast<int>(xt.step)) xt.values.push_back(n);
  Ticks yt;
  yt.step = 0.5;
  yt.values = {0.0, 0.5, 1.0};
  axes(c, c.layout.modes, m, xt, yt, "n");
  if (d.mode_scale > 0) {
    const float half = 0.36f * a.w / std::max(1, count);
    for (int n = 0; n < count; ++n) {
      const float x = m.px(n);
      const float y = m.py(d.mode_amplitude[n] / d.mode_scale);
      c.draw->AddRectFilled(ImVec2(x - half, y), ImVec2(x + half, a.bottom()), col(kBar));
      const float peak = m.py(d.mode_peak[n] / d.mode_scale);  // the largest so far
      c.draw->AddLine(ImVec2(x - half, peak), ImVec2(x + half, peak), col(kText), 1.5f);
    }
  }
  const Box& box = c.layout.modes;
  text(c, c.fonts.sans, box.x + 0.45f * fs, box.y + 1.45f * fs, kDim,
       "\u221A(a\u2099\u2032\u00B2 + \u03A9\u2099\u00B2a\u2099\u00B2): bar now, tick peak", 0.0f,
       0.75f);
}

}  // namespace cb::overlay_detail

namespace cb {

OverlayRgb overlay_strain_rgb(float s) {
  if (std::isnan(s)) return kOverlayBackground;
  const Color k = strain_color(s);
  const auto byte = [](float v) {
    return static_cast<std::uint8_t>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
  };
  return OverlayRgb{byte(k.r), byte(k.g), byte(k.b)};
}

}  // namespace cb
