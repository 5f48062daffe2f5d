// draw_figure: every part of a figure, in the order they cover each other: the plot area, its
// grid, the heatmap, the series (clipped to the area), notes, the frame, ticks and labels, the
// colour bar, the legend, the title; insets after their panel on their own background; the
// caption last.
//
// Strokes that follow the pixel grid (frames, grid lines, ticks, dashed guides) sit on half
// units, so a 1-unit line covers one row of PNG pixels sharply; vector outputs do not care.
#include "figure_cairo/figure_draw.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include "figure_cairo/cairo_handles.h"
#include "figure_cairo/figure_layout.h"
#include "figure_cairo/figure_text.h"
#include "snapshot/snapshot.h"

namespace cb {

namespace {

constexpr double kPi = 3.14159265358979323846;

void source(cairo_t* cr, Rgb8 c, double alpha = 1.0) {
  cairo_set_source_rgba(cr, c.r / 255.0, c.g / 255.0, c.b / 255.0, alpha);
}

double crisp(double v) {
  return std::floor(v) + 0.5;
}

// The chain's strain colour map in the figure's theme (its lightness range), as 8-bit BGRA
// (cairo's ARGB32 in memory on little-endian).
std::uint32_t strain_argb(double s, const Theme& theme) {
  const Color c = strain_color(std::clamp(s, -1.0, 1.0), theme.name);
  const auto byte = [](float v) {
    return static_cast<std::uint32_t>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
  };
  return 0xFF000000u | byte(c.r) << 16 | byte(c.g) << 8 | byte(c.b);
}

// The sequential map at t in 0 .. 1: from the plot area through a mid blue to the far end of
// the theme's lightness (navy on paper, pale yellow on a dark screen), each anchor further from
// the background in lightness, so the map reads in greyscale and for colour-blind readers.
std::uint32_t sequential_argb(double t, const Theme& theme) {
  t = std::clamp(std::isfinite(t) ? t : 0.0, 0.0, 1.0);
  const bool light = theme.name == ThemeName::Light;
  const Rgb8 anchors[3] = {theme.panel, light ? Rgb8{74, 140, 196} : Rgb8{30, 110, 180},
                           light ? Rgb8{8, 29, 88} : Rgb8{255, 240, 170}};
  const int k = t < 0.5 ? 0 : 1;
  const double f = t < 0.5 ? 2.0 * t : 2.0 * t - 1.0;
  const auto mix = [&](std::uint8_t a, std::uint8_t b) {
    return static_cast<std::uint32_t>(std::lround(a + f * (double(b) - double(a))));
  };
  const Rgb8 &a = anchors[k], &b = anchors[k + 1];
  return 0xFF000000u | mix(a.r, b.r) << 16 | mix(a.g, b.g) << 8 | mix(a.b, b.b);
}

std::uint32_t cell_argb(double v, HeatmapColours colours, const Theme& theme) {
  return colours == HeatmapColours::Sequential ? sequential_argb(v, theme) : strain_argb(v, theme);
}

// An image of a heatmap's colours, `columns` x `rows`, row 0 at the top; value(column, row) /
// scale.
template <typename Value>
CairoSurface heatmap_image(const Theme& theme, HeatmapColours colours, int columns, int rows,
                           Value value) {
  CairoSurface image(cairo_image_surface_create(CAIRO_FORMAT_RGB24, columns, rows));
  cairo_surface_flush(image.get());
  unsigned char* data = cairo_image_surface_get_data(image.get());
  const int stride = cairo_image_surface_get_stride(image.get());
  if (!data) throw std::runtime_error("cairo could not make a heatmap image");
  for (int r = 0; r < rows; ++r) {
    auto* row = reinterpret_cast<std::uint32_t*>(data + static_cast<std::ptrdiff_t>(r) * stride);
    for (int c = 0; c < columns; ++c) row[c] = cell_argb(value(c, r), colours, theme);
  }
  cairo_surface_mark_dirty(image.get());
  return image;
}

// Paints the image over the box, each image pixel a sharp rectangle (no smoothing between
// cells: a heatmap's cells are data).
void paint_image(cairo_t* cr, cairo_surface_t* image, const FigureBox& box) {
  const int w = cairo_image_surface_get_width(image), h = cairo_image_surface_get_height(image);
  cairo_save(cr);
  cairo_translate(cr, box.x, box.y);
  cairo_scale(cr, box.w / w, box.h / h);
  cairo_set_source_surface(cr, image, 0, 0);
  cairo_pattern_set_filter(cairo_get_source(cr), CAIRO_FILTER_NEAREST);
  cairo_rectangle(cr, 0, 0, w, h);
  cairo_fill(cr);
  cairo_restore(cr);
}

struct PanelPainter {
  cairo_t* cr;
  const Theme& theme;
  const Panel& p;
  const FigurePanelLayout& l;
  const FigureMetrics& m;

