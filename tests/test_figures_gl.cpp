// The figures as pictures: every figure against its golden (tests/golden/figures/), the
// curves on the pixels their data give, and the `figures` command as a user runs it.
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>

#include "app/figure_image.h"
#include "exact/exact_chain.h"
#include "figure_test_support.h"
#include "figures/trajectories.h"
#include "gl_test_support.h"
#include "golden_support.h"
#include "overlay/figure_drawing.h"
#include "overlay/overlay.h"
#include "test_support.h"

namespace {

using cb::test::built_figure;
using cb::test::channel_distance;

struct FigureCanvas {
  std::unique_ptr<cb::GlContext> context;
  std::unique_ptr<cb::Renderer> renderer;
  std::unique_ptr<cb::FigureDrawer> drawer;
  explicit FigureCanvas(cb::GlBackend backend) : context(cb::test::create_or_skip(backend)) {
    if (!context) return;
    renderer = std::make_unique<cb::Renderer>(cb::kFigureWidth, cb::kFigureHeight);
    drawer = std::make_unique<cb::FigureDrawer>(cb::kFigureWidth, cb::kFigureHeight);
  }
  cb::Image draw(const cb::Figure& f) { return cb::figure_image(*renderer, *drawer, f); }
};

}  // namespace

TEST_CASE("Figures match their goldens within tolerance", "[figures][golden]") {
  const cb::GlBackend backend = GENERATE(cb::GlBackend::OSMesa, cb::GlBackend::Egl);
  INFO("backend " << cb::gl_backend_name(backend));
  FigureCanvas canvas(backend);
  if (!canvas.context) return;
  for (const cb::FigureEntry& e : cb::figure_entries()) {
    const cb::Image image = canvas.draw(built_figure(e.name));
    REQUIRE(image.width == cb::kFigureWidth);
    REQUIRE(image.height == cb::kFigureHeight);
    cb::test::check_golden("figures/" + e.name, backend, image);
  }
}

TEST_CASE("Figures GL: points and lines land on the pixels their data give", "[figures]") {
  FigureCanvas canvas(cb::GlBackend::OSMesa);
  if (!canvas.context) return;
  // Hand-made: a line y = x / 2 and two points well apart from it, on a log x axis inset
  // over a plain panel, so both mappings are exercised.
  cb::Figure f;
  cb::Panel main;
  main.x = cb::axis("x", 0.0, 100.0);
  main.y = cb::axis("y", -10.0, 60.0);
  main.series.push_back(cb::make_series("line", cb::SeriesStyle::Line, cb::kFigSkyBlue,
                                        cb::linspace(0, 100, 201), {}));
  for (double x : main.series[0].x) main.series[0].y.push_back(x / 2.0);
  main.series.push_back(
      cb::make_series("dots", cb::SeriesStyle::Points, cb::kFigOrange, {20.0, 70.0}, {45.0, 5.0}));
  cb::Panel inset;
  inset.x = cb::axis("beta", 0.01, 10.0, true);
  inset.y = cb::axis("", 0.0, 1.0);
  inset.series.push_back(
      cb::make_series("dot", cb::SeriesStyle::Points, cb::kFigGreen, {0.3}, {0.5}));
  inset.inset = true;
  inset.left = 0.6f;
  inset.top = 0.05f;
  inset.width = 0.35f;
  inset.height = 0.35f;
  f.panels = {main, inset};
  const cb::Image image = canvas.draw(f);

  const auto mapping = [&](int panel) {
    return cb::figure_panel_layout(f.panels[panel], cb::kFigureWidth, cb::kFigureHeight).mapping;
  };
  const cb::PlotMapping m = mapping(0);
  // A point's disc is opaque at its centre: exactly its colour; 12 px above, not.
  for (auto [x, y] : {std::pair{20.0, 45.0}, {70.0, 5.0}}) {
    const int px = static_cast<int>(std::floor(m.px(x))),
              py = static_cast<int>(std::floor(m.py(y)));
    INFO("point (" << x << ", " << y << ") at pixel (" << px << ", " << py << ")");
    CHECK(channel_distance(image, px, py, cb::kFigOrange) == 0);
    CHECK(channel_distance(image, px, py - 12, cb::kFigOrange) > 60);
  }
  // The line passes through its pixel: within a row of the mapped y, a pixel of its colour
  // (antialiased edges are lighter); 6 px above and below, the background.
  for (double x : {15.0, 33.0, 57.0}) {  // below the inset, right of the legend
    const int px = static_cast<int>(std::floor(m.px(x))),
              py = static_cast<int>(std::floor(m.py(x / 2)));
    int nearest = 255;
    for (int y = py - 1; y <= py + 1; ++y)
      nearest = std::min(nearest, channel_distance(image, px, y, cb::kFigSkyBlue));
    INFO("line at x = " << x << ", pixel (" << px << ", " << py << ")");
    CHECK(nearest <= 12);
    CHECK(channel_distance(image, px, py - 6, cb::kFigSkyBlue) > 60);
    CHECK(channel_distance(image, px, py + 6, cb::kFigSkyBlue) > 60);
  }
  // On the log axis of the inset, beta = 0.3 sits at log10(0.3) between 0.01 and 10.
  const cb::PlotMapping l = mapping(1);
  const float expected_x = l.area.x + static_cast<float>((std::log10(0.3) + 2.0) / 3.0) * l.area.w;
  CHECK(l.px(std::log10(0.3)) == Approx(expected_x));
  const int px = static_cast<int>(std::floor(expected_x)),
            py = static_cast<int>(std::floor(l.py(0.5)));
  CHECK(channel_distance(image, px, py, cb::kFigGreen) == 0);
}

