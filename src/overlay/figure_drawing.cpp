// The FigureDrawer: one ImGui frame per figure, every panel drawn through ImDrawList with the
// overlay's primitives (overlay_plot.h).
#include "overlay/figure_drawing.h"

#include <imgui.h>
#include <imgui_impl_opengl3.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "overlay/overlay_panels.h"
#include "overlay/overlay_plot.h"

namespace cb {

namespace {

using namespace overlay_detail;

OverlayRgb rgb(const FigureRgb& c) {
  return OverlayRgb{c.r, c.g, c.b};
}

// Round-number ticks, or on a log axis 1, 2 and 5 times the powers of ten inside it.
Ticks axis_ticks(const Axis& axis, int count) {
  Ticks t;
  if (!axis.ticks.empty()) {
    for (const AxisTick& tick : axis.ticks) {
      t.values.push_back(figure_axis_value(axis, tick.value));
      t.labels.push_back(tick.label);
    }
    return t;
  }
  if (!axis.log) return nice_ticks(axis.lo, axis.hi, count);
  for (int e = static_cast<int>(std::floor(std::log10(axis.lo))); std::pow(10.0, e) <= axis.hi; ++e)
    for (double m : {1.0, 2.0, 5.0}) {
      const double v = m * std::pow(10.0, e);
      if (v < axis.lo * (1 - 1e-12) || v > axis.hi * (1 + 1e-12)) continue;
      t.values.push_back(std::log10(v));
      t.labels.push_back(format("%g", v));
    }
  return t;
}

struct PanelDraw {
  Canvas& c;
  const Panel& p;
  const FigurePanelLayout& l;
  float fs, line;

  float px(double x) const { return l.mapping.px(figure_axis_value(p.x, x)); }
  float py(double y) const { return l.mapping.py(y); }

  void heatmap() const {
    const Heatmap& h = p.heatmap;
    // Cell edges on whole pixels: neighbouring cells share their edge, no seams, no overlap.
    std::vector<float> xs, ys;
    for (int i = 0; i <= h.columns; ++i)
      xs.push_back(std::round(px(h.x_lo + (h.x_hi - h.x_lo) * i / h.columns)));
    for (int i = 0; i <= h.rows; ++i)
      ys.push_back(std::round(py(h.y_lo + (h.y_hi - h.y_lo) * i / h.rows)));
    for (int r = 0; r < h.rows; ++r)
      for (int k = 0; k < h.columns; ++k) {
        const float s =
            static_cast<float>(h.values[static_cast<std::size_t>(r) * h.columns + k] / h.scale);
        c.draw->AddRectFilled(ImVec2(xs[k], ys[r + 1]), ImVec2(xs[k + 1], ys[r]),
                              col(overlay_strain_rgb(std::clamp(s, -1.0f, 1.0f), ThemeName::Dark)));
      }
  }

  void colour_bar() const {
    const Heatmap& h = p.heatmap;
    // The colour bar: value / scale from -1 (bottom) to +1 (top).
    const Box& b = l.colour_bar;
    for (int y = 0; y < static_cast<int>(b.h); ++y) {
      const float s = 1.0f - 2.0f * (y + 0.5f) / b.h;
      c.draw->AddRectFilled(ImVec2(b.x, b.y + y), ImVec2(b.right(), b.y + y + 1),
                            col(overlay_strain_rgb(s, ThemeName::Dark)));
    }
    c.draw->AddRect(ImVec2(b.x, b.y), ImVec2(b.right(), b.bottom()), col(c.theme.axis));
    for (double v : {-1.0, -0.5, 0.0, 0.5, 1.0}) {
      const float y = b.y + static_cast<float>(0.5 * (1.0 - v)) * b.h;
      text(c, c.fonts.mono, b.right() + 0.3f * fs, y - 0.5f * fs, c.theme.text_dim, format("%g", v * h.scale),
           0.0f, 0.85f);
    }
    text_sub(c, c.fonts.sans, b.x + 0.5f * b.w, b.y - 1.3f * fs, c.theme.text, h.label, 0.5f, 0.85f);
  }