  const FigureBox& area() const { return l.mapping.area; }
  double px(double x) const { return l.mapping.px(axis_value(p.x, x)); }
  double py(double y) const { return l.mapping.py(y); }
  Rgb8 rgb(FigureColour c) const { return figure_rgb(c, theme); }
  TextFont small() const { return {FontFace::Sans, m.small}; }

  void clip_to_area() const {
    cairo_rectangle(cr, area().x, area().y, area().w, area().h);
    cairo_clip(cr);
  }

  void hline(double x0, double x1, double y) const {
    cairo_move_to(cr, x0, crisp(y));
    cairo_line_to(cr, x1, crisp(y));
  }
  void vline(double x, double y0, double y1) const {
    cairo_move_to(cr, crisp(x), y0);
    cairo_line_to(cr, crisp(x), y1);
  }

  void background() const {
    if (p.inset) {  // cover what lies below it, and set it apart by a faint outline
      source(cr, theme.background);
      cairo_rectangle(cr, l.box.x, l.box.y, l.box.w, l.box.h);
      cairo_fill(cr);
      source(cr, theme.grid);
      cairo_set_line_width(cr, 1.0);
      cairo_rectangle(cr, crisp(l.box.x), crisp(l.box.y), l.box.w - 1, l.box.h - 1);
      cairo_stroke(cr);
    }
    source(cr, theme.panel);
    cairo_rectangle(cr, area().x, area().y, area().w, area().h);
    cairo_fill(cr);
  }

  void grid() const {
    if (!p.heatmap.empty()) return;  // a grid would only hide the field's colours
    source(cr, theme.grid);
    cairo_set_line_width(cr, 1.0);
    for (double v : l.x_ticks.values)
      if (inside_x(v)) vline(l.mapping.px(v), area().y, area().bottom());
    for (double v : l.y_ticks.values)
      if (inside_y(v)) hline(area().x, area().right(), l.mapping.py(v));
    cairo_stroke(cr);
  }

  bool inside_x(double v) const {
    const double lo = std::min(l.mapping.x0, l.mapping.x1),
                 hi = std::max(l.mapping.x0, l.mapping.x1);
    return v >= lo - 1e-9 * (hi - lo) && v <= hi + 1e-9 * (hi - lo);
  }
  bool inside_y(double v) const {
    const double lo = std::min(l.mapping.y0, l.mapping.y1),
                 hi = std::max(l.mapping.y0, l.mapping.y1);
    return v >= lo - 1e-9 * (hi - lo) && v <= hi + 1e-9 * (hi - lo);
  }

  void heatmap() const {
    const Heatmap& h = p.heatmap;
    if (h.empty()) return;
    const CairoSurface image =
        heatmap_image(theme, h.colours, h.columns, h.rows, [&](int c, int r) {
          // Image row 0 is the top, the heatmap's row 0 the bottom (y_lo).
          return h.values[static_cast<std::size_t>(h.rows - 1 - r) * h.columns + c] / h.scale;
        });
    const double x0 = px(h.x_lo), x1 = px(h.x_hi), y0 = py(h.y_hi), y1 = py(h.y_lo);
    paint_image(cr, image.get(), {x0, y0, x1 - x0, y1 - y0});
  }

  void line(const Series& s) const {
    source(cr, rgb(s.colour));
    cairo_set_line_width(cr, m.line);
    cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
    cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
    bool drawing = false;  // NaN in y breaks the line
    for (std::size_t i = 0; i < s.x.size() && i < s.y.size(); ++i) {
      if (!std::isfinite(s.y[i])) {
        drawing = false;
        continue;
      }
      (drawing ? cairo_line_to : cairo_move_to)(cr, px(s.x[i]), py(s.y[i]));
      drawing = true;
    }
    cairo_stroke(cr);
  }

  // One filled path per point: an SVG holds one element per plotted point, countable.
  void points(const Series& s) const {
    source(cr, rgb(s.colour));
    for (std::size_t i = 0; i < s.x.size() && i < s.y.size(); ++i) {
      if (!std::isfinite(s.y[i])) continue;
      cairo_new_sub_path(cr);
      cairo_arc(cr, px(s.x[i]), py(s.y[i]), m.point, 0, 2 * kPi);
      cairo_fill(cr);
    }
  }

