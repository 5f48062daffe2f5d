// The viewer's window layout (issue #27), end to end under Xvfb: the docked panels never
// cover the chain, the picture is `render`'s frame laid out at the rectangle they leave free,
// and it follows the window (resize, Tab, presentation mode) within one frame.
//
// Each run writes, for one displayed frame, the script's `layout` JSON (the window, the
// picture, every Dear ImGui window as ImGui reports it, and from the snapshot the frame was
// drawn from the wall, the beads and the force arrow) and a screenshot of the whole window.
// Geometry: no shape of the chain touches an ImGui window. Pixels: inside the picture the
// screenshot equals `chainbreak snapshot` at the picture's size and tau (the frame drawn
// without the UI in the same rectangle), everywhere but the selected spring's marker.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <vector>

#include "output/image.h"
#include "output/png_writer.h"
#include "test_support.h"
#include "viewer_test_support.h"

#ifdef CHAINBREAK_VIEWER_EXE

namespace {

using cb::test::run_chainbreak;
using cb::test::TempDir;
using json = nlohmann::json;

const std::string kScene = std::string(CHAINBREAK_SCENES) + "/anomalous_breaking.toml";
// 0.2 tau a frame at the scene's 60 fps; t_end = 20 keeps the pre-passes short. The viewer
// and `snapshot` both fit the chain to the run they measure, so their layouts agree.
const std::string kSets = "--set render.speed=12 --set integrator.t_end=20";
// The tolerance of test_viewer.cpp: the same drawing code through GLX instead of OSMesa/EGL
// (measured: identical); a channel may differ by 2, on at most 0.1 % of the pixels.
constexpr int kChannelTolerance = 2;
constexpr double kFractionTolerance = 0.001;

struct Box {
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  bool overlaps(const Box& o) const { return x0 < o.x1 && o.x0 < x1 && y0 < o.y1 && o.y0 < y1; }
  bool inside(const Box& o) const { return x0 >= o.x0 && y0 >= o.y0 && x1 <= o.x1 && y1 <= o.y1; }
  Box grown(double d) const { return {x0 - d, y0 - d, x1 + d, y1 + d}; }
};

Box box(const json& j) {
  return {j["x0"].get<double>(), j["y0"].get<double>(), j["x1"].get<double>(),
          j["y1"].get<double>()};
}

json read_json(const std::string& path) {
  std::ifstream in(path);
  REQUIRE(in);
  return json::parse(in);
}

// What must stay visible: the wall, every bead (its disc's square), the force arrow.
std::vector<Box> chain_shapes(const json& layout) {
  std::vector<Box> out;
  for (const json& w : layout["wall"]) out.push_back(box(w));
  for (const json& b : layout["beads"]) {
    const double x = b["x"], y = b["y"], r = b["r"];
    out.push_back({x - r, y - r, x + r, y + r});
  }
  for (const json& a : layout["arrow"]) out.push_back(box(a));
  return out;
}

// `chainbreak snapshot` of the picture's size at the layout's tau, with the video's overlay
// (the viewer's default, as the scene's): the frame drawn without the UI.
cb::Image headless_frame(const TempDir& dir, const json& layout) {
  const int w = layout["frame_size"][0], h = layout["frame_size"][1];
  char tau[32];
  std::snprintf(tau, sizeof tau, "%.10g", layout["tau"].get<double>());
  const std::string folder = dir.file(std::to_string(w) + "x" + std::to_string(h) + "_" + tau);
  std::filesystem::create_directories(folder);
  const auto snap = run_chainbreak("snapshot " + kScene + " " + kSets + " --overlay all --size " +
                                   std::to_string(w) + "x" + std::to_string(h) + " --at " + tau +
                                   " -o " + folder);
  INFO(snap.err);
  REQUIRE(snap.status == 0);
  for (const auto& e : std::filesystem::directory_iterator(folder))
    if (e.path().extension() == ".png") return cb::read_png(e.path().string());
  FAIL("no PNG from snapshot in " << folder);
  return {};
}

// The screenshot inside the picture against the headless frame, pixel by pixel, leaving out
// `skip` (window pixels): how many differ by more than the tolerance, in all and on `shapes`.
// The boxes are painted into masks first: one pass over a 4K picture, fast in sanitizer runs.
struct PixelDiff {
  long compared = 0, differing = 0, on_shapes = 0, shape_pixels = 0;
};
PixelDiff compare_picture(const cb::Image& shot, const Box& picture, const cb::Image& frame,
                          const std::vector<Box>& shapes, const std::vector<Box>& skip) {
  const int W = frame.width, H = frame.height;
  // A box in window pixels covers the picture pixels whose centres it contains.
  const auto paint = [&](const std::vector<Box>& boxes) {
    std::vector<std::uint8_t> mask(static_cast<std::size_t>(W) * H, 0);
    for (const Box& b : boxes) {
      const int x0 = std::max(0, static_cast<int>(std::ceil(b.x0 - picture.x0 - 0.5)));
      const int y0 = std::max(0, static_cast<int>(std::ceil(b.y0 - picture.y0 - 0.5)));
      const int x1 = std::min(W, static_cast<int>(std::ceil(b.x1 - picture.x0 - 0.5)));
      const int y1 = std::min(H, static_cast<int>(std::ceil(b.y1 - picture.y0 - 0.5)));
      for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) mask[static_cast<std::size_t>(y) * W + x] = 1;
    }
    return mask;
  };
  const std::vector<std::uint8_t> on_shape = paint(shapes), skipped = paint(skip);
  PixelDiff d;
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * W + x;
      if (skipped[i]) continue;
      const std::uint8_t* a =
          shot.pixel(static_cast<int>(picture.x0) + x, static_cast<int>(picture.y0) + y);
      const std::uint8_t* b = frame.pixel(x, y);
      int worst = 0;
      for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(int(a[c]) - int(b[c])));
      ++d.compared;
      d.shape_pixels += on_shape[i];
      if (worst > kChannelTolerance) {
        ++d.differing;
        d.on_shapes += on_shape[i];
      }
    }
  return d;
}

