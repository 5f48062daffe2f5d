// The figures as pictures, drawn by the cairo backend (src/figure_cairo): every figure against
// its golden (tests/golden/figures/, light; figures/dark/ for two), data on the pixels their
// axes map them to, the light theme's border, text contrast on drawn pixels, SVG and PDF
// checked by independent tools (xmllint, pdfinfo, pdffonts, pdftotext), and the `figures`
// command as a user runs it.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "exact/exact_chain.h"
#include "figure_cairo/figure_draw.h"
#include "figure_cairo/figure_layout.h"
#include "figure_cairo/figure_output.h"
#include "figure_test_support.h"
#include "figures/trajectories.h"
#include "gl_test_support.h"
#include "golden_support.h"
#include "test_support.h"

namespace {

using cb::test::built_figure;
using cb::test::channel_distance;

const cb::Theme& light() {
  return cb::theme(cb::ThemeName::Light);
}
const cb::Theme& dark() {
  return cb::theme(cb::ThemeName::Dark);
}

cb::FigurePanelLayout panel_layout(const cb::Figure& f, std::size_t panel) {
  return cb::figure_layout(f, cb::kFigureWidth, cb::kFigureHeight).panels.at(panel);
}

// The pixel a data point lands on (floor of its figure units: pixel (i, j) covers
// [i, i + 1) x [j, j + 1)).
std::pair<int, int> pixel_of(const cb::FigureMapping& m, double x, double y) {
  return {static_cast<int>(std::floor(m.px(x))), static_cast<int>(std::floor(m.py(y)))};
}

// Where a disc of colour `c` drawn over `under` sits: the centroid of its coverage in the
// (2r+1)^2 pixels around (x, y), each pixel's coverage read off its blend of the two colours
// in the channel where they differ most; pixel (i, j) has its centre at (i + 0.5, j + 0.5).
std::pair<double, double> coverage_centroid(const cb::Image& image, int x, int y, int r, cb::Rgb8 c,
                                            cb::Rgb8 under) {
  const int dr = c.r - under.r, dg = c.g - under.g, db = c.b - under.b;
  const int channel = std::abs(dr) >= std::abs(dg) && std::abs(dr) >= std::abs(db) ? 0
                      : std::abs(dg) >= std::abs(db)                               ? 1
                                                                                   : 2;
  const double from = channel == 0 ? under.r : channel == 1 ? under.g : under.b;
  const double span = channel == 0 ? dr : channel == 1 ? dg : db;
  double sum = 0, sx = 0, sy = 0;
  for (int j = y - r; j <= y + r; ++j)
    for (int i = x - r; i <= x + r; ++i) {
      const double a = std::clamp((image.pixel(i, j)[channel] - from) / span, 0.0, 1.0);
      sum += a;
      sx += a * (i + 0.5);
      sy += a * (j + 0.5);
    }
  return {sx / sum, sy / sum};
}

// The strongest contrast any pixel of the box has against `background`: a text's darkest
// (light theme) or lightest (dark theme) glyph pixel, where its stems are fully covered.
// Also counts the pixels that are exactly the background, to prove the box holds text on it.
struct TextSample {
  double contrast = 1.0;
  int background_pixels = 0, pixels = 0;
};
TextSample sample_text(const cb::Image& image, const cb::FigureBox& box, cb::Rgb8 background) {
  TextSample s;
  for (int y = static_cast<int>(box.y); y < static_cast<int>(box.bottom()); ++y)
    for (int x = static_cast<int>(box.x); x < static_cast<int>(box.right()); ++x) {
      const std::uint8_t* p = image.pixel(x, y);
      const cb::Rgb8 c{p[0], p[1], p[2]};
      ++s.pixels;
      if (c == background) ++s.background_pixels;
      s.contrast = std::max(s.contrast, cb::contrast_ratio(c, background));
    }
  return s;
}

// Letters only: pdftotext spaces words and subscripts as the layout suggests, and the
// figures' "_c" markup becomes a lowered c.
std::string squeeze(const std::string& text) {
  std::string out;
  for (char ch : text)
    if (ch != ' ' && ch != '\n' && ch != '_' && ch != '\f') out += ch;
  return out;
}

// The character content of each <text> element of an SVG, its tags taken out (one string per
// label, its runs and subscripts joined).
std::vector<std::string> svg_texts(const std::string& svg) {
  std::vector<std::string> texts;
  for (std::size_t at = svg.find("<text"); at != std::string::npos; at = svg.find("<text", at)) {
    const std::size_t end = svg.find("</text>", at);
    std::string content;
    bool in_tag = false;
    for (std::size_t i = svg.find('>', at) + 1; i < end; ++i) {
      if (svg[i] == '<' || svg[i] == '>')
        in_tag = svg[i] == '<';
      else if (!in_tag)
        content += svg[i];
    }
    texts.push_back(content);
    at = end;
  }
  return texts;
}

}  // namespace

