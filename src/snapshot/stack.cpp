#include "snapshot/stack.h"

#include <cmath>

#include "snapshot/snapshot_internal.h"
#include "theme/fonts.h"

namespace cb {

using namespace snapshot_detail;

namespace {

void shift(Layer& layer, float dy) {
  for (Rect& r : layer.rects) r.y += dy;
  for (Segment& s : layer.segments) s.y0 += dy, s.y1 += dy;
  for (Triangle& t : layer.triangles)
    for (float& y : t.y) y += dy;
  for (SpringInstance& s : layer.springs) s.y0 += dy, s.y1 += dy;
  for (BeadInstance& b : layer.beads) b.y += dy;
  for (Label& l : layer.labels) l.y += dy;
}

template <class T>
void append(std::vector<T>& to, std::vector<T>& from) {
  to.insert(to.end(), std::make_move_iterator(from.begin()), std::make_move_iterator(from.end()));
}

// A frame of the theme's background with empty layers.
RenderSnapshot empty_frame(int width, int height, const Palette& pal) {
  RenderSnapshot out;
  out.width = width;
  out.height = height;
  out.background = pal.background;
  out.layers.resize(kLayerCount);
  return out;
}

}  // namespace

RenderSnapshot stack_snapshots(std::vector<RenderSnapshot> parts, const std::vector<std::string>& labels,
                               int width, int height, ThemeName theme) {
  const Palette pal = palette(theme);
  RenderSnapshot out = empty_frame(width, height, pal);
  float y = 0;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    RenderSnapshot& p = parts[i];
    out.tau = p.tau;
    const SnapshotLayout& l = p.layout;
    for (int k = 0; k < kLayerCount; ++k) {
      shift(p.layers[k], y);
      append(out.layers[k].rects, p.layers[k].rects);
      append(out.layers[k].segments, p.layers[k].segments);
      append(out.layers[k].triangles, p.layers[k].triangles);
      append(out.layers[k].springs, p.layers[k].springs);
      append(out.layers[k].beads, p.layers[k].beads);
      append(out.layers[k].labels, p.layers[k].labels);
    }
    // The run's name, right of its time label; a rule above every run but the first.
    if (i < labels.size()) {
      const float x = l.margin + text_width("τ = 0000.00", l.font_px) + 2.0f * l.font_px;
      out.layers[kLayerFrame].labels.push_back(Label{labels[i], x, y + l.margin, l.font_px, pal.text,
                                                     FontFace::Bold});
    }
    if (i > 0)
      out.layers[kLayerFrame].rects.push_back(Rect{0, y, static_cast<float>(width), 1.0f, pal.rest_line});
    append(out.breaks_shown, p.breaks_shown);
    y += static_cast<float>(p.height);
  }
  return out;
}

RenderSnapshot title_card(int width, int height, ThemeName theme, const std::string& title,
                          const std::vector<std::string>& lines, const std::string& question) {
  const Palette pal = palette(theme);
  RenderSnapshot out = empty_frame(width, height, pal);
  const float px = frame_text_px(height);
  const float big = std::round(2.0f * px), ask = std::round(1.5f * px);
  auto& labels = out.layers[kLayerMarks].labels;
  const auto centred = [&](const std::string& text, float y, float size, Color c, FontFace face) {
    const float w = text_width(text, size, face);
    labels.push_back(Label{text, std::round(0.5f * (width - w)), std::round(y), size, c, face});
  };
  float y = 0.3f * height;
  centred(title, y, big, pal.text, FontFace::Bold);
  y += 2.2f * big;
  for (const std::string& line : lines) {
    centred(line, y, px, pal.dim_text, FontFace::Sans);
    y += 1.6f * px;
  }
  centred(question, std::max(y + 1.5f * ask, 0.7f * height), ask, pal.text, FontFace::Sans);
  return out;
}

}  // namespace cb