  void line_series(const Series& s) const {
    std::vector<double> x, y;
    const auto flush = [&] {
      if (x.size() >= 2) polyline(c, l.mapping, x, y, col(rgb(s.colour)), line);
      x.clear();
      y.clear();
    };
    for (std::size_t i = 0; i < s.x.size(); ++i) {
      if (!std::isfinite(s.y[i])) {
        flush();
        continue;
      }
      x.push_back(figure_axis_value(p.x, s.x[i]));
      y.push_back(s.y[i]);
    }
    flush();
  }

  void series(const Series& s) const {
    const Box& a = l.mapping.area;
    const ImU32 colour = col(rgb(s.colour));
    switch (s.style) {
      case SeriesStyle::Line:
        line_series(s);
        break;
      case SeriesStyle::Points:
        for (std::size_t i = 0; i < s.x.size(); ++i) {
          if (!std::isfinite(s.y[i])) continue;
          const float h = 0.5f * c.marker.size, x = px(s.x[i]), y = py(s.y[i]);
          c.draw->AddImage(c.marker.texture, ImVec2(x - h, y - h), ImVec2(x + h, y + h),
                           c.marker.uv0, c.marker.uv1, colour);
        }
        break;
      case SeriesStyle::Band: {
        // Without antialiased fringes: adjacent quads would double their alpha at each seam.
        const ImDrawListFlags flags = c.draw->Flags;
        c.draw->Flags &= ~ImDrawListFlags_AntiAliasedFill;
        const ImU32 fill = col(rgb(s.colour), 0.35f);
        for (std::size_t i = 0; i + 1 < s.x.size(); ++i) {
          if (!std::isfinite(s.y[i] + s.y2[i] + s.y[i + 1] + s.y2[i + 1])) continue;
          c.draw->AddQuadFilled(
              ImVec2(px(s.x[i]), py(s.y[i])), ImVec2(px(s.x[i + 1]), py(s.y[i + 1])),
              ImVec2(px(s.x[i + 1]), py(s.y2[i + 1])), ImVec2(px(s.x[i]), py(s.y2[i])), fill);
        }
        c.draw->Flags = flags;
        break;
      }
      case SeriesStyle::XSpans:
        for (std::size_t i = 0; i < s.x.size(); ++i) {
          const float x0 = std::round(px(s.x[i]));
          const float x1 = std::max(x0 + 1.0f, std::round(px(s.x2[i])));
          c.draw->AddRectFilled(ImVec2(x0, a.y), ImVec2(x1, a.bottom()), col(rgb(s.colour), 0.3f));
        }
        break;
      case SeriesStyle::VLines:
        for (double x : s.x)
          dashed_vline(c, std::round(px(x)) + 0.5f, a.y, a.bottom(), colour, 1.0f, 0.4f * fs);
        break;
      case SeriesStyle::HLines:
        for (double y : s.y)
          dashed_hline(c, a.x, a.right(), std::round(py(y)) + 0.5f, colour, 1.5f, 0.4f * fs);
        break;
    }
  }

  // As many entries a row as fit in the plot's width, in the chosen corner.
  void legends() const {
    const Box& a = l.mapping.area;
    std::vector<std::vector<LegendEntry>> rows(1);
    std::vector<float> widths(1, 0.4f * fs);  // as legend() measures a row
    for (const Series& s : p.series) {
      if (s.label.empty()) continue;
      const float w = 1.5f * fs + text_width(c.fonts.sans, 0.85f * fs, s.label);
      if (!rows.back().empty() && widths.back() + w > a.w - 1.2f * fs) {
        rows.emplace_back();
        widths.push_back(0.4f * fs);
      }
      rows.back().push_back({rgb(s.colour), s.label, s.style == SeriesStyle::Points});
      widths.back() += w;
    }
    for (std::size_t r = 0; r < rows.size(); ++r) {
      if (rows[r].empty()) continue;
      Box at = a;
      float y = a.y + 0.3f * fs + 1.3f * fs * static_cast<float>(r);
      if (p.legend == Panel::Legend::BottomRight) {
        at.x = a.right() - widths[r] - 0.6f * fs;
        y = a.bottom() - 0.3f * fs - 1.3f * fs * static_cast<float>(rows.size() - r);
      }
      legend(c, at, y, rows[r]);
    }
  }