TEST_CASE("Figures match their goldens within tolerance", "[figures][golden]") {
  for (const cb::FigureEntry& e : cb::figure_entries()) {
    const cb::Image image = cb::figure_image(built_figure(e.name), light());
    REQUIRE(image.width == cb::kFigureWidth);
    REQUIRE(image.height == cb::kFigureHeight);
    cb::test::check_golden_image("figures/" + e.name, "cairo", true, image);
  }
  // The dark theme: a figure of curves and one of a heatmap.
  for (const char* name : {"fig4a", "fig3a"})
    cb::test::check_golden_image(std::string("figures/dark/") + name, "cairo", true,
                                 cb::figure_image(built_figure(name), dark()));
}

TEST_CASE("Figures: points and lines land on the pixels their data give", "[figures]") {
  // Hand-made: a line y = x / 2 and two points well apart from it, on a log x axis inset
  // over a plain panel, so both mappings are exercised.
  cb::Figure f;
  cb::Panel main;
  main.x = cb::axis("x", 0.0, 100.0);
  main.y = cb::axis("y", -10.0, 60.0);
  main.series.push_back(cb::make_series("line", cb::SeriesStyle::Line, cb::FigureColour::Series0,
                                        cb::linspace(0, 100, 201), {}));
  for (double x : main.series[0].x) main.series[0].y.push_back(x / 2.0);
  main.series.push_back(cb::make_series("dots", cb::SeriesStyle::Points, cb::FigureColour::Series2,
                                        {23.0, 71.0}, {43.0, 7.0}));
  cb::Panel inset;
  inset.x = cb::axis("\u03B2", 0.01, 10.0, true);
  inset.y = cb::axis("", 0.0, 1.0);
  inset.series.push_back(
      cb::make_series("dot", cb::SeriesStyle::Points, cb::FigureColour::Series1, {0.3}, {0.45}));
  inset.inset = true;
  inset.left = 0.6f;
  inset.top = 0.05f;
  inset.width = 0.35f;
  inset.height = 0.35f;
  f.panels = {main, inset};
  const cb::Theme& theme = GENERATE(light(), dark());
  INFO("theme " << cb::theme_name(theme.name));
  const cb::Image image = cb::figure_image(f, theme);
  const cb::Rgb8 line = cb::figure_rgb(cb::FigureColour::Series0, theme);
  const cb::Rgb8 dots = cb::figure_rgb(cb::FigureColour::Series2, theme);

  const cb::FigureMapping m = panel_layout(f, 0).mapping;
  // A point's disc (radius 4.2 px) is opaque at its centre: exactly its colour; 12 px above,
  // not. The centroid of its coverage (antialiased edges included) is where the axes map the
  // data, to a fifth of a pixel.
  for (auto [x, y] : {std::pair{23.0, 43.0}, {71.0, 7.0}}) {
    const auto [px, py] = pixel_of(m, x, y);
    INFO("point (" << x << ", " << y << ") at pixel (" << px << ", " << py << ")");
    CHECK(channel_distance(image, px, py, dots) == 0);
    CHECK(channel_distance(image, px, py - 12, dots) > 60);
    const auto [cx, cy] = coverage_centroid(image, px, py, 7, dots, theme.panel);
    CHECK(cx == Approx(m.px(x)).margin(0.2));
    CHECK(cy == Approx(m.py(y)).margin(0.2));
  }
  // The line (2 px wide) passes through its pixel: within a row of the mapped y, a pixel of
  // its colour (antialiased edges are lighter); 6 px above and below, not.
  for (double x : {15.0, 33.0, 57.0}) {  // below the inset, right of the legend
    const auto [px, py] = pixel_of(m, x, x / 2);
    int nearest = 255;
    for (int y = py - 1; y <= py + 1; ++y)
      nearest = std::min(nearest, channel_distance(image, px, y, line));
    INFO("line at x = " << x << ", pixel (" << px << ", " << py << ")");
    CHECK(nearest <= 12);
    CHECK(channel_distance(image, px, py - 6, line) > 60);
    CHECK(channel_distance(image, px, py + 6, line) > 60);
  }
  // On the log axis of the inset, beta = 0.3 sits at log10(0.3) between 0.01 and 10.
  const cb::FigureMapping l = panel_layout(f, 1).mapping;
  const double expected_x = l.area.x + (std::log10(0.3) + 2.0) / 3.0 * l.area.w;
  CHECK(l.px(cb::axis_value(f.panels[1].x, 0.3)) == Approx(expected_x).epsilon(1e-12));
  const int px = static_cast<int>(std::floor(expected_x));
  const int py = static_cast<int>(std::floor(l.py(0.45)));
  const cb::Rgb8 dot = cb::figure_rgb(cb::FigureColour::Series1, theme);
  CHECK(channel_distance(image, px, py, dot) == 0);
  const auto [cx, cy] = coverage_centroid(image, px, py, 6, dot, theme.panel);
  CHECK(cx == Approx(expected_x).margin(0.2));
  CHECK(cy == Approx(l.py(0.45)).margin(0.2));
}