  // One path per stretch where both edges are finite: no seams where pieces would overlap.
  void band(const Series& s) const {
    source(cr, rgb(s.colour), 0.35);
    const std::size_t n = std::min({s.x.size(), s.y.size(), s.y2.size()});
    std::size_t i = 0;
    while (i < n) {
      if (!std::isfinite(s.y[i] + s.y2[i])) {
        ++i;
        continue;
      }
      std::size_t j = i;
      while (j < n && std::isfinite(s.y[j] + s.y2[j])) ++j;
      for (std::size_t k = i; k < j; ++k) cairo_line_to(cr, px(s.x[k]), py(s.y[k]));
      for (std::size_t k = j; k-- > i;) cairo_line_to(cr, px(s.x[k]), py(s.y2[k]));
      cairo_close_path(cr);
      cairo_fill(cr);
      i = j;
    }
  }

  void series(const Series& s) const {
    const Rgb8 colour = rgb(s.colour);
    switch (s.style) {
      case SeriesStyle::Line:
        line(s);
        break;
      case SeriesStyle::Points:
        points(s);
        break;
      case SeriesStyle::Band:
        band(s);
        break;
      case SeriesStyle::XSpans:
        source(cr, colour, 0.3);
        for (std::size_t i = 0; i < s.x.size() && i < s.x2.size(); ++i) {
          const double x0 = px(s.x[i]), x1 = std::max(x0 + 1.0, px(s.x2[i]));
          cairo_rectangle(cr, x0, area().y, x1 - x0, area().h);
        }
        cairo_fill(cr);
        break;
      case SeriesStyle::VLines:
      case SeriesStyle::HLines: {
        const double dash = 0.4 * m.font;
        cairo_set_dash(cr, &dash, 1, 0);
        source(cr, colour);
        cairo_set_line_width(cr, 1.0);
        if (s.style == SeriesStyle::VLines)
          for (double x : s.x) vline(px(x), area().y, area().bottom());
        else
          for (double y : s.y) hline(area().x, area().right(), py(y));
        cairo_stroke(cr);
        cairo_set_dash(cr, nullptr, 0, 0);
        break;
      }
    }
  }

  void frame_and_ticks() const {
    source(cr, theme.axis);
    cairo_set_line_width(cr, 1.0);
    cairo_rectangle(cr, crisp(area().x), crisp(area().y), area().w - 1, area().h - 1);
    for (double v : l.x_ticks.values)
      if (inside_x(v)) vline(l.mapping.px(v), area().bottom(), area().bottom() + m.tick);
    for (double v : l.y_ticks.values)
      if (inside_y(v)) hline(area().x - m.tick, area().x, l.mapping.py(v));
    cairo_stroke(cr);
    source(cr, theme.text);
    const double gap = 0.3 * m.font;
    for (std::size_t i = 0; i < l.x_ticks.values.size(); ++i)
      if (inside_x(l.x_ticks.values[i]))
        draw_text(cr, small(), l.mapping.px(l.x_ticks.values[i]),
                  area().bottom() + m.tick + gap + 0.5 * m.small, l.x_ticks.labels[i], 0.5);
    for (std::size_t i = 0; i < l.y_ticks.values.size(); ++i)
      if (inside_y(l.y_ticks.values[i]))
        draw_text(cr, small(), area().x - m.tick - gap, l.mapping.py(l.y_ticks.values[i]),
                  l.y_ticks.labels[i], 1.0);
  }

  void axis_labels() const {
    source(cr, theme.text);
    const TextFont font{FontFace::Sans, m.font};
    if (!p.x.label.empty())
      draw_text(cr, font, area().x + 0.5 * area().w, l.x_label_y, p.x.label, 0.5);
    if (!p.y.label.empty()) {  // rotated, reading upwards, centred on the axis
      cairo_save(cr);
      cairo_translate(cr, l.y_label_x, area().y + 0.5 * area().h);
      cairo_rotate(cr, -0.5 * kPi);
      draw_text(cr, font, 0.0, 0.0, p.y.label, 0.5);
      cairo_restore(cr);
    }
    if (!p.title.empty())
      draw_text(cr, {p.inset ? FontFace::Sans : FontFace::Bold, p.inset ? m.small : m.font},
                l.box.x + (p.inset ? 0.3 : 0.6) * m.font, l.title_y, p.title);
  }

