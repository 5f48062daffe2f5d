// Theme: the colour roles every picture of chainbreak is drawn from (chain panels, overlay,
// figures in PNG/SVG/PDF, the viewer), and the typeface they all use.
//
// Design note: one set of roles, two values of it (STYLE.md, Pictures): a drawing asks for
// "text" or "grid", never for a colour, so the light (paper, handout) and dark (projector)
// pictures come from the same drawing code. Colours are 8-bit sRGB as written to an image.
// Text roles are chosen for a contrast of at least 7:1 (WCAG 2 AAA) against both the
// background and the panel colour; tests/test_theme.cpp checks every pair, and the render and
// figure tests check it again on drawn pixels. Plain data: no GL, no cairo, no ImGui.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

namespace cb {

enum class ThemeName { Dark, Light };

struct Rgb8 {
  std::uint8_t r = 0, g = 0, b = 0;
  bool operator==(const Rgb8&) const = default;
};

struct Theme {
  ThemeName name = ThemeName::Dark;
  Rgb8 background;  // the frame's or figure's background
  Rgb8 panel;       // plot areas (a shade off the background)
  Rgb8 text;        // all text: >= 7:1 against background and panel
  Rgb8 text_dim;    // secondary text (captions, units): still >= 7:1
  Rgb8 axis;        // plot frames, ticks
  Rgb8 border;      // outlines of the overlay's panels
  Rgb8 grid;        // grid lines, faint
  Rgb8 rest_line;   // the chain's rest line in the transverse view
  Rgb8 wall;        // the wall's face and hatching
  Rgb8 bead;        // beads (shaded discs)
  Rgb8 force;       // the pulling force's arrow and string
  Rgb8 accent;      // thresholds +-phi_c, break markers' lines (Okabe-Ito vermillion)
  Rgb8 marker;      // break markers and the flash
  Rgb8 cursor;      // the current time in plots
  Rgb8 series[3];   // phi_1, phi_N/2, phi_N (Okabe-Ito: distinct for colour-blind viewers)
  Rgb8 total, kinetic, potential;  // energy plot
  Rgb8 bar;                        // normal-mode bars
  // The strain colour map's lightness range (CIE L*, from s = -1 to s = +1; rising, so
  // compression and tension differ in greyscale). The zero-strain grey lies halfway.
  double strain_l_min = 30, strain_l_max = 92;
};

const Theme& theme(ThemeName name);
// "dark" / "light"; nullopt for anything else.
std::optional<ThemeName> parse_theme(const std::string& text);
const char* theme_name(ThemeName name);

// WCAG 2 contrast ratio of two sRGB colours, 1..21.
double contrast_ratio(Rgb8 a, Rgb8 b);
// CIE76 colour difference (Euclidean distance in CIELAB, D65).
double delta_e76(Rgb8 a, Rgb8 b);
struct Lab {
  double L = 0, a = 0, b = 0;
};
Lab srgb_to_lab(Rgb8 c);

}  // namespace cb