TEST_CASE("Figures: a real figure's curve, Fig. 4(b)'s kinetic energy", "[figures]") {
  const cb::Figure& f = built_figure("fig4b");
  const cb::Image image = cb::figure_image(f, light());
  const cb::FigureMapping m = panel_layout(f, 0).mapping;
  const cb::Series& kinetic = cb::test::series_of(f, "kinetic");
  const cb::Rgb8 colour = cb::figure_rgb(kinetic.colour, light());
  for (std::size_t i : {250u, 290u, 370u}) {  // tau = 62.5, 72.5, 92.5: clear of the others
    const auto [px, py] = pixel_of(m, kinetic.x[i], kinetic.y[i]);
    int nearest = 255;
    for (int y = py - 1; y <= py + 1; ++y)
      nearest = std::min(nearest, channel_distance(image, px, y, colour));
    INFO("kinetic at tau = " << kinetic.x[i] << ", pixel (" << px << ", " << py << ")");
    CHECK(nearest <= 12);
  }
}

TEST_CASE("Figures: the light theme's border is its background, all around", "[figures]") {
  for (const cb::FigureEntry& e : cb::figure_entries()) {
    const cb::Image image = cb::figure_image(built_figure(e.name), light());
    int wrong = 0;
    for (int x = 0; x < image.width; ++x)
      for (int y : {0, image.height - 1})
        wrong += channel_distance(image, x, y, light().background) != 0;
    for (int y = 0; y < image.height; ++y)
      for (int x : {0, image.width - 1})
        wrong += channel_distance(image, x, y, light().background) != 0;
    INFO(e.name << ": border pixels that are not the background");
    CHECK(wrong == 0);
  }
}

TEST_CASE("Figures: text reads at 7:1 or more against its background, both themes",
          "[figures][contrast]") {
  const cb::Theme& theme = GENERATE(light(), dark());
  INFO("theme " << cb::theme_name(theme.name));
  const cb::Figure& f = built_figure("fig4a");
  const cb::Image image = cb::figure_image(f, theme);
  const cb::FigurePanelLayout l = panel_layout(f, 0);
  const cb::FigureMetrics m = cb::figure_metrics(cb::kFigureHeight);
  const cb::FigureBox& a = l.mapping.area;
  // The x axis' label (τ), the rotated y axis' label (φⱼ), the title's first words and the
  // first x tick label ("0"), each in a box of background around it.
  const struct {
    const char* what;
    cb::FigureBox box;
  } texts[] = {
      {"x label", {a.x + 0.5 * a.w - m.font, l.x_label_y - 0.7 * m.font, 2 * m.font, 1.4 * m.font}},
      {"y label", {l.y_label_x - 0.7 * m.font, a.y + 0.5 * a.h - m.font, 1.4 * m.font, 2 * m.font}},
      {"title", {l.box.x, l.title_y - 0.7 * m.font, 6 * m.font, 1.4 * m.font}},
      {"tick label", {a.x - 0.6 * m.small, a.bottom() + m.tick + 1, 1.2 * m.small, 1.2 * m.small}},
  };
  for (const auto& t : texts) {
    const TextSample s = sample_text(image, t.box, theme.background);
    INFO(t.what << ": strongest contrast " << s.contrast << ", " << s.background_pixels << " of "
                << s.pixels << " pixels are the background");
    CHECK(s.background_pixels > s.pixels / 3);  // text on the background, not a filled box
    CHECK(s.background_pixels < s.pixels);      // and some text there
    CHECK(s.contrast >= 7.0);
  }
  // Notes drawn in a data colour are darkened (light) or lightened (dark) until they read.
  for (cb::FigureColour c : {cb::FigureColour::Accent, cb::FigureColour::Kinetic,
                             cb::FigureColour::Series2, cb::FigureColour::Potential}) {
    const cb::Rgb8 text = cb::readable_on(theme, cb::figure_rgb(c, theme));
    CHECK(cb::contrast_ratio(text, theme.background) >= 7.0);
    CHECK(cb::contrast_ratio(text, theme.panel) >= 7.0);
  }
}

