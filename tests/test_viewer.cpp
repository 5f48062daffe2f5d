// `chainbreak view` end to end. Under Xvfb (Debian's xvfb-run, llvmpipe GL through GLX) a
// script drives the window for a fixed number of frames; its snapshot must match what the
// headless commands draw at the same tau. Without xvfb-run these tests are skipped with a
// message (the README's install line provides it, so CI runs them). The no-display error
// needs no X server at all.
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "output/image.h"
#include "output/output_lock.h"
#include "output/png_writer.h"
#include "scene/scene.h"
#include "test_support.h"
#include "video_probe.h"
#include "viewer_test_support.h"

namespace {

using cb::test::run_chainbreak;
using cb::test::run_shell;
using cb::test::TempDir;

const std::string kScene = std::string(CHAINBREAK_SCENES) + "/anomalous_breaking.toml";
// 12 tau per second at the scene's 60 fps: 0.2 tau per frame, 20 steps of the scene's dt, so
// frame k is on the grid `snapshot` uses. t_end = 20 makes the viewer's layout (measured over
// the whole run, as `render` does) the one `snapshot --at 20` measures.
const std::string kSets = "--set render.speed=12 --set integrator.t_end=20";

using cb::test::skip_without_xvfb;
using cb::test::write_file;

// `chainbreak view ARGS` on a private virtual screen large enough for a 1080p window.
cb::test::RunResult view_under_xvfb(const std::string& args) {
  return cb::test::view_on_screen("1920x1080", args);
}

// Writes `script` into the folder and runs `view ARGS --script` on it under Xvfb; it must
// quit with status 0.
void run_script(const TempDir& dir, const std::string& script, const std::string& args) {
  write_file(dir.file("s.txt"), script);
  const auto view = view_under_xvfb(args + " --script " + dir.file("s.txt"));
  INFO(view.err);
  REQUIRE(view.status == 0);
}

// The tolerance: the viewer draws with the same renderer, snapshot and overlay code into its
// own framebuffer; only the GL driver's entry point differs (GLX against OSMesa/EGL, both
// llvmpipe). Measured: byte-identical PNGs. Allowed: channel differences up to 2 (one
// rounding step either way) on at most 0.1 % of the pixels, so a driver update that changes
// rasterisation rules slightly does not fail the test while a wrong tau or layout does.
constexpr int kChannelTolerance = 2;
constexpr double kFractionTolerance = 0.001;

void require_close(const std::string& actual, const std::string& expected) {
  const cb::ImageDiff diff =
      cb::compare_images(cb::read_png(actual), cb::read_png(expected), kChannelTolerance);
  INFO("max channel difference " << diff.max_channel << ", fraction over " << diff.fraction_over);
  REQUIRE(diff.same_size);
  CHECK(diff.fraction_over <= kFractionTolerance);
}

}  // namespace

#ifdef CHAINBREAK_VIEWER_EXE

TEST_CASE("view without a display says so and points to render and snapshot", "[viewer][cli]") {
  const auto r = run_shell("env -u DISPLAY -u WAYLAND_DISPLAY " + std::string(CHAINBREAK_EXE) +
                           " view " + kScene);
  CHECK(r.status == 1);
  CHECK_THAT(r.err, Catch::Contains("no display"));
  CHECK_THAT(r.err, Catch::Contains("chainbreak render"));
  CHECK_THAT(r.err, Catch::Contains("chainbreak snapshot"));
  // The viewer itself, started with a display that cannot be opened, says the same.
  const auto direct = run_shell("env -u WAYLAND_DISPLAY DISPLAY=:4242 " +
                                std::string(CHAINBREAK_VIEWER_EXE) + " " + kScene);
  CHECK(direct.status == 1);
  CHECK_THAT(direct.err, Catch::Contains("chainbreak render"));
}

TEST_CASE("the headless program does not link GLFW, only the viewer does", "[viewer][cli]") {
  // So `run`, `sweep`, `snapshot` and `render` start where GLFW is not installed.
  const auto headless = run_shell("ldd " + std::string(CHAINBREAK_EXE));
  REQUIRE(headless.status == 0);
  CHECK(headless.out.find("libglfw") == std::string::npos);
  const auto viewer = run_shell("ldd " + std::string(CHAINBREAK_VIEWER_EXE));
  CHECK(viewer.out.find("libglfw") != std::string::npos);
}

TEST_CASE("a bad script line is reported before any window opens", "[viewer][cli]") {
  TempDir dir("chainbreak-view");
  write_file(dir.file("s.txt"), "0 play\n5 fly away\n");
  const auto r =
      run_shell("env -u DISPLAY -u WAYLAND_DISPLAY " + std::string(CHAINBREAK_VIEWER_EXE) + " " +
                kScene + " --script " + dir.file("s.txt"));
  CHECK(r.status == 2);
  CHECK_THAT(r.err, Catch::Contains("s.txt:2: unknown action 'fly'"));
}

