// The strain colour map, strain_color(s) with s = phi / phi_c.
//
// Design note: the map is built in CIELAB (D65) so that its steps are perceptually even and
// its lightness is exact:
//  - L* rises linearly from 30 at s = -1 to 92 at s = +1. Lightness alone orders the whole
//    scale, so compression and tension stay apart in greyscale print, on a projector that
//    washes colour out, and for every kind of colour blindness.
//  - Hue: blue-violet (h ~ 285..302 deg) for compression, orange turning golden
//    (h ~ 62..98 deg) for tension. Blue against orange/yellow is the one opponent axis that
//    deuteranopes and protanopes (red-green confusion) keep, so the sign reads in colour too.
//  - Chroma is zero at s = 0 (a neutral grey: a spring at rest carries no colour) and grows
//    with |s|, held below 90% of the sRGB gamut boundary at that L* and hue, so no colour is
//    clipped and lightness survives the conversion. Over the last 10% (|s| > 0.9) chroma
//    rises to 97% of the boundary: a spring about to break visibly saturates. At the dark
//    end that is a deep pure blue. At the bright end a hot red-magenta is out of reach (at
//    L* ~ 90 sRGB allows it a chroma of ~15, a pale pink), so tension heats towards a
//    saturated golden yellow instead, the brightest and most chromatic colour there is at that
//    lightness, like the white-hot end of a blackbody scale; the lightness order is kept.
// The map is tabulated once (1025 entries, so s = -1, 0, +1 fall on entries) on first use;
// a function-local static is initialised thread-safely. Lookups interpolate linearly.
#include <algorithm>
#include <array>
#include <cmath>

#include "snapshot/snapshot.h"

namespace cb {

namespace {

constexpr int kLutSize = 1025;
constexpr double kPi = 3.14159265358979323846;

struct Linear {
  double r, g, b;
};

// CIELAB -> linear sRGB for the D65 white point (IEC 61966-2-1 matrix).
Linear lab_to_linear(double L, double a, double b) {
  const auto finv = [](double t) {
    constexpr double d = 6.0 / 29.0;
    return t > d ? t * t * t : 3.0 * d * d * (t - 4.0 / 29.0);
  };
  const double fy = (L + 16.0) / 116.0;
  const double x = 0.95047 * finv(fy + a / 500.0);
  const double y = 1.00000 * finv(fy);
  const double z = 1.08883 * finv(fy - b / 200.0);
  return {3.2404542 * x - 1.5371385 * y - 0.4985314 * z,
          -0.9692660 * x + 1.8760108 * y + 0.0415560 * z,
          0.0556434 * x - 0.2040259 * y + 1.0572252 * z};
}

Linear lch_to_linear(double L, double chroma, double hue_deg) {
  const double h = hue_deg * kPi / 180.0;
  return lab_to_linear(L, chroma * std::cos(h), chroma * std::sin(h));
}

bool in_gamut(const Linear& c) {
  constexpr double eps = 1e-9;
  return c.r >= -eps && c.r <= 1 + eps && c.g >= -eps && c.g <= 1 + eps && c.b >= -eps &&
         c.b <= 1 + eps;
}

// The largest chroma sRGB can show at this lightness and hue (bisection; the gamut is convex
// along a ray of constant L* and hue from the grey axis).
double max_chroma(double L, double hue_deg) {
  double lo = 0.0, hi = 200.0;
  for (int i = 0; i < 40; ++i) {
    const double mid = 0.5 * (lo + hi);
    (in_gamut(lch_to_linear(L, mid, hue_deg)) ? lo : hi) = mid;
  }
  return lo;
}

float encode_srgb(double v) {
  v = std::clamp(v, 0.0, 1.0);  // only rounding error is out of range (chroma is in gamut)
  return static_cast<float>(v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055);
}

double smoothstep(double t) {
  t = std::clamp(t, 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}

// The theme sets the lightness range (dark: L* 30..92, light: 26..86, theme/theme.h).
Color design_color(double s, double l_min, double l_max) {
  const double u = std::abs(s);
  const double L = 0.5 * (l_min + l_max) + 0.5 * (l_max - l_min) * s;
  double hue, chroma;
  if (s < 0) {
    hue = 285.0 + 17.0 * u;  // blue-violet -> deep blue
    chroma = 75.0 * u;
  } else {
    hue = 62.0 + 36.0 * u * u;  // orange, turning golden as the gamut narrows at high L*
    chroma = 66.0 * u;
  }
  const double boundary = max_chroma(L, hue);
  chroma = std::min(chroma, 0.9 * boundary);
  chroma += (0.97 * boundary - chroma) * smoothstep((u - 0.9) / 0.1);  // saturate near breaking
  const Linear c = lch_to_linear(L, chroma, hue);
  return Color{encode_srgb(c.r), encode_srgb(c.g), encode_srgb(c.b), 1.0f};
}

using Lut = std::array<Color, kLutSize>;

Lut build_lut(const Theme& theme) {
  Lut lut;
  for (int i = 0; i < kLutSize; ++i)
    lut[i] = design_color(-1.0 + 2.0 * i / (kLutSize - 1), theme.strain_l_min, theme.strain_l_max);
  return lut;
}

}  // namespace

Color strain_color(double s) { return strain_color(s, ThemeName::Dark); }

Color strain_color(double s, ThemeName theme_name) {
  static const Lut dark = build_lut(theme(ThemeName::Dark));
  static const Lut light = build_lut(theme(ThemeName::Light));
  const Lut& lut = theme_name == ThemeName::Light ? light : dark;
  if (std::isnan(s)) s = 0.0;  // a non-finite state shows as unstrained rather than garbage
  const double t = (std::clamp(s, -1.0, 1.0) + 1.0) * 0.5 * (kLutSize - 1);
  const int i = std::min(static_cast<int>(t), kLutSize - 2);
  const float w = static_cast<float>(t - i);
  const Color& a = lut[i];
  const Color& b = lut[i + 1];
  return Color{a.r + (b.r - a.r) * w, a.g + (b.g - a.g) * w, a.b + (b.b - a.b) * w, 1.0f};
}

}  // namespace cb