// Every figure in every format, as a user makes them; the files checked by independent tools.
// How long the command takes is a benchmark's business, not a test's (README: Figures).
TEST_CASE("figures command: PNG, SVG, PDF and CSV per figure, checked by xmllint and poppler",
          "[figures][cli]") {
  const cb::test::TempDir dir("chainbreak-figures");
  const auto r = cb::test::run_chainbreak("figures -q --format png,svg,pdf -o " + dir.file("out"));
  INFO(r.err);
  REQUIRE(r.status == 0);
  for (const cb::FigureEntry& e : cb::figure_entries()) {
    INFO(e.name);
    const std::string stem = dir.file("out/" + e.name);
    for (const char* ext : {".png", ".svg", ".pdf", ".csv"})
      CHECK(r.out.find(stem + ext + "\n") != std::string::npos);
    CHECK(std::filesystem::file_size(stem + ".png") > 10000);
    // The default theme is light: the PNG is the light figure, pixel for pixel.
    const cb::ImageDiff d = cb::compare_images(cb::read_png(stem + ".png"),
                                               cb::figure_image(built_figure(e.name), light()), 0);
    CHECK((d.same_size && d.max_channel == 0));

    const auto lint = cb::test::run_shell("xmllint --noout " + stem + ".svg");
    INFO(lint.err);
    CHECK(lint.status == 0);
    // The SVG's labels are real text (selectable, searchable): each axis label is one <text>
    // element, and no glyph is drawn as an outline (cairo's <symbol id="glyph...">).
    const std::string svg = cb::test::slurp(stem + ".svg");
    CHECK(svg.find("<symbol") == std::string::npos);
    std::vector<std::string> svg_labels;
    for (const std::string& t : svg_texts(svg)) svg_labels.push_back(squeeze(t));
    const auto info = cb::test::run_shell("pdfinfo " + stem + ".pdf");
    INFO(info.err);
    CHECK(info.status == 0);
    CHECK(std::regex_search(info.out, std::regex("Pages: +1\n")));
    CHECK(info.out.find("600 x 400 pts") != std::string::npos);  // kPdfScale of 1200 x 800
    // The typeface is embedded (pdffonts' "emb" column) and is DejaVu.
    const auto fonts = cb::test::run_shell("pdffonts " + stem + ".pdf");
    CHECK(fonts.out.find("DejaVuSans") != std::string::npos);
    CHECK(fonts.out.find(" no  ") == std::string::npos);  // no font left out
    // The axis labels are text, found by pdftotext (each panel's x and y label).
    const auto text = cb::test::run_shell("pdftotext " + stem + ".pdf -");
    REQUIRE(text.status == 0);
    const cb::Figure& f = built_figure(e.name);
    for (const cb::Panel& p : f.panels)
      for (const std::string& label : {p.x.label, p.y.label}) {
        INFO("axis label '" << label << "'");
        CHECK(squeeze(text.out).find(squeeze(label)) != std::string::npos);
        if (!label.empty())
          CHECK(std::count(svg_labels.begin(), svg_labels.end(), squeeze(label)) >= 1);
      }
  }

  // One element per plotted point in the SVG: fig4a's φ₃₀ RK4 is its only filled series in
  // Series2's colour; its points plus the legend's dot. cairo writes a fill as
  // fill:rgb(R%,G%,B%), the channels in percent. The expected count is the CSV's rows of it.
  const std::string svg = cb::test::slurp(dir.file("out/fig4a.svg"));
  const cb::Rgb8 c = cb::figure_rgb(cb::FigureColour::Series2, light());
  int filled = 0;
  double first_x = -1, first_y = -1;  // where the first of them starts
  for (std::size_t at = svg.find("<path"); at != std::string::npos;
       at = svg.find("<path", at + 1)) {
    const std::string element = svg.substr(at, svg.find('>', at) - at);
    const std::size_t style = element.find("fill:rgb(");
    double r = -1, g = -1, b = -1;
    if (style == std::string::npos || element.find("fill-opacity:1") == std::string::npos ||
        std::sscanf(element.c_str() + style, "fill:rgb(%lf%%,%lf%%,%lf%%)", &r, &g, &b) != 3)
      continue;
    const auto near = [](double percent, std::uint8_t v) {
      return std::abs(percent * 2.55 - v) < 0.5;
    };
    const bool ours = near(r, c.r) && near(g, c.g) && near(b, c.b);
    if (ours && filled == 0) {
      const std::size_t d = element.find(" d=\"M ");
      REQUIRE(d != std::string::npos);
      REQUIRE(std::sscanf(element.c_str() + d, " d=\"M %lf %lf", &first_x, &first_y) == 2);
    }
    filled += ours;
  }
  std::istringstream rows(cb::test::slurp(dir.file("out/fig4a.csv")));
  int points = 0;
  for (std::string row; std::getline(rows, row);)
    points += row.rfind("0,\"\u03C6\u2083\u2080 RK4\",points,", 0) == 0;
  REQUIRE(points > 50);
  CHECK(filled == points + 1);
  // The same layout as the PNG: the first point's disc starts (cairo_arc from angle 0) at its
  // mapped centre plus the radius, in SVG user units that are the PNG's pixels.
  const cb::Figure& fig4a = built_figure("fig4a");
  const cb::Series& rk4 = cb::test::series_of(fig4a, "\u03C6\u2083\u2080 RK4");
  const cb::FigureMapping m = panel_layout(fig4a, 0).mapping;
  CHECK(first_x ==
        Approx(m.px(rk4.x[0]) + cb::figure_metrics(cb::kFigureHeight).point).margin(1e-3));
  CHECK(first_y == Approx(m.py(rk4.y[0])).margin(1e-3));

  // The CSV holds the plotted numbers: fig4a's phi_30 RK4 row at tau = 150 is the exact
  // solution's phi_30 there, to RK4's accuracy.
  const std::string csv = cb::test::slurp(dir.file("out/fig4a.csv"));
  CHECK(csv.rfind("panel,series,style,x,y,z\n", 0) == 0);
  const std::string key = "0,\"\u03C6\u2083\u2080 RK4\",points,150,";
  const auto row = csv.find(key);
  REQUIRE(row != std::string::npos);
  const cb::ExactChain exact(30, 0.0, cb::unit_ramp());
  CHECK(std::stod(csv.substr(row + key.size())) == Approx(exact.phi(30, 150.0)).margin(1e-6));
}

