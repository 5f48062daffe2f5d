// The overlay's panels. Index: the HUD; the phi plot (Fig. 4(a)); the energy plot
// (Fig. 4(b)); the space-time picture; the mode bars; what the still parts depend on.
//
// Every plot maps data to pixels through overlay_layout.h's PlotMapping, the same functions
// the tests use to find where a point lands.
#include "overlay/overlay_panels.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "overlay/overlay_plot.h"

namespace cb::overlay_detail {

// ---- The HUD -----------------------------------------------------------------------------

void draw_hud(Canvas& c) {
  const Box& box = c.layout.hud;
  const OverlayData& d = c.data;
  const bool still = c.pass == Pass::Static;
  const float fs = c.layout.font_px, line = 1.38f * fs;
  if (still)
    c.draw->AddRect(ImVec2(box.x + 0.5f, box.y + 0.5f),
                    ImVec2(box.right() - 0.5f, box.bottom() - 0.5f), col(c.theme.border), 0.3f * fs, 0,
                    1.0f);
  c.draw->PushClipRect(ImVec2(box.x, box.y), ImVec2(box.right(), box.bottom()), true);
  const float x = box.x + 0.6f * fs, value_x = x + 2.2f * fs;
  float y = box.y + 0.45f * fs;
  {  // the title, wrapped to the panel (a long one takes two lines)
    const std::string title = d.title.empty() ? std::string("chainbreak") : d.title;
    const float size = 1.15f * fs, wrap = box.right() - x - 0.4f * fs;
    if (still)
      c.draw->AddText(c.fonts.bold, size, ImVec2(std::round(x), std::round(y)), col(c.theme.text),
                      title.c_str(), nullptr, wrap);
    y += c.fonts.bold->CalcTextSizeA(size, FLT_MAX, wrap, title.c_str()).y + 0.35f * line;
  }
  std::string params = format("N = %d   \u03B3 = %g", d.beads, d.gamma);
  params += d.phi_c > 0 ? format("   \u03C6_c = %g", d.phi_c) : std::string("   unbreakable");
  if (still) text_sub(c, c.fonts.sans, x, y, c.theme.text_dim, params, 0.0f, 0.9f);
  y += line;
  // Label in the proportional font (still), value in the monospaced one so digits do not
  // jitter (changing).
  const auto row = [&](const std::string& label, const std::string& value) {
    if (still)
      text(c, c.fonts.sans, x, y, c.theme.text, label);
    else
      text(c, c.fonts.mono, value_x, y, c.theme.text, value);
    y += line;
  };
  row("\u03C4", format("%.2f", d.tau));
  if (std::isfinite(d.seconds)) row("t", format("%.5g s", d.seconds));
  row("f", format("%.4g", d.force));
  row("\u03B5", format("%.4g", d.energy));  // Eq. (energy), per particle
  const auto part = [&](const char* label, double value) {
    if (still)
      text(c, c.fonts.sans, value_x, y, c.theme.text_dim, label, 0.0f, 0.85f);
    else
      text(c, c.fonts.mono, value_x + 5.2f * fs, y, c.theme.text_dim, format("%.4g", value), 0.0f, 0.85f);
    y += 0.9f * line;
  };
  part("kinetic", d.kinetic);
  part("potential", d.potential);
  y += 0.1f * line;
  if (!still) {
    text(c, c.fonts.sans, x, y, c.theme.text, d.breaks.empty() ? "no break yet" : "breaks");
    y += line;
    // As many breaks as fit; the last line counts the rest.
    const int fit = std::max(1, static_cast<int>((box.bottom() - y - 0.3f * fs) / line));
    const int count = static_cast<int>(d.breaks.size());
    // The first break stands out as in the chain panel: bold in the text colour behind an
    // accent bar; the later ones are muted (the secondary text colour).
    for (int i = 0; i < count && i < fit; ++i) {
      const OverlayBreak& b = d.breaks[i];
      std::string s =
          b.spring == 0 ? std::string("pull string") : "spring " + std::to_string(b.spring);
      s += format(" at \u03C4 = %.2f", b.tau);
      const bool more = i == fit - 1 && count > fit;
      if (more) s = format("+%d more", count - i);
      if (i == 0 && !more) {
        c.draw->AddRectFilled(ImVec2(x, y + 0.1f * fs), ImVec2(x + 0.3f * fs, y + 1.0f * fs),
                              col(c.theme.accent));
        text(c, c.fonts.bold, x + 0.6f * fs, y, c.theme.text, s, 0.0f, 0.9f);
      } else {
        text(c, c.fonts.mono, x + 0.6f * fs, y, c.theme.text_dim, s, 0.0f, 0.9f);
      }
      y += line;
    }
  }
  c.draw->PopClipRect();
}

// ---- phi_1, phi_N/2, phi_N vs tau: the paper's Fig. 4(a) -----------------------------------

void draw_phi_plot(Canvas& c) {
  const OverlayData& d = c.data;
  const float fs = c.layout.font_px;
  const PlotMapping m = phi_mapping(c.layout, d);
  const Box& a = m.area;
  if (c.pass == Pass::Static) {
    panel(c, c.layout.phi, "Extension \u03C6\u2C7C(\u03C4)");
    axes(c, c.layout.phi, m, nice_ticks(0.0, d.tau_end, 6), nice_ticks(d.phi_lo, d.phi_hi, 5),
         "\u03C4", true);
    c.draw->PushClipRect(ImVec2(a.x, a.y), ImVec2(a.right(), a.bottom()), true);
    if (d.phi_c > 0) {  // Eq. (break): the threshold
      const float w = std::max(1.0f, 0.6f * c.layout.line_px);
      for (double level : {d.phi_c, -d.phi_c}) {
        if (level < 0 && !d.threshold_both_signs) continue;
        if (level < d.phi_lo || level > d.phi_hi) continue;
        const float y = m.py(level);
        dashed_hline(c, a.x, a.right(), y, col(c.theme.accent), w, 0.5f * fs);
        text_sub(c, c.fonts.sans, a.right() - 0.3f * fs, level > 0 ? y - 1.15f * fs : y + 0.1f * fs,
                 c.theme.text_dim, level > 0 ? "\u03C6_c" : "\u2212\u03C6_c", 1.0f, 0.85f);
      }
    }
    // The exact solution is the unbroken chain's: where its lines end, and why. (Still: it
    // changes once, and the still parts are then drawn again.)
    if (std::isfinite(d.exact_end)) {
      const float x = m.px(d.exact_end);
      dashed_vline(c, x, a.y, a.bottom(), col(c.theme.accent, 0.8f), 1.0f, 0.3f * fs);
      // Right of the line, else left of it; a shorter note when neither side holds the long
      // one, kept inside the plot so it never runs into the axis' labels.
      std::string note = format("exact lines end: first break, \u03C4 = %.2f", d.exact_end);
      const float pad = 0.3f * fs;
      const auto fits = [&](const std::string& n) {
        const float w = text_width(c.fonts.sans, 0.8f * fs, n);
        return x + pad + w <= a.right() - pad || x - pad - w >= a.x + pad;
      };
      if (!fits(note)) note = format("first break, \u03C4 = %.2f", d.exact_end);
      const float w = text_width(c.fonts.sans, 0.8f * fs, note);
      const bool right = x + pad + w <= a.right() - pad;
      const float left_x = right ? x + pad : std::max(a.x + pad, x - pad - w);
      text(c, c.fonts.sans, left_x, a.bottom() - 1.3f * fs, c.theme.text_dim, note, 0.0f, 0.8f);
    }
    c.draw->PopClipRect();
    std::vector<LegendEntry> entries;
    for (int s = 0; s < d.spring_count; ++s)
      entries.push_back({c.theme.series[s], "\u03C6" + subscript(d.springs[s]), true});
    legend(c, a, a.y + 0.3f * fs, entries);
    text(c, c.fonts.sans, a.x + 0.6f * fs, a.y + 1.65f * fs, c.theme.text_dim,
         d.exact ? "dots: RK4 \u00B7 lines: exact" : "dots: RK4 (no exact lines above N = 1024)",
         0.0f, 0.8f);
    return;
  }
  c.draw->PushClipRect(ImVec2(a.x, a.y), ImVec2(a.right(), a.bottom()), true);
  time_cursor(c, m);
  // The exact lines under the RK4 points, each in its spring's colour, dimmed so that the
  // points stand out on them.
  for (int s = 0; d.exact && s < d.spring_count; ++s)
    polyline(c, m, d.exact_tau, d.exact_phi[s], col(c.theme.series[s], kOverlayExactLineAlpha),
             c.layout.line_px);
  // The points, newest first so the newest always shows; at most one every ~2 diameters,
  // like the paper's figure (and each costs llvmpipe two triangles).
  const float h = 0.5f * c.marker.size, spacing = 2.2f * c.marker.size;
  for (int s = 0; s < d.spring_count; ++s) {
    const std::vector<double>& v = d.phi[s];
    float last_x = FLT_MAX;
    for (std::size_t i = d.history_tau.size(); i-- > 0;) {
      const float x = m.px(d.history_tau[i]);
      if (std::abs(last_x - x) < spacing) continue;
      last_x = x;
      const float y = m.py(v[i]);
      c.draw->AddImage(c.marker.texture, ImVec2(x - h, y - h), ImVec2(x + h, y + h), c.marker.uv0,
                       c.marker.uv1, col(c.theme.series[s]));
    }
  }
  c.draw->PopClipRect();
}

// ---- Energy per particle vs tau: Fig. 4(b), Eq. (energy) -----------------------------------

void draw_energy_plot(Canvas& c) {
  const OverlayData& d = c.data;
  const float fs = c.layout.font_px;
  const PlotMapping m = energy_mapping(c.layout, d);
  const Box& a = m.area;
  if (c.pass == Pass::Static) {
    panel(c, c.layout.energy, "Energy per particle \u03B5(\u03C4)");
    axes(c, c.layout.energy, m, nice_ticks(0.0, d.tau_end, 4), nice_ticks(0.0, d.energy_hi, 5),
         "\u03C4", true);
    legend(c, a, a.y + 0.3f * fs,
           {{c.theme.total, "total", false}, {c.theme.kinetic, "kin.", false}, {c.theme.potential, "pot.", false}});
    return;
  }
  c.draw->PushClipRect(ImVec2(a.x, a.y), ImVec2(a.right(), a.bottom()), true);
  time_cursor(c, m);
  const float w = c.layout.line_px;
  polyline(c, m, d.history_tau, d.energy_kinetic, col(c.theme.kinetic), w);
  polyline(c, m, d.history_tau, d.energy_potential, col(c.theme.potential), w);
  polyline(c, m, d.history_tau, d.energy_total, col(c.theme.total), w);
  c.draw->PopClipRect();
}

// ---- The space-time picture: strain over springs and time ----------------------------------

std::uint32_t spacetime_texel(float s, ThemeName theme) {
  return col(overlay_strain_rgb(s, theme));
}

unsigned char marker_coverage(int x, int y, int size, float radius) {
  // The area of the texel inside the disc, approximated by the distance of its centre from
  // the edge (a 1-texel ramp): the usual antialiased edge, the interior exactly opaque.
  const float c = 0.5f * static_cast<float>(size);
  const float d = std::hypot(x + 0.5f - c, y + 0.5f - c);
  return static_cast<unsigned char>(
      std::lround(255.0f * std::clamp(radius + 0.5f - d, 0.0f, 1.0f)));
}

void draw_spacetime(Canvas& c) {
  const OverlayData& d = c.data;
  const PlotMapping m = spacetime_mapping(c.layout, d);
  const Box& a = m.area;
  if (c.pass == Pass::Static) {
    panel(c, c.layout.spacetime, "Strain \u03C6\u2C7C/\u03C6_c");
    // No grid: the picture covers the whole area.
    axes(c, c.layout.spacetime, m, nice_ticks(0.0, d.beads, 4), nice_ticks(0.0, d.tau_end, 5), "j",
         false);
    title_note(c, c.layout.spacetime, "wall \u2192 pulled end");
    return;
  }
  // The picture itself is composed on the CPU and copied in (compose_spacetime); its frame
  // goes on top of it.
  c.draw->AddRect(ImVec2(a.x - 0.5f, a.y - 0.5f), ImVec2(a.right() + 0.5f, a.bottom() + 0.5f),
                  col(c.theme.axis), 0.0f, 0, 1.0f);
}

void compose_spacetime(const OverlayLayout& layout, const OverlayData& d, ThemeName theme,
                       std::vector<std::uint32_t>& pixels) {
  const PlotMapping m = spacetime_mapping(layout, d);
  const int w = static_cast<int>(m.area.w), h = static_cast<int>(m.area.h);
  const std::uint32_t background = spacetime_texel(std::numeric_limits<float>::quiet_NaN(), theme);
  pixels.assign(static_cast<std::size_t>(w) * h, background);
  const int rows = d.spacetime_rows(), columns = d.spacetime_columns;
  if (rows == 0 || columns == 0) return;
  // Each pixel shows the cell under its centre: column c spans springs c N / C .. (c+1) N / C,
  // row r the times nearer spacetime_tau[r] than its neighbours' (rows are evenly spaced in
  // frames, which slow motion makes uneven in tau), up to half a normal row past the last.
  std::vector<int> column_of(static_cast<std::size_t>(w));
  for (int x = 0; x < w; ++x) {
    const double springs = m.x0 + (x + 0.5) / w * (m.x1 - m.x0);
    column_of[x] =
        std::clamp(static_cast<int>(std::floor(springs / d.beads * columns)), 0, columns - 1);
  }
  const double row_tau = d.spacetime_stride * d.tau_per_frame;
  std::vector<std::uint32_t> colours(static_cast<std::size_t>(columns));
  int cached_row = -1;
  for (int y = 0; y < h; ++y) {  // y = 0 is the area's bottom row (GL order)
    const double tau = m.y0 + (y + 0.5) / h * (m.y1 - m.y0);
    const auto& t = d.spacetime_tau;
    if (tau < t.front() - 0.5 * row_tau || tau > t.back() + 0.5 * row_tau) continue;
    const auto above = std::lower_bound(t.begin(), t.end(), tau);
    long r = static_cast<long>(above - t.begin());
    if (r == rows || (r > 0 && tau - t[r - 1] < t[r] - tau)) --r;
    if (r != cached_row) {
      for (int k = 0; k < columns; ++k)
        colours[k] = spacetime_texel(d.spacetime[static_cast<std::size_t>(r) * columns + k], theme);
      cached_row = static_cast<int>(r);
    }
    std::uint32_t* out = &pixels[static_cast<std::size_t>(y) * w];
    for (int x = 0; x < w; ++x) out[x] = colours[column_of[x]];
  }
}

// ---- Normal modes ---------------------------------------------------------------------------

void draw_modes(Canvas& c) {
  const OverlayData& d = c.data;
  const float fs = c.layout.font_px;
  const PlotMapping m = modes_mapping(c.layout, d);
  const Box& a = m.area;
  const int count = static_cast<int>(d.mode_amplitude.size());
  if (c.pass == Pass::Static) {
    panel(c, c.layout.modes, "Normal modes A\u2099");
    Ticks xt;
    xt.step = count > 8 ? 5.0 : 1.0;
    for (int n = 0; n < count; n += static_cast<int>(xt.step)) xt.values.push_back(n);
    Ticks yt;
    yt.step = 0.5;
    yt.values = {0.0, 0.5, 1.0};
    axes(c, c.layout.modes, m, xt, yt, "n", true);
    const Box& box = c.layout.modes;
    text(c, c.fonts.sans, box.x + 0.45f * fs, box.y + 1.45f * fs, c.theme.text_dim,
         "\u221A(a\u2099\u2032\u00B2 + \u03A9\u2099\u00B2a\u2099\u00B2): bar now, tick peak", 0.0f,
         0.75f);
    return;
  }
  if (!(d.mode_scale > 0)) return;
  const float half = 0.36f * a.w / std::max(1, count);
  for (int n = 0; n < count; ++n) {
    const float x = m.px(n);
    const float y = m.py(d.mode_amplitude[n] / d.mode_scale);
    c.draw->AddRectFilled(ImVec2(x - half, y), ImVec2(x + half, a.bottom()), col(c.theme.bar));
    const float peak = m.py(d.mode_peak[n] / d.mode_scale);  // the largest so far
    c.draw->AddLine(ImVec2(x - half, peak), ImVec2(x + half, peak), col(c.theme.text), 1.5f);
  }
}

bool same_still_parts(const OverlayData& a, const OverlayData& b) {
  const bool same_end =
      std::isnan(a.exact_end) ? std::isnan(b.exact_end) : a.exact_end == b.exact_end;
  bool same = same_end && a.title == b.title && a.beads == b.beads && a.gamma == b.gamma &&
              a.phi_c == b.phi_c && std::isfinite(a.seconds) == std::isfinite(b.seconds) &&
              a.tau_end == b.tau_end && a.phi_lo == b.phi_lo && a.phi_hi == b.phi_hi &&
              a.energy_hi == b.energy_hi && a.threshold_both_signs == b.threshold_both_signs &&
              a.spring_count == b.spring_count && a.exact == b.exact &&
              a.mode_amplitude.size() == b.mode_amplitude.size();
  for (int s = 0; same && s < a.spring_count; ++s) same = a.springs[s] == b.springs[s];
  return same;
}

}  // namespace cb::overlay_detail

namespace cb {

OverlayRgb overlay_strain_rgb(float s, ThemeName name) {
  if (std::isnan(s)) return theme(name).background;
  const Color k = strain_color(s, name);
  const auto byte = [](float v) {
    return static_cast<std::uint8_t>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
  };
  return OverlayRgb{byte(k.r), byte(k.g), byte(k.b)};
}

}  // namespace cb