  void colour_bar() const {
    const Heatmap& h = p.heatmap;
    if (h.empty()) return;
    const FigureBox& b = l.colour_bar;
    // value / scale from +1 (top) to -1 (bottom), or to 0 for a sequential map.
    constexpr int kSteps = 256;
    const bool sequential = h.colours == HeatmapColours::Sequential;
    const double bottom = sequential ? 0.0 : -1.0;
    const CairoSurface image = heatmap_image(theme, h.colours, 1, kSteps, [&](int, int r) {
      return 1.0 - (1.0 - bottom) * (r + 0.5) / kSteps;
    });
    paint_image(cr, image.get(), b);
    source(cr, theme.axis);
    cairo_set_line_width(cr, 1.0);
    cairo_rectangle(cr, crisp(b.x), crisp(b.y), b.w - 1, b.h - 1);
    cairo_stroke(cr);
    source(cr, theme.text);
    for (double v : sequential ? std::vector<double>{0.0, 0.25, 0.5, 0.75, 1.0}
                               : std::vector<double>{-1.0, -0.5, 0.0, 0.5, 1.0}) {
      char buffer[32];
      std::snprintf(buffer, sizeof buffer, "%g", v * h.scale);
      std::string label = buffer;
      if (label[0] == '-') label = "\u2212" + label.substr(1);
      draw_text(cr, small(), b.right() + 0.3 * m.font, b.y + (1.0 - v) / (1.0 - bottom) * b.h,
                label);
    }
    draw_text(cr, small(), b.x + 0.5 * b.w, b.y - 1.4 * m.small, h.label, 0.5);
  }

  struct Entry {
    const Series* s;
    double width;
  };

  // The legend: as many entries a row as fit in the area's width, in the panel's corner, on
  // the background (slightly translucent) so data below stay visible but the text reads.
  void legend() const {
    const double fs = m.small, swatch = 1.4 * fs, pad = 0.4 * fs, row_h = 1.35 * fs;
    std::vector<std::vector<Entry>> rows(1);
    std::vector<double> widths(1, pad);
    for (const Series& s : p.series) {
      if (s.label.empty()) continue;
      const double w = swatch + 0.35 * fs + text_advance(cr, small(), s.label) + 0.9 * fs;
      if (!rows.back().empty() && widths.back() + w > area().w - 2 * pad) {
        rows.emplace_back();
        widths.push_back(pad);
      }
      rows.back().push_back({&s, w});
      widths.back() += w;
    }
    if (rows.front().empty()) return;
    const double box_w = *std::max_element(widths.begin(), widths.end()) - 0.5 * fs;
    const double box_h = row_h * static_cast<double>(rows.size()) + 0.3 * fs;
    const bool bottom_right = p.legend == Panel::Legend::BottomRight;
    const double x0 = bottom_right ? area().right() - pad - box_w : area().x + pad;
    const double y0 = bottom_right ? area().bottom() - pad - box_h : area().y + pad;
    source(cr, theme.background, 0.9);
    cairo_rectangle(cr, x0, y0, box_w, box_h);
    cairo_fill(cr);
    source(cr, theme.grid);
    cairo_set_line_width(cr, 1.0);
    cairo_rectangle(cr, crisp(x0), crisp(y0), std::round(box_w), std::round(box_h));
    cairo_stroke(cr);
    for (std::size_t r = 0; r < rows.size(); ++r) {
      double x = x0 + pad;
      const double y = y0 + 0.15 * fs + row_h * (static_cast<double>(r) + 0.5);
      for (const Entry& e : rows[r]) {
        swatch_of(*e.s, x, y, swatch);
        source(cr, theme.text);
        draw_text(cr, small(), x + swatch + 0.35 * fs, y, e.s->label);
        x += e.width;
      }
    }
  }

  void swatch_of(const Series& s, double x, double y, double w) const {
    const Rgb8 colour = rgb(s.colour);
    switch (s.style) {
      case SeriesStyle::Points:
        source(cr, colour);
        cairo_new_path(cr);
        cairo_arc(cr, x + 0.5 * w, y, m.point, 0, 2 * kPi);
        cairo_fill(cr);
        break;
      case SeriesStyle::Band:
      case SeriesStyle::XSpans:
        source(cr, colour, s.style == SeriesStyle::Band ? 0.35 : 0.3);
        cairo_rectangle(cr, x, y - 0.35 * w, w, 0.7 * w);
        cairo_fill(cr);
        break;
      case SeriesStyle::Line:
      case SeriesStyle::VLines:
      case SeriesStyle::HLines: {
        const double dash = 0.2 * w;
        if (s.style != SeriesStyle::Line) cairo_set_dash(cr, &dash, 1, 0);
        source(cr, colour);
        cairo_set_line_width(cr, s.style == SeriesStyle::Line ? m.line : 1.5);
        cairo_move_to(cr, x, y);
        cairo_line_to(cr, x + w, y);
        cairo_stroke(cr);
        cairo_set_dash(cr, nullptr, 0, 0);
        break;
      }
    }
  }