TEST_CASE("figures command: themes, a subset of formats, clear errors", "[figures][cli]") {
  const cb::test::TempDir dir("chainbreak-figures-flags");
  const auto r = cb::test::run_chainbreak(
      "figures -q --only fig3b --theme dark --format pdf,svg -o " + dir.file("d"));
  INFO(r.err);
  REQUIRE(r.status == 0);
  CHECK(r.out == dir.file("d/fig3b.pdf") + "\n" + dir.file("d/fig3b.svg") + "\n" +
                     dir.file("d/fig3b.csv") + "\n");
  CHECK(!std::filesystem::exists(dir.file("d/fig3b.png")));
  // The dark theme's background fills the SVG (cairo writes the first fill as a rect or path).
  const cb::Rgb8 bg = dark().background;
  char percent[64];
  std::snprintf(percent, sizeof percent, "fill:rgb(%.0f", 100.0 * bg.r / 255.0);
  CHECK(cb::test::slurp(dir.file("d/fig3b.svg")).find(percent) != std::string::npos);

  const auto bad_theme = cb::test::run_chainbreak("figures -q --theme sepia -o " + dir.file("x"));
  CHECK(bad_theme.status == 2);
  CHECK(bad_theme.err.find("--theme sepia") != std::string::npos);
  CHECK(bad_theme.err.find("light") != std::string::npos);
  const auto bad_format =
      cb::test::run_chainbreak("figures -q --format png,eps -o " + dir.file("x"));
  CHECK(bad_format.status == 2);
  CHECK(bad_format.err.find("--format png,eps") != std::string::npos);
  CHECK(!std::filesystem::exists(dir.file("x")));  // refused before any folder or file
  const auto bad = cb::test::run_chainbreak("figures -q --only fig9 -o " + dir.file("x"));
  CHECK(bad.status == 2);
  CHECK(bad.err.find("fig4a") != std::string::npos);  // lists the known names
  std::filesystem::create_directories(dir.file("out"));
  std::ofstream(dir.file("out/fig4a.png")) << "a file";
  const auto file_parent =
      cb::test::run_chainbreak("figures -q --only fig4a -o " + dir.file("out/fig4a.png/sub"));
  CHECK(file_parent.status == 2);
  CHECK(file_parent.err.find("-o") != std::string::npos);
}

