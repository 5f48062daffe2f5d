// The themes' colour roles: text contrast (WCAG 2 AAA, >= 7:1) against every background it is
// drawn on, and the colour-science helpers against published values.
#include <catch2/catch.hpp>
#include <cstdlib>

#include "theme/fonts.h"
#include "theme/theme.h"

using namespace cb;

TEST_CASE("contrast_ratio and delta_e76 match published values", "[theme]") {
  // WCAG 2: black on white is 21:1, a colour against itself 1:1.
  CHECK(contrast_ratio({0, 0, 0}, {255, 255, 255}) == Approx(21.0).epsilon(1e-9));
  CHECK(contrast_ratio({119, 119, 119}, {255, 255, 255}) == Approx(4.48).margin(0.01));
  CHECK(contrast_ratio({40, 50, 60}, {40, 50, 60}) == Approx(1.0));
  // CIELAB of sRGB primaries (D65; e.g. Bruce Lindbloom's calculator): red (53.24, 80.09, 67.20).
  const Lab red = srgb_to_lab({255, 0, 0});
  CHECK(red.L == Approx(53.24).margin(0.02));
  CHECK(red.a == Approx(80.09).margin(0.05));
  CHECK(red.b == Approx(67.20).margin(0.05));
  CHECK(delta_e76({0, 0, 0}, {255, 255, 255}) == Approx(100.0).margin(0.01));
}

TEST_CASE("every theme's text reaches 7:1 on its background and its panels", "[theme]") {
  for (ThemeName name : {ThemeName::Dark, ThemeName::Light}) {
    const Theme& t = theme(name);
    INFO(theme_name(name));
    for (Rgb8 fg : {t.text, t.text_dim, t.marker}) {  // the marker colour labels breaks
      CHECK(contrast_ratio(fg, t.background) >= 7.0);
      CHECK(contrast_ratio(fg, t.panel) >= 7.0);
    }
  }
}

TEST_CASE("themes parse by name and nothing else", "[theme]") {
  CHECK(parse_theme("light") == ThemeName::Light);
  CHECK(parse_theme("dark") == ThemeName::Dark);
  CHECK_FALSE(parse_theme("Light").has_value());
  CHECK_FALSE(parse_theme("").has_value());
  CHECK(theme(ThemeName::Light).background == Rgb8{255, 255, 255});
}

TEST_CASE("the typeface is found, and a missing folder is named", "[theme]") {
  CHECK_NOTHROW(font_path(FontFace::Sans));
  setenv("CHAINBREAK_FONT_DIR", "/nonexistent-fonts", 1);
  CHECK_THROWS_WITH(font_path(FontFace::Sans),
                    Catch::Contains("fonts-dejavu-core"));
  unsetenv("CHAINBREAK_FONT_DIR");
}