TEST_CASE("Figures GL: a real figure's curve, Fig. 4(b)'s kinetic energy", "[figures]") {
  FigureCanvas canvas(cb::GlBackend::OSMesa);
  if (!canvas.context) return;
  const cb::Figure& f = built_figure("fig4b");
  const cb::Image image = canvas.draw(f);
  const cb::PlotMapping m =
      cb::figure_panel_layout(f.panels[0], cb::kFigureWidth, cb::kFigureHeight).mapping;
  const cb::Series& kinetic = cb::test::series_of(f, "kinetic");
  for (std::size_t i : {250u, 290u, 370u}) {  // tau = 62.5, 72.5, 92.5: clear of the others
    const int px = static_cast<int>(std::floor(m.px(kinetic.x[i])));
    const int py = static_cast<int>(std::floor(m.py(kinetic.y[i])));
    int nearest = 255;
    for (int y = py - 1; y <= py + 1; ++y)
      nearest = std::min(nearest, channel_distance(image, px, y, cb::kFigPurple));
    INFO("kinetic at tau = " << kinetic.x[i] << ", pixel (" << px << ", " << py << ")");
    CHECK(nearest <= 12);
  }
}

// How long the command takes is a benchmark's business, not a test's.
TEST_CASE("figures command: PNG + CSV per figure, clear errors", "[figures][cli]") {
  if (!cb::test::gl_required()) {
    auto probe = cb::test::create_or_skip(cb::GlBackend::Auto);
    if (!probe) return;
  }
  const cb::test::TempDir dir("chainbreak-figures");
  const auto r = cb::test::run_chainbreak("figures -q -o " + dir.file("out"));
  INFO(r.err);
  REQUIRE(r.status == 0);
  for (const cb::FigureEntry& e : cb::figure_entries()) {
    INFO(e.name);
    CHECK(std::filesystem::file_size(dir.file("out/" + e.name + ".png")) > 10000);
    CHECK(r.out.find(dir.file("out/" + e.name + ".csv")) != std::string::npos);
  }
  // The CSV holds the plotted numbers: fig4a's phi_30 RK4 row at tau = 150 is the exact
  // solution's phi_30 there, to RK4's accuracy.
  const std::string csv = cb::test::slurp(dir.file("out/fig4a.csv"));
  CHECK(csv.rfind("panel,series,style,x,y,z\n", 0) == 0);
  const std::string key = "0,\"\u03C6\u2083\u2080 RK4\",points,150,";
  const auto row = csv.find(key);
  REQUIRE(row != std::string::npos);
  const cb::ExactChain exact(30, 0.0, cb::unit_ramp());
  CHECK(std::stod(csv.substr(row + key.size())) == Approx(exact.phi(30, 150.0)).margin(1e-6));

  const auto bad = cb::test::run_chainbreak("figures -q --only fig9 -o " + dir.file("x"));
  CHECK(bad.status == 2);
  CHECK(bad.err.find("fig4a") != std::string::npos);  // lists the known names
  const auto file_parent =
      cb::test::run_chainbreak("figures -q --only fig4a -o " + dir.file("out/fig4a.png/sub"));
  CHECK(file_parent.status == 2);
  CHECK(file_parent.err.find("-o") != std::string::npos);
}