// The checks of issue #27 on one frame: geometry from the layout, pixels from the screenshot.
void require_chain_uncovered(const TempDir& dir, const std::string& layout_path,
                             const std::string& shot_path, int beads) {
  const json layout = read_json(layout_path);
  INFO(layout_path << ": " << layout.dump());
  const Box window = box(layout["window"]), picture = box(layout["picture"]);
  REQUIRE(layout["frame_size"][0].get<double>() == picture.x1 - picture.x0);
  REQUIRE(layout["frame_size"][1].get<double>() == picture.y1 - picture.y0);
  REQUIRE(picture.inside(window));
  const std::vector<Box> shapes = chain_shapes(layout);
  REQUIRE(layout["beads"].size() == static_cast<std::size_t>(beads));
  REQUIRE(layout["wall"].size() == 1);
  REQUIRE(!layout["arrow"].empty());
  std::vector<Box> ui;
  for (const json& w : layout["ui_windows"]) ui.push_back(box(w["box"]));
  for (const Box& s : shapes) {
    CHECK(s.inside(picture));
    for (const Box& u : ui) CHECK_FALSE(s.overlaps(u));
  }
  std::vector<Box> skip;  // drawn on the window only: the marker, the presentation hint
  if (!layout["marker"].is_null()) {
    const Box m = box(layout["marker"]);
    CHECK(m.inside(picture));
    for (const Box& u : ui) CHECK_FALSE(m.overlaps(u));
    skip.push_back(m.grown(3));
  }
  if (!layout["hint"].is_null()) {
    const Box h = box(layout["hint"]);
    for (const Box& s : shapes) CHECK_FALSE(s.overlaps(h));
    skip.push_back(h);
  }
  const cb::Image shot = cb::read_png(shot_path);
  REQUIRE(shot.width == window.x1);
  REQUIRE(shot.height == window.y1);
  const PixelDiff d = compare_picture(shot, picture, headless_frame(dir, layout), shapes, skip);
  INFO("pixels compared " << d.compared << ", differing " << d.differing << "; on the chain's "
                          << d.shape_pixels << ", differing " << d.on_shapes);
  CHECK(d.compared > 0.9 * (picture.x1 - picture.x0) * (picture.y1 - picture.y0));
  CHECK(d.shape_pixels > 0);
  CHECK(d.on_shapes == 0);
  CHECK(d.differing <= kFractionTolerance * d.compared);
}