TEST_CASE("a scripted view snapshot matches the headless snapshot at the same tau",
          "[viewer][xvfb]") {
  if (skip_without_xvfb()) return;
  TempDir dir("chainbreak-view");
  // 100 frames of 0.2 tau: tau = 20. Then the snapshot, a saved scene and quit.
  run_script(dir,
             "0 play\n100 pause\n100 snapshot " + dir.file("view.png") + "\n100 save " +
                 dir.file("saved.toml") + "\n100 quit\n",
             kScene + " " + kSets + " --no-overlay");
  REQUIRE(std::filesystem::exists(dir.file("view.png")));
  const auto snap =
      run_chainbreak("snapshot " + kScene + " " + kSets + " --at 20 -o " + dir.path.string());
  REQUIRE(snap.status == 0);
  require_close(dir.file("view.png"), dir.file("anomalous_breaking_tau_000020.000.png"));

  // The saved scene is the one on screen: the speed and the t_end set above.
  const cb::SceneDesc saved = cb::load_scene(dir.file("saved.toml"));
  CHECK(saved.render.speed == 12.0);
  CHECK(saved.integrator.t_end == 20.0);
  CHECK(saved.chain.beads == 30);
}

TEST_CASE("with the overlay, the view's frame is the rendered video's frame", "[viewer][xvfb]") {
  if (skip_without_xvfb()) return;
  TempDir dir("chainbreak-view");
  // Set from the script (slider edits restart the run), then play: displayed frames 0..40
  // each advance one frame before they are drawn, so frame 40 shows tau = 41 * 0.2 = 8.2.
  // t_end = 10: a 51-frame video is enough (the layout still spans the whole run).
  const std::string size = " --size 960x540 --set integrator.t_end=10";
  run_script(dir, "0 set gamma 0.01\n0 play\n40 snapshot " + dir.file("view.png") + "\n40 quit\n",
             kScene + " " + kSets + size);
  std::filesystem::create_directories(dir.file("frames"));
  const auto render =
      run_chainbreak("render " + kScene + " " + kSets + size +
                     " --set chain.gamma=0.01 --quiet --frames " + dir.file("frames"));
  INFO(render.err);
  REQUIRE(render.status == 0);
  const std::string frame41 = dir.file("frames/anomalous_breaking_000041.png");
  REQUIRE(std::filesystem::exists(frame41));
  require_close(dir.file("view.png"), frame41);
}

TEST_CASE("record writes the session as an MP4", "[viewer][xvfb]") {
  if (skip_without_xvfb()) return;
  TempDir dir("chainbreak-view");
  run_script(dir, "0 play\n0 record " + dir.file("session.mp4") + "\n12 record stop\n12 quit\n",
             kScene + " " + kSets + " --size 640x360");
  // Frames 0..11 were recorded (the stop at frame 12 comes before its frame is pushed).
  REQUIRE(std::filesystem::exists(dir.file("session.mp4")));
  const cb::test::Decoded video = cb::test::decode(dir.file("session.mp4"), -1);
  CHECK(video.codec == "h264");
  CHECK(video.frames == 12);
  CHECK(video.width == 640);
  CHECK(video.height == 360);
}

TEST_CASE("record refuses a video that another chainbreak is writing", "[viewer][xvfb][lock]") {
  // Issue #12 row 9: the recorder takes the lock `render` takes on X.mp4 (its X.json name),
  // so the two cannot rename their videos over one another.
  if (skip_without_xvfb()) return;
  TempDir dir("chainbreak-view");
  write_file(dir.file("s.txt"), "0 play\n0 record " + dir.file("session.mp4") + "\n5 quit\n");
  const cb::OutputLock other(dir.file("session.json"));
  const auto view =
      view_under_xvfb(kScene + " " + kSets + " --no-overlay -q l --script " + dir.file("s.txt"));
  INFO(view.err);
  CHECK(view.status == 1);  // a script's failed action (test below)
  CHECK_THAT(view.err, Catch::Contains("frame 0: record failed") &&
                           Catch::Contains("another chainbreak is writing this output now"));
  // No video, nor the encoder's temporary: only the script and the holder's lock file.
  CHECK(dir.names() == std::vector<std::string>{".session.json.lock", "s.txt"});
}

#endif  // CHAINBREAK_VIEWER_EXE

TEST_CASE("a script's failed actions are reported on stderr and end with status 1",
          "[viewer][xvfb]") {
  if (skip_without_xvfb()) return;
  TempDir dir("chainbreak-view");
  write_file(dir.file("s.txt"), "0 snapshot /nonexistent-dir/x.png\n1 set threshold 0\n2 save " +
                                    dir.file("ok.toml") + "\n3 quit\n");
  const auto view =
      view_under_xvfb(kScene + " " + kSets + " --no-overlay -q l --script " + dir.file("s.txt"));
  CHECK(view.status == 1);
  CHECK_THAT(view.err, Catch::Contains("frame 0: snapshot failed") && Catch::Contains("frame 1:") &&
                           Catch::Contains("threshold") &&
                           Catch::Contains("2 script action(s) failed"));
  CHECK(std::filesystem::exists(dir.file("ok.toml")));  // the script carried on
}