  void draw() const {
    const Box& a = l.mapping.area;
    if (p.inset) {  // cover what lies below it
      c.draw->AddRectFilled(ImVec2(l.box.x, l.box.y), ImVec2(l.box.right(), l.box.bottom()),
                            col(c.theme.background));
    }
    panel(c, l.box, p.title);
    axes(c, l.box, l.mapping, axis_ticks(p.x, 10), axis_ticks(p.y, 8), "", p.heatmap.empty());
    text_sub(c, c.fonts.sans, a.x + 0.5f * a.w, a.bottom() + 1.45f * fs, c.theme.text, p.x.label, 0.5f,
             0.9f);
    text_sub(c, c.fonts.sans, a.x, a.y - 1.3f * fs, c.theme.text, p.y.label, 0.0f, 0.9f);
    c.draw->PushClipRect(ImVec2(a.x, a.y), ImVec2(a.right(), a.bottom()), true);
    if (!p.heatmap.empty()) heatmap();
    for (const Series& s : p.series) series(s);
    for (const Note& n : p.notes)
      text_sub(c, c.fonts.sans, px(n.x), py(n.y) - 0.45f * fs, rgb(n.colour), n.text, 0.0f, 0.85f);
    c.draw->PopClipRect();
    if (!p.heatmap.empty()) colour_bar();
    c.draw->AddRect(ImVec2(a.x, a.y), ImVec2(a.right(), a.bottom()), col(c.theme.axis), 0.0f, 0, 1.0f);
    legends();
  }
};

}  // namespace

struct FigureDrawer::Impl {
  int width = 0, height = 0;
  ImGuiContext* context = nullptr;
  OverlayLayout layout;  // font_px and line_px for the primitives
  OverlayData no_data;   // the primitives' canvas wants one; figures use none of it
  Fonts fonts;
  Marker marker;
  bool backend = false;

  ~Impl() {
    if (!context) return;
    ImGuiContext* previous = ImGui::GetCurrentContext();
    ImGui::SetCurrentContext(context);
    if (backend) ImGui_ImplOpenGL3_Shutdown();
    ImGui::DestroyContext(context);
    ImGui::SetCurrentContext(previous == context ? nullptr : previous);
  }
};

FigureDrawer::FigureDrawer(int width, int height) : impl_(std::make_unique<Impl>()) {
  Impl& im = *impl_;
  im.width = width;
  im.height = height;
  im.layout.font_px = figure_font_px(height);
  im.layout.line_px = std::max(2.0f, std::round(0.0025f * static_cast<float>(height)));
  ImGuiContext* previous = ImGui::GetCurrentContext();
  im.context = ImGui::CreateContext();
  ImGuiIO& io = ImGui::GetIO();
  configure_headless_io(io, static_cast<float>(width), static_cast<float>(height), 1.0f / 30.0f);
  im.fonts = load_fonts(*io.Fonts, im.layout.font_px, im.marker);
  if (!ImGui_ImplOpenGL3_Init("#version 330"))
    throw std::runtime_error("Dear ImGui's OpenGL3 backend did not start");
  im.backend = true;
  ImGui::SetCurrentContext(previous);
}

FigureDrawer::~FigureDrawer() = default;

void FigureDrawer::draw(const Figure& figure) {
  Impl& im = *impl_;
  ImGuiContext* previous = ImGui::GetCurrentContext();
  ImGui::SetCurrentContext(im.context);
  ImGui_ImplOpenGL3_NewFrame();  // uploads the font atlas on first use
  ImGui::NewFrame();
  im.marker.texture = ImGui::GetIO().Fonts->TexID;
  Canvas canvas{Pass::Static, ImGui::GetBackgroundDrawList(), im.fonts, im.marker, im.layout,
                im.no_data, cb::theme(ThemeName::Dark)};
  for (const Panel& p : figure.panels) {
    const FigurePanelLayout l = figure_panel_layout(p, im.width, im.height);
    PanelDraw{canvas, p, l, im.layout.font_px, im.layout.line_px}.draw();
  }
  ImGui::Render();
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
  ImGui::SetCurrentContext(previous);
}

}  // namespace cb