TEST_CASE("Figures: tick labels and the --format list", "[figures][ticks]") {
  // Round numbers: step 20 over [0, 150] (nice_ticks' 1-2-5 rule), labels without decimals.
  const cb::Ticks t = cb::axis_ticks(cb::axis("\u03C4", 0.0, 150.0), 8);
  CHECK(t.values == std::vector<double>{0, 20, 40, 60, 80, 100, 120, 140});
  CHECK(t.labels.front() == "0");
  CHECK(t.labels.back() == "140");
  // Negative values get a true minus sign (U+2212), decimals follow the step.
  const cb::Ticks n = cb::axis_ticks(cb::axis("", -1.0, 1.0), 4);
  CHECK(n.labels == std::vector<std::string>{"\u22121.0", "\u22120.5", "0.0", "0.5", "1.0"});
  // A log axis from 0.01 to 10: 1, 2, 5 times each power of ten, at log10 of the value.
  const cb::Ticks l = cb::axis_ticks(cb::axis("", 0.01, 10.0, true), 8);
  CHECK(l.labels ==
        std::vector<std::string>{"0.01", "0.02", "0.05", "0.1", "0.2", "0.5", "1", "2", "5", "10"});
  CHECK(l.values[3] == Approx(-1.0).margin(1e-12));

  // The plots of the overlay and the page: the energy per particle, 0 to 6e-6, shares a
  // power of ten shown once; time axes get SI suffixes past 1e4.
  const cb::Ticks e = cb::nice_ticks(0.0, 6.5e-6, 4);
  const cb::TickFormat ef = cb::tick_format(e);
  CHECK(ef.exponent == -6);
  CHECK(cb::tick_label(e.values.back(), ef) == "6");
  CHECK(cb::tick_label(-2e-6, ef) == "\u22122");  // step 2e-6: no decimals
  CHECK(cb::power_of_ten_text(ef.exponent) == "\u00D710\u207B\u2076");
  CHECK(cb::power_of_ten_text(12) == "\u00D710\u00B9\u00B2");
  CHECK(cb::tick_format(cb::nice_ticks(0.0, 10.0, 5)).exponent == 0);
  const cb::Ticks tau = cb::nice_ticks(0.0, 60000.0, 5);  // step 20000
  CHECK(cb::x_tick_label(40000.0, tau) == "40k");
  CHECK(cb::x_tick_label(3000.0, cb::nice_ticks(0.0, 3000.0, 5)) == "3000");
  CHECK(cb::x_tick_label(1.5e6, cb::nice_ticks(0.0, 2.5e6, 5)) == "1.5M");
  CHECK(cb::x_tick_label(0.5, cb::nice_ticks(0.0, 2.0, 4)) == "0.5");

  using F = cb::FigureFormat;
  CHECK(cb::parse_figure_formats("png") == std::vector<F>{F::Png});
  CHECK(cb::parse_figure_formats("pdf,png,svg") == std::vector<F>{F::Pdf, F::Png, F::Svg});
  CHECK(!cb::parse_figure_formats(""));
  CHECK(!cb::parse_figure_formats("png,png"));
  CHECK(!cb::parse_figure_formats("png,"));
  CHECK(!cb::parse_figure_formats("PNG"));
}
