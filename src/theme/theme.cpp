#include "theme/theme.h"

#include <algorithm>
#include <cmath>

namespace cb {

namespace {

// Dark: the projector theme, as the videos have always looked.
constexpr Theme kDark{
    .name = ThemeName::Dark,
    .background = {23, 24, 28},
    .panel = {30, 31, 36},
    .text = {232, 232, 236},
    .text_dim = {178, 181, 188},
    .axis = {96, 99, 108},
    .border = {58, 60, 67},
    .grid = {44, 46, 52},
    .rest_line = {70, 72, 80},
    .wall = {150, 153, 160},
    .bead = {215, 218, 225},
    .force = {240, 240, 244},
    .accent = {213, 94, 0},
    .marker = {255, 200, 90},
    .cursor = {110, 112, 120},
    .series = {{86, 180, 233}, {0, 158, 115}, {230, 159, 0}},
    .total = {236, 236, 240},
    .kinetic = {204, 121, 167},
    .potential = {240, 228, 66},
    .bar = {86, 180, 233},
    .strain_l_min = 30,
    .strain_l_max = 92,
};

// Light: paper and handouts, black on white like the paper's figures. The strain map's bright
// end is pulled down to L* 86 so that tension stays visible on white; its zero-strain grey
// (L* 56) is far from the background in both themes.
constexpr Theme kLight{
    .name = ThemeName::Light,
    .background = {255, 255, 255},
    .panel = {248, 248, 250},
    .text = {17, 17, 20},
    .text_dim = {68, 70, 76},
    .axis = {60, 62, 68},
    .border = {200, 202, 208},
    .grid = {222, 223, 228},
    .rest_line = {190, 192, 198},
    .wall = {90, 92, 98},
    .bead = {60, 62, 70},
    .force = {17, 17, 20},
    .accent = {213, 94, 0},
    .marker = {125, 62, 0},  // amber darkened to 7.7:1 on the panel: HUD and marker text use it
    .cursor = {150, 152, 160},
    .series = {{0, 114, 178}, {0, 158, 115}, {230, 159, 0}},
    .total = {17, 17, 20},
    .kinetic = {204, 121, 167},
    .potential = {170, 140, 0},
    .bar = {0, 114, 178},
    .strain_l_min = 26,
    .strain_l_max = 86,
};

double linear(std::uint8_t v) {
  const double c = v / 255.0;
  return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

double luminance(Rgb8 c) {  // WCAG 2 relative luminance
  return 0.2126 * linear(c.r) + 0.7152 * linear(c.g) + 0.0722 * linear(c.b);
}

}  // namespace

const Theme& theme(ThemeName name) { return name == ThemeName::Light ? kLight : kDark; }

std::optional<ThemeName> parse_theme(const std::string& text) {
  if (text == "dark") return ThemeName::Dark;
  if (text == "light") return ThemeName::Light;
  return std::nullopt;
}

const char* theme_name(ThemeName name) { return name == ThemeName::Light ? "light" : "dark"; }

double contrast_ratio(Rgb8 a, Rgb8 b) {
  const double la = luminance(a), lb = luminance(b);
  return (std::max(la, lb) + 0.05) / (std::min(la, lb) + 0.05);
}

Lab srgb_to_lab(Rgb8 c) {
  // sRGB (D65) -> XYZ (IEC 61966-2-1) -> CIELAB.
  const double r = linear(c.r), g = linear(c.g), b = linear(c.b);
  const double x = (0.4124564 * r + 0.3575761 * g + 0.1804375 * b) / 0.95047;
  const double y = (0.2126729 * r + 0.7151522 * g + 0.0721750 * b) / 1.00000;
  const double z = (0.0193339 * r + 0.1191920 * g + 0.9503041 * b) / 1.08883;
  const auto f = [](double t) {
    constexpr double d = 6.0 / 29.0;
    return t > d * d * d ? std::cbrt(t) : t / (3.0 * d * d) + 4.0 / 29.0;
  };
  return {116.0 * f(y) - 16.0, 500.0 * (f(x) - f(y)), 200.0 * (f(y) - f(z))};
}

double delta_e76(Rgb8 a, Rgb8 b) {
  const Lab p = srgb_to_lab(a), q = srgb_to_lab(b);
  return std::sqrt((p.L - q.L) * (p.L - q.L) + (p.a - q.a) * (p.a - q.a) +
                   (p.b - q.b) * (p.b - q.b));
}

}  // namespace cb
