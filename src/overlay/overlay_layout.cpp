#include "overlay/overlay_layout.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <vector>

#include "theme/fonts.h"

namespace cb {

namespace {

struct Part {
  const char* name;
  bool OverlaySwitches::*flag;
};
constexpr Part kParts[] = {{"hud", &OverlaySwitches::hud},
                           {"plots", &OverlaySwitches::plots},
                           {"spacetime", &OverlaySwitches::spacetime},
                           {"modes", &OverlaySwitches::modes}};

// A panel per column of a row; widths in proportion to `weight` (the phi plot, the paper's
// Fig. 4(a), gets the most room).
struct Column {
  Box* box;
  float weight;
};

void lay_row(const std::vector<Column>& columns, float x, float y, float w, float h, float gap) {
  if (columns.empty()) return;
  float total = 0;
  for (const Column& c : columns) total += c.weight;
  const float usable = w - gap * static_cast<float>(columns.size() - 1);
  for (const Column& c : columns) {
    const float cw = std::round(usable * c.weight / total);
    *c.box = Box{x, y, cw, h};
    x += cw + gap;
  }
}

}  // namespace

bool parse_overlay_switches(const std::string& text, OverlaySwitches& out, std::string& bad) {
  OverlaySwitches s{false, false, false, false};
  std::stringstream words(text);
  std::string word;
  bool any_word = false;
  while (std::getline(words, word, ',')) {
    any_word = true;
    if (word == "all") {
      s = OverlaySwitches{};
      continue;
    }
    if (word == "none") continue;
    bool found = false;
    for (const Part& p : kParts)
      if (word == p.name) {
        s.*p.flag = true;
        found = true;
      }
    if (!found) {
      bad = word;
      return false;
    }
  }
  if (!any_word) {
    bad = text;
    return false;
  }
  out = s;
  return true;
}

std::string overlay_switches_text(const OverlaySwitches& s) {
  std::string out;
  for (const Part& p : kParts)
    if (s.*p.flag) out += (out.empty() ? "" : ",") + std::string(p.name);
  return out.empty() ? "none" : out;
}

OverlayLayout overlay_layout(int width, int height, const OverlaySwitches& switches) {
  OverlayLayout l;
  if (!switches.any() || width < kOverlayMinWidth || height < kOverlayMinHeight) return l;
  const float W = static_cast<float>(width), H = static_cast<float>(height);
  l.enabled = true;
  // The frame's one text size (theme/fonts.h), as the chain panel's labels: 22 px at 1080p,
  // 14 px at 480p (crisp: the atlas is rasterised at it).
  l.font_px = frame_text_px(height);
  // Whole pixels: ImGui then draws antialiased lines from its texture, 2 vertices a point.
  l.line_px = std::max(2.0f, std::round(0.12f * l.font_px));
  // The same outer margin as the snapshot's, so the panels line up with the wall.
  const float margin = std::max(6.0f, std::round(0.025f * std::min(W, H)));
  const float gap = std::round(0.9f * l.font_px);
  const bool graphs = switches.plots || switches.spacetime || switches.modes;
  const bool portrait = W < 1.25f * H;
  // The HUD alone needs ~9 text lines; plots need room for their curves.
  const float band_h = std::round((graphs ? (portrait ? 0.56f : 0.48f) : 0.24f) * H);
  l.chain_height = static_cast<int>(H - band_h);
  l.band = Box{0, static_cast<float>(l.chain_height), W, band_h};

  std::vector<Column> first, second;
  if (switches.hud) first.push_back({&l.hud, 0.95f});
  if (switches.plots) first.push_back({&l.phi, 1.7f});
  std::vector<Column>& rest = portrait ? second : first;
  if (switches.plots) rest.push_back({&l.energy, 1.05f});
  if (switches.spacetime) rest.push_back({&l.spacetime, 0.95f});
  if (switches.modes) rest.push_back({&l.modes, 0.95f});
  if (first.empty()) std::swap(first, second);

  // Whole pixels throughout: the backgrounds are cleared through the scissor box.
  const float top = std::round(l.band.y + 0.5f * gap), bottom = H - margin;
  const float x = margin, w = W - 2 * margin;
  if (second.empty()) {
    lay_row(first, x, top, w, bottom - top, gap);
  } else {
    const float row_h = std::round(0.5f * (bottom - top - gap));
    lay_row(first, x, top, w, row_h, gap);
    lay_row(second, x, bottom - row_h, w, row_h, gap);
  }
  return l;
}

Box plot_area(const Box& panel, float font_px, int header) {
  // Left: tick labels of up to ~6 characters; top: the panel's title (and notes); bottom:
  // the tick labels of the x axis.
  const float left = std::round(3.6f * font_px);
  const float top = std::round((0.5f + 1.2f * static_cast<float>(header)) * font_px);
  const float right = std::round(0.6f * font_px), bottom = std::round(1.6f * font_px);
  return Box{panel.x + left, panel.y + top, std::max(1.0f, panel.w - left - right),
             std::max(1.0f, panel.h - top - bottom)};
}

std::vector<float> x_tick_label_lefts(const std::vector<float>& x, const std::vector<float>& width,
                                      float area_right, float font_px) {
  const std::size_t n = std::min(x.size(), width.size());
  std::vector<float> left(n, std::numeric_limits<float>::quiet_NaN());
  float next_left = std::numeric_limits<float>::infinity();  // the label right of this one
  for (std::size_t i = n; i-- > 0;) {
    const bool past = x[i] + 0.5f * width[i] > area_right + 0.5f * font_px;
    const float l = past ? x[i] - width[i] : x[i] - 0.5f * width[i];
    if (l + width[i] > next_left - 0.5f * font_px) continue;
    left[i] = l;
    next_left = l;
  }
  return left;
}

PlotMapping phi_mapping(const OverlayLayout& layout, const OverlayData& d) {
  return PlotMapping{plot_area(layout.phi, layout.font_px), 0.0, d.tau_end, d.phi_lo, d.phi_hi};
}

PlotMapping energy_mapping(const OverlayLayout& layout, const OverlayData& d) {
  return PlotMapping{plot_area(layout.energy, layout.font_px), 0.0, d.tau_end, 0.0, d.energy_hi};
}

PlotMapping spacetime_mapping(const OverlayLayout& layout, const OverlayData& d) {
  return PlotMapping{plot_area(layout.spacetime, layout.font_px), 0.0,
                     static_cast<double>(std::max(1, d.beads)), 0.0, d.tau_end};
}

PlotMapping modes_mapping(const OverlayLayout& layout, const OverlayData& d) {
  const double count = std::max<double>(1.0, static_cast<double>(d.mode_amplitude.size()));
  return PlotMapping{plot_area(layout.modes, layout.font_px, 2), -0.5, count - 0.5, 0.0, 1.0};
}

}  // namespace cb