void run_script(const TempDir& dir, const std::string& screen, const std::string& script,
                const std::string& args) {
  cb::test::write_file(dir.file("s.txt"), script);
  const auto view = cb::test::view_on_screen(screen, args + " --script " + dir.file("s.txt"));
  INFO(view.err);
  REQUIRE(view.status == 0);
}

}  // namespace

TEST_CASE("the docked panels cover none of the wall, the beads and the force arrow",
          "[viewer][xvfb][layout]") {
  if (cb::test::skip_without_xvfb()) return;
  for (const std::string size : {"1280x720", "1920x1080", "3840x2160"}) {
    INFO(size);
    TempDir dir("chainbreak-view-layout");
    // Spring 15 selected (its plot docked under the controls), paused at tau = 6; then Tab.
    run_script(dir, size,
               "0 play\n20 select 15\n30 pause\n30 layout " + dir.file("shown.json") +
                   "\n30 screenshot " + dir.file("shown.png") + "\n31 panels off\n31 layout " +
                   dir.file("hidden.json") + "\n31 screenshot " + dir.file("hidden.png") +
                   "\n31 quit\n",
               kScene + " " + kSets + " --size " + size);
    const json shown = read_json(dir.file("shown.json"));
    CHECK(shown["tau"].get<double>() == Approx(6.0).margin(1e-9));
    CHECK(shown["ui_windows"].size() == 2);  // the controls and the spring plot
    CHECK(!shown["marker"].is_null());
    require_chain_uncovered(dir, dir.file("shown.json"), dir.file("shown.png"), 30);

    // Panels hidden: the picture is the window, with nothing drawn over it, and the window
    // shows `snapshot` at the window's size and the same tau.
    const json hidden = read_json(dir.file("hidden.json"));
    CHECK(hidden["ui_windows"].empty());
    CHECK(hidden["marker"].is_null());
    CHECK(box(hidden["picture"]).x1 == box(hidden["window"]).x1);
    const cb::ImageDiff diff = cb::compare_images(cb::read_png(dir.file("hidden.png")),
                                                  headless_frame(dir, hidden), kChannelTolerance);
    INFO("max channel difference " << diff.max_channel << ", fraction over " << diff.fraction_over);
    REQUIRE(diff.same_size);
    CHECK(diff.fraction_over <= kFractionTolerance);
  }
}

TEST_CASE(
    "a resize while playing relays out the picture within one frame, and presentation mode "
    "gives it the screen",
    "[viewer][xvfb][layout]") {
  if (cb::test::skip_without_xvfb()) return;
  TempDir dir("chainbreak-view-layout");
  // Displayed frame k shows tau = (k + 1) * 0.2 while playing. The resize and the layout
  // are in the same frame: that frame is already laid out for 1280x720.
  run_script(dir, "1920x1080",
             "0 play\n10 select 15\n12 resize 1280 720\n12 layout " + dir.file("resized.json") +
                 "\n12 screenshot " + dir.file("resized.png") + "\n13 present on\n13 layout " +
                 dir.file("present.json") + "\n13 screenshot " + dir.file("present.png") +
                 "\n14 present off\n14 layout " + dir.file("back.json") + "\n14 quit\n",
             kScene + " " + kSets + " -q h");
  const json resized = read_json(dir.file("resized.json"));
  CHECK(resized["tau"].get<double>() == Approx(2.6).margin(1e-9));
  CHECK(box(resized["window"]).x1 == 1280);
  CHECK(box(resized["window"]).y1 == 720);
  CHECK(box(resized["picture"]).x1 == 1280 - 400);  // the column: 400 px at scale 1
  require_chain_uncovered(dir, dir.file("resized.json"), dir.file("resized.png"), 30);

  // Presentation: fullscreen (the screen's size), no panels, the hint at the top right,
  // clear of the chain.
  const json present = read_json(dir.file("present.json"));
  CHECK(present["presenting"].get<bool>());
  CHECK(box(present["window"]).x1 == 1920);
  CHECK(box(present["window"]).y1 == 1080);
  CHECK(box(present["picture"]).x1 == 1920);
  CHECK(present["ui_windows"].empty());
  REQUIRE(!present["hint"].is_null());
  require_chain_uncovered(dir, dir.file("present.json"), dir.file("present.png"), 30);
  // And back to the window it was, with its panels.
  const json back = read_json(dir.file("back.json"));
  CHECK_FALSE(back["presenting"].get<bool>());
  CHECK(box(back["window"]).x1 == 1280);
  CHECK(back["ui_windows"].size() == 2);
}