  void draw() const {
    background();
    grid();
    cairo_save(cr);
    clip_to_area();
    heatmap();
    for (const Series& s : p.series) series(s);
    for (const Note& n : p.notes) {
      if (!p.heatmap.empty()) {  // on a field of any colour: on a patch of the background
        source(cr, theme.background, 0.8);
        const double pad = 0.3 * m.small;
        cairo_rectangle(cr, px(n.x) - pad, py(n.y) - 0.5 * m.small - pad,
                        text_advance(cr, small(), n.text) + 2 * pad, m.small + 2 * pad);
        cairo_fill(cr);
      }
      source(cr, readable_on(theme, rgb(n.colour)));
      draw_text(cr, small(), px(n.x), py(n.y), n.text);
    }
    cairo_restore(cr);
    frame_and_ticks();
    axis_labels();
    colour_bar();
    legend();
  }
};

void caption(cairo_t* cr, const Figure& f, const FigureLayout& layout, const Theme& theme,
             const FigureMetrics& m) {
  if (layout.caption.empty()) return;
  TextFont font{FontFace::Sans, m.caption};
  std::vector<std::string> lines = wrap_text(cr, font, f.caption, layout.caption.w);
  while (static_cast<int>(lines.size()) > layout.caption_lines && font.size > 0.6 * m.caption) {
    font.size *= 0.95;
    lines = wrap_text(cr, font, f.caption, layout.caption.w);
  }
  source(cr, theme.text_dim);
  const double line_h = layout.caption.h / layout.caption_lines;
  for (std::size_t i = 0; i < lines.size(); ++i)
    draw_text(cr, font, layout.caption.x,
              layout.caption.y + line_h * (static_cast<double>(i) + 0.5), lines[i]);
}

}  // namespace

Rgb8 readable_on(const Theme& theme, Rgb8 colour) {
  for (int step = 0; step <= 20; ++step) {
    const double t = step / 20.0;
    const auto mix = [t](std::uint8_t a, std::uint8_t b) {
      return static_cast<std::uint8_t>(std::lround(a + (b - a) * t));
    };
    const Rgb8 c{mix(colour.r, theme.text.r), mix(colour.g, theme.text.g),
                 mix(colour.b, theme.text.b)};
    if (contrast_ratio(c, theme.background) >= 7.0 && contrast_ratio(c, theme.panel) >= 7.0)
      return c;
  }
  return theme.text;
}

void draw_figure(cairo_t* cr, const Figure& figure, const Theme& theme, int width, int height) {
  // Glyph outlines unhinted (the same shapes in every output) but anti-aliased; metrics
  // unrounded, so text widths and positions are the same on every surface.
  const CairoFontOptions options(cairo_font_options_create());
  cairo_font_options_set_antialias(options.get(), CAIRO_ANTIALIAS_GRAY);
  cairo_font_options_set_hint_style(options.get(), CAIRO_HINT_STYLE_NONE);
  cairo_font_options_set_hint_metrics(options.get(), CAIRO_HINT_METRICS_OFF);
  cairo_set_font_options(cr, options.get());
  cairo_set_antialias(cr, CAIRO_ANTIALIAS_GRAY);

  source(cr, theme.background);
  cairo_rectangle(cr, 0, 0, width, height);
  cairo_fill(cr);
  const FigureLayout layout = figure_layout(figure, width, height);
  const FigureMetrics m = figure_metrics(height);
  for (std::size_t i = 0; i < figure.panels.size(); ++i)
    PanelPainter{cr, theme, figure.panels[i], layout.panels[i], m}.draw();
  caption(cr, figure, layout, theme, m);
  if (cairo_status(cr) != CAIRO_STATUS_SUCCESS)
    throw std::runtime_error(std::string("cairo: ") + cairo_status_to_string(cairo_status(cr)) +
                             " while drawing " + figure.name);
}

}  // namespace cb