TEST_CASE("the panels' text follows the window's content scale and --ui-scale",
          "[viewer][xvfb][layout]") {
  if (cb::test::skip_without_xvfb()) return;
  TempDir dir("chainbreak-view-layout");
  const auto layout_at = [&](const std::string& name, const std::string& xft_dpi,
                             const std::string& args) {
    cb::test::write_file(dir.file(name + ".txt"),
                         "0 layout " + dir.file(name + ".json") + "\n0 quit\n");
    std::string command = std::string(CHAINBREAK_EXE) + " view " + kScene + " " + kSets + " -q h " +
                          args + " --script " + dir.file(name + ".txt");
    // The desktop's scale, as X11 desktops say it: Xft.dpi in the server's resources, which
    // GLFW reads (96 dpi is 1). -noreset keeps them after xrdb disconnects.
    if (!xft_dpi.empty()) {
      cb::test::write_file(dir.file("xresources"), "Xft.dpi: " + xft_dpi + "\n");
      command = "sh -c 'xrdb -nocpp -merge " + dir.file("xresources") + " && " + command + "'";
    }
    const TempDir auth("chainbreak-xauth");
    const auto view = cb::test::run_shell("xvfb-run -a -f " + auth.file("Xauthority") +
                                          " -s '-screen 0 1920x1080x24 -noreset' " + command);
    INFO(view.err);
    REQUIRE(view.status == 0);
    return read_json(dir.file(name + ".json"));
  };
  const auto width = [](const json& j) { return box(j["controls"]).x1 - box(j["controls"]).x0; };
  const json plain = layout_at("plain", "", "");
  CHECK(plain["ui_scale"].get<double>() == 1.0);
  CHECK(plain["font_px"].get<double>() == 17.0);
  CHECK(width(plain) == 400);
  // --ui-scale 2 on a plain screen: twice the text, the column at its cap (40 % of 1920).
  const json doubled = layout_at("doubled", "", "--ui-scale 2");
  CHECK(doubled["font_px"].get<double>() == 34.0);
  CHECK(width(doubled) == 768);
  // ImGui's own window is the docked rectangle at any scale.
  CHECK(box(doubled["ui_windows"][0]["box"]).x0 == 1920 - 768);
  if (std::system("command -v xrdb >/dev/null 2>&1") != 0) {
    WARN("content scale not checked: xrdb not found (apt-get install x11-xserver-utils)");
    return;
  }
  // A HiDPI desktop (192 dpi: content scale 2), then with --ui-scale 1.5 on top of it.
  const json hidpi = layout_at("hidpi", "192", "");
  CHECK(hidpi["ui_scale"].get<double>() == 2.0);
  CHECK(hidpi["font_px"].get<double>() == 34.0);
  const json both = layout_at("both", "192", "--ui-scale 1.5");
  CHECK(both["ui_scale"].get<double>() == 3.0);
  CHECK(both["font_px"].get<double>() == 51.0);
  CHECK(width(both) == 768);
}

#endif  // CHAINBREAK_VIEWER_EXE
