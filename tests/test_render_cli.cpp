// `chainbreak render` as a user meets it: the real program is spawned and what it writes is
// decoded again (video_probe.h). Containers, codecs, timing, the JSON sidecar, determinism,
// a frame against `snapshot` at the same tau, Ctrl-C, and failures that leave nothing.
// Small frames (320x180) and short runs keep the whole file at a few seconds.
// Needs an OpenGL context: where none can be made it warns and passes, unless
// CHAINBREAK_REQUIRE_GL=1 (set by ctest).
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <catch2/catch.hpp>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>
#include <vector>

#include "gl_test_support.h"
#include "output/output_lock.h"
#include "output/png_writer.h"
#include "test_support.h"
#include "video_probe.h"

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

struct TempDir : cb::test::TempDir {
  TempDir() : cb::test::TempDir("chainbreak-render") {}
};
using Result = cb::test::RunResult;
Result chainbreak(const std::string& args) {
  return cb::test::run_chainbreak(args);
}

std::string scene(const std::string& name) {
  return std::string(CHAINBREAK_SCENES) + "/" + name;
}

json read_json(const std::string& path) {
  return json::parse(cb::test::read_bytes(path));
}

// Whether the program can draw here: its default backend (auto) in this process, once (a
// WARN and a skip where it cannot, a FAIL under ctest's CHAINBREAK_REQUIRE_GL=1).
bool gl_available() {
  static const bool available = cb::test::create_or_skip(cb::GlBackend::Auto) != nullptr;
  return available;
}

// The pulled end breaks at tau ~ 30 (zeta_c = threshold / beta = 3 / 0.1, the scene's note);
// the run stops 20 later. At --fps 30 --speed 30 a frame is 1 tau = 100 scene steps of 0.01,
// so the render's step equals the scene's (no shrinking) and frame k shows tau = k exactly.
const std::string kBreaking = scene("ramp_pulled_end.toml");
const std::string kSmall = " --size 320x180 --fps 30 --speed 30 --quiet";

}  // namespace

TEST_CASE("render MP4: H.264 yuv420p, exact timing, moov first, a sidecar", "[render_cli]") {
  if (!gl_available()) return;
  TempDir dir;
  const std::string mp4 = dir.file("clip.mp4");
  const auto r =
      chainbreak("render " + kBreaking + " -o " + mp4 + kSmall + " --set integrator.t_end=60");
  INFO(r.err);
  REQUIRE(r.status == 0);
  CHECK(r.out == mp4 + "\n");  // stdout: the path, for scripts
  CHECK(dir.names() == std::vector<std::string>{"clip.json", "clip.mp4"});  // no temporaries

  const json side = read_json(dir.file("clip.json"));
  const int frames = side["frames"];
  CHECK(side["codec"] == "h264");
  CHECK(side["fps"] == 30);
  CHECK(side["width"] == 320);
  CHECK(side["height"] == 180);
  CHECK(side["duration"].get<double>() == Approx(frames / 30.0).margin(1e-12));
  CHECK(side["integrator"]["dt_used"] == 0.01);  // 1 tau per frame / 100 steps, exactly 0.01
  const std::string gl = side["gl"];
  CHECK((gl.rfind("osmesa: ", 0) == 0 || gl.rfind("egl", 0) == 0));  // describe(): "backend: ..."
  // First break: spring N = 30 near tau = zeta_c = 30 (within 2: the discrete chain's front
  // is not the continuum's step); the run stops after_break = 20 later. The released chain
  // recoils and more springs break (in compression; break_on = "abs") within those 20.
  // Frame k shows tau = k, so the first frame showing a break is ceil(tau).
  const json& breaks = side["breaks"];
  REQUIRE(!breaks.empty());
  CHECK(breaks[0]["spring"] == 30);
  const double first = breaks[0]["tau"];
  CHECK(first == Approx(30).margin(2));
  CHECK(frames == static_cast<int>(std::floor(first + 20)) + 1);
  for (const json& b : breaks) {
    CHECK(b["frame"] == static_cast<int>(std::ceil(b["tau"].get<double>())));
    CHECK(b["frame"] < frames);
  }

  const cb::test::Decoded d = cb::test::decode(mp4, -1);
  CHECK(d.container.find("mp4") != std::string::npos);
  CHECK(d.codec == "h264");
  CHECK(d.pix_fmt == "yuv420p");
  CHECK(d.width == 320);
  CHECK(d.height == 180);
  CHECK(d.frames == frames);
  CHECK(d.frame_rate.num == 30);
  CHECK(d.frame_rate.den == 1);
  CHECK(d.duration == Approx(frames / 30.0).margin(1e-9));  // time base 1/30 in 1/15360 units
  CHECK(d.colorspace == AVCOL_SPC_BT709);
  CHECK(d.chroma_location == AVCHROMA_LOC_CENTER);  // 2x2 means: centred chroma, tagged
  const auto boxes = cb::test::top_level_boxes(cb::test::read_bytes(mp4));
  const auto moov = std::find(boxes.begin(), boxes.end(), "moov");
  const auto mdat = std::find(boxes.begin(), boxes.end(), "mdat");
  REQUIRE(moov != boxes.end());
  REQUIRE(mdat != boxes.end());
  CHECK(moov < mdat);  // faststart

  // The hash covers the overrides: the same --set gives the same hash, another value another.
  auto hash_of = [&](const std::string& set) {
    const auto plan = chainbreak("render " + kBreaking + " -o " + dir.file("plan.mp4") + kSmall +
                                 " --set " + set + " --dry-run");
    REQUIRE(plan.status == 0);
    return json::parse(plan.out)["scene_hash"].get<std::string>();
  };
  CHECK(hash_of("integrator.t_end=60") == side["scene_hash"]);
  CHECK(hash_of("integrator.t_end=61") != side["scene_hash"]);
}

TEST_CASE("render twice: byte-identical videos", "[render_cli]") {
  if (!gl_available()) return;
  TempDir dir;
  // --speed 10: 1/3 tau per frame, so the step is shrunk to 1/102 (34 per frame), 31 frames.
  const std::string args = " --size 320x180 --fps 30 --speed 10 --quiet --set integrator.t_end=10";
  REQUIRE(chainbreak("render " + kBreaking + " -o " + dir.file("a.mp4") + args).status == 0);
  REQUIRE(chainbreak("render " + kBreaking + " -o " + dir.file("b.mp4") + args).status == 0);
  const std::string a = cb::test::read_bytes(dir.file("a.mp4"));
  CHECK(a.size() > 1000);
  CHECK(a == cb::test::read_bytes(dir.file("b.mp4")));
  json sa = read_json(dir.file("a.json")), sb = read_json(dir.file("b.json"));
  CHECK(sa["frames"] == 31);
  sa.erase("output"), sb.erase("output");
  CHECK(sa == sb);  // the sidecars differ in the output path only
}

TEST_CASE("render WebM (VP9) and GIF: every frame, GIF at most 50 fps", "[render_cli]") {
  if (!gl_available()) return;
  TempDir dir;
  const std::string common = " --size 320x180 --speed 10 --quiet --set integrator.t_end=10";
  const std::string webm = dir.file("clip.webm"), gif = dir.file("anim.gif");
  REQUIRE(chainbreak("render " + kBreaking + " -o " + webm + " --fps 30" + common).status == 0);
  REQUIRE(chainbreak("render " + kBreaking + " -o " + gif + " --fps 25" + common).status == 0);
  const json sw = read_json(dir.file("clip.json")), sg = read_json(dir.file("anim.json"));
  CHECK(sw["codec"] == "vp9");
  CHECK(sw["frames"] == 31);  // tau 0..10 every 1/3
  CHECK(sg["codec"] == "gif");
  CHECK(sg["frames"] == 26);  // tau 0..10 every 0.4

  const cb::test::Decoded w = cb::test::decode(webm, -1);
  CHECK(w.container.find("webm") != std::string::npos);
  CHECK(w.codec == "vp9");
  CHECK(w.width == 320);
  CHECK(w.height == 180);
  CHECK(w.frames == 31);
  CHECK(w.duration == Approx(31 / 30.0).margin(1e-3));  // WebM counts whole milliseconds

  const cb::test::Decoded g = cb::test::decode(gif, -1);
  CHECK(g.codec == "gif");
  CHECK(g.width == 320);
  CHECK(g.height == 180);
  CHECK(g.frames == 26);
  CHECK(g.duration == Approx(26 / 25.0).margin(1e-9));  // 4 cs per frame, exact

  // GIF delays are whole centiseconds and browsers slow down anything under 2 cs.
  const auto fast =
      chainbreak("render " + kBreaking + " -o " + dir.file("fast.gif") + " --fps 60" + common);
  CHECK(fast.status == 2);
  CHECK_THAT(fast.err, Catch::Contains("50 frames/s"));
  CHECK_FALSE(fs::exists(dir.file("fast.gif")));
}

namespace {

// Per-channel mean and 99th percentile of |a - b| over every pixel (r, g, b).
struct Difference {
  double mean[3] = {0, 0, 0};
  int p99 = 0, max = 0;
};
Difference difference(const cb::Image& a, const cb::Image& b) {
  Difference d;
  std::array<long, 256> histogram{};
  const long pixels = static_cast<long>(a.width) * a.height;
  for (long i = 0; i < pixels; ++i)
    for (int c = 0; c < 3; ++c) {
      const int v = std::abs(a.rgba[4 * i + c] - b.rgba[4 * i + c]);
      d.mean[c] += v;
      ++histogram[v];
      d.max = std::max(d.max, v);
    }
  for (double& m : d.mean) m /= static_cast<double>(pixels);
  for (long seen = 0; d.p99 < 255 && (seen += histogram[d.p99]) < 0.99 * 3 * pixels;) ++d.p99;
  return d;
}

// `snapshot SCENE --at TAU` with the same overrides, size and frame layout as a render that
// ends at TAU: both measure the run up to TAU with the same dt (frames.h, measure_run), so
// the layout (psi and force ranges) is the same. A frame before the end of a render would be
// scaled for the whole run and differ from a snapshot at its tau.
cb::Image snapshot_at(const TempDir& dir, const std::string& tau, const std::string& sets) {
  const auto r = chainbreak("snapshot " + kBreaking + " --at " + tau + " --size 320x180 -o " +
                            dir.path.string() + sets);
  INFO(r.err);
  REQUIRE(r.status == 0);
  const std::string png = r.out.substr(0, r.out.find('\n'));  // the path it wrote
  return cb::read_png(png);
}

}  // namespace

TEST_CASE("render: a decoded frame matches the snapshot at the same tau", "[render_cli]") {
  if (!gl_available()) return;
  TempDir dir;
  // Frame 24 of 25 shows tau = 24 (1 tau per frame) with dt_used = the scene's dt = 0.01, and
  // the snapshot reaches tau = 24 on the scene's grid in 2400 steps of 0.01: the same steps,
  // so the same state. Before the break (~30): the chain is strained, springs coloured.
  const std::string sets = " --set integrator.t_end=24";
  const std::string mp4 = dir.file("clip.mp4");
  REQUIRE(chainbreak("render " + kBreaking + " -o " + mp4 + kSmall + sets).status == 0);
  REQUIRE(read_json(dir.file("clip.json"))["frames"] == 25);
  const cb::test::Decoded d = cb::test::decode(mp4, 24);
  REQUIRE(d.picture.width == 320);
  const cb::Image snap = snapshot_at(dir, "24", sets);
  REQUIRE(snap.width == 320);
  REQUIRE(snap.height == 180);

  const Difference diff = difference(d.picture, snap);
  INFO("mean " << diff.mean[0] << " " << diff.mean[1] << " " << diff.mean[2] << ", p99 " << diff.p99
               << ", max " << diff.max);
  // The pictures differ only by the codec: H.264 at crf 18 and 8-bit BT.709 limited-range
  // Y'CbCr cost 1-2 levels on flat areas; 4:2:0 halves the colour resolution, so 1-2 px
  // coloured springs, bead rims and text lose their colour over a few pixels (large
  // differences, but on under 1 % of the picture). Measured: mean 0.62, 1.22, 1.66 (r, g, b),
  // p99 12, max 134.
  for (double m : diff.mean) CHECK(m < 4.0);
  CHECK(diff.p99 < 40);
}

TEST_CASE("render --frames: numbered PNGs, the last one exactly the snapshot", "[render_cli]") {
  if (!gl_available()) return;
  TempDir dir;
  const fs::path frames = dir.path / "frames";
  fs::create_directory(frames);
  const std::string sets = " --set integrator.t_end=24";
  const auto r = chainbreak("render " + kBreaking + " --frames " + frames.string() + kSmall + sets);
  INFO(r.err);
  REQUIRE(r.status == 0);
  const json side = read_json((frames / "ramp_pulled_end.json").string());
  CHECK(side["codec"] == "png");
  const int count = side["frames"];
  CHECK(count == 25);
  std::vector<std::string> want;
  for (int k = 0; k < count; ++k) {
    char name[64];
    std::snprintf(name, sizeof name, "ramp_pulled_end_%06d.png", k);
    want.push_back(name);
  }
  want.insert(want.begin(), "ramp_pulled_end.json");  // '.' sorts before '_'
  std::vector<std::string> got;
  for (const auto& e : fs::directory_iterator(frames)) got.push_back(e.path().filename().string());
  std::sort(got.begin(), got.end());
  CHECK(got == want);
  // No codec in between: the same state, layout and GL draw give the same pixels.
  const cb::Image last = cb::read_png((frames / want.back()).string());
  const cb::Image snap = snapshot_at(dir, "24", sets);
  CHECK(last.width == 320);
  CHECK(last.height == 180);
  CHECK(cb::compare_images(last, snap, 0).max_channel == 0);
}

TEST_CASE("snapshot --overlay: the video's frame at that tau, pixel for pixel", "[render_cli]") {
  if (!gl_available()) return;
  TempDir dir;
  const fs::path frames = dir.path / "frames";
  fs::create_directory(frames);
  // Past the break at tau ~ 30, so the plots, the space-time picture and the HUD's break list
  // all have content. 640x360: the smallest frame with an overlay.
  const std::string common = " --size 640x360 --set render.fps=30 --set render.speed=30";
  const auto r = chainbreak("render " + kBreaking + " --frames " + frames.string() + common +
                            " --overlay all --quiet");
  INFO(r.err);
  REQUIRE(r.status == 0);
  const auto s = chainbreak("snapshot " + kBreaking + " --at 12,33 --overlay all -o " +
                            dir.path.string() + common);
  INFO(s.err);
  REQUIRE(s.status == 0);
  for (const auto& [tau, frame] : {std::pair{"12", 12}, std::pair{"33", 33}}) {
    char name[64];
    std::snprintf(name, sizeof name, "ramp_pulled_end_%06d.png", frame);
    const cb::Image video = cb::read_png((frames / name).string());
    const cb::Image snap = cb::read_png(
        (dir.path / ("ramp_pulled_end_tau_0000" + std::string(tau) + ".000.png")).string());
    CHECK(cb::compare_images(video, snap, 0).max_channel == 0);
    // ...and the overlay is there: the chain-only snapshot differs below the chain's band.
    const auto plain =
        chainbreak("snapshot " + kBreaking + " --at " + tau + " -o " + frames.string() + common);
    REQUIRE(plain.status == 0);
    const cb::Image alone = cb::read_png(plain.out.substr(0, plain.out.find('\n')));
    CHECK(cb::compare_images(alone, snap, 8).fraction_over > 0.05);
  }

  // A time between frames, a time past the end, a frame too small: exit 2, with the fix.
  const auto off = chainbreak("snapshot " + kBreaking + " --at 12.5 --overlay all -o " +
                              dir.path.string() + common);
  CHECK(off.status == 2);
  CHECK_THAT(off.err, Catch::Contains("speed / fps = 1 of tau") &&
                          Catch::Contains("nearest to 12.5: 12 or 13"));
  // Frame times that cannot be typed exactly (k / 3 here) are accepted as printed, to 10 digits.
  const auto third =
      chainbreak("snapshot " + kBreaking + " --at 0.3333333333 --overlay all -o " +
                 dir.path.string() + " --size 640x360 --set render.fps=30 --set render.speed=10");
  INFO(third.err);
  CHECK(third.status == 0);
  const auto late = chainbreak("snapshot " + kBreaking + " --at 500 --overlay all -o " +
                               dir.path.string() + common);
  CHECK(late.status == 2);
  CHECK_THAT(late.err, Catch::Contains("past the video's last frame"));
  const auto small = chainbreak("snapshot " + kBreaking + " --at 12 --overlay all -o " +
                                dir.path.string() + " --size 320x180");
  CHECK(small.status == 2);
  CHECK_THAT(small.err, Catch::Contains("too small for the overlay"));
}

TEST_CASE("snapshot: two times that would share a file name are refused", "[render_cli]") {
  TempDir dir;
  const auto r = chainbreak("snapshot " + kBreaking + " --at 1.0001,1.0002 -o " +
                            dir.path.string() + " --size 320x180");
  CHECK(r.status == 2);
  CHECK_THAT(r.err, Catch::Contains("ramp_pulled_end_tau_000001.000.png") &&
                        Catch::Contains("at least 0.001 apart"));
  CHECK(dir.names().empty());  // refused before anything was drawn
}

TEST_CASE("render: Ctrl-C exits 130 and keeps a playable .partial.mp4", "[render_cli]") {
  if (!gl_available()) return;
  TempDir dir;
  const std::string mp4 = dir.file("long.mp4"), err = dir.file("stderr.txt");
  const std::string scene_path = scene("anomalous_breaking.toml");
  // Unbreakable and long: 4501 frames at 854x480@15 (-q l), far more than the test waits for.
  // Not --quiet: the plan line on stderr says when rendering starts.
  const pid_t pid = ::fork();
  REQUIRE(pid >= 0);
  if (pid == 0) {
    if (!std::freopen("/dev/null", "w", stdout) || !std::freopen(err.c_str(), "w", stderr))
      ::_exit(127);
    ::execl(CHAINBREAK_EXE, CHAINBREAK_EXE, "render", scene_path.c_str(), "-o", mp4.c_str(), "-q",
            "l", "--set", "chain.threshold=1e9", "--set", "integrator.t_end=3000",
            static_cast<char*>(nullptr));
    ::_exit(127);
  }
  // The plan line ("render anomalous_breaking: 4501 frames ...") comes once the physics
  // pre-pass is done and GL is ready; a second later ~250 frames are done here. (The
  // temporary file is no sign: the MP4 muxer first writes to it after ~256 KB, ~3 s.)
  using clock = std::chrono::steady_clock;
  const auto give_up = clock::now() + std::chrono::seconds(20);
  bool started = false;
  while (!started && clock::now() < give_up) {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    started = cb::test::read_bytes(err).find(" frames ") != std::string::npos;
  }
  CHECK(started);
  std::this_thread::sleep_for(std::chrono::seconds(1));
  const auto sent = clock::now();
  ::kill(pid, SIGINT);
  int raw = 0;
  while (::waitpid(pid, &raw, WNOHANG) == 0 && clock::now() < sent + std::chrono::seconds(10))
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  const double seconds = std::chrono::duration<double>(clock::now() - sent).count();
  if (seconds >= 10) {  // hung: do not leave it running
    ::kill(pid, SIGKILL);
    ::waitpid(pid, &raw, 0);
    FAIL("render did not stop within 10 s of SIGINT");
  }
  const std::string message = cb::test::read_bytes(err);
  INFO(message);
  REQUIRE(WIFEXITED(raw));
  CHECK(WEXITSTATUS(raw) == 130);
  // Within a frame: the frame being drawn, up to 3 queued snapshots and 3 queued images, then
  // x264 flushes its look-ahead (~10 frames at veryfast): 0.06 s at 480p here; 2 s of slack
  // for a loaded machine.
  CHECK(seconds < 2.0);
  // Nothing under the requested name (nor its sidecar, nor a temporary); the partial plays.
  CHECK(dir.names() == std::vector<std::string>{"long.partial.mp4", "stderr.txt"});
  const cb::test::Decoded d = cb::test::decode(dir.file("long.partial.mp4"), -1);
  CHECK(d.codec == "h264");
  CHECK(d.width == 854);
  CHECK(d.frames > 0);
  // Every frame drawn was kept, and the message says how many.
  CHECK_THAT(message, Catch::Contains("interrupted after " + std::to_string(d.frames) + " frames"));
  CHECK(d.duration == Approx(d.frames / 15.0).margin(1e-9));
}

TEST_CASE("render: two renders to one output leave a video and a sidecar of one run",
          "[render_cli]") {
  // Issue #12 row 9: both used to exit 0, the video of one and the sidecar of the other.
  if (!gl_available()) return;
  TempDir dir;
  const std::string mp4 = dir.file("clip.mp4");
  const std::string args = " --fps 30 --speed 30 --quiet --set integrator.t_end=20 -o " + mp4;
  {
    // Another process holding the output: refused at once (exit 2), nothing written.
    cb::OutputLock other(dir.file("clip.json"));
    const auto r = chainbreak("render " + kBreaking + args + " --size 320x180");
    CHECK(r.status == 2);
    CHECK_THAT(r.err, Catch::Contains("clip.json: another chainbreak is writing this output"));
    CHECK(dir.names() == std::vector<std::string>{".clip.json.lock"});
  }
  CHECK(dir.names().empty());  // the holder removes its lock file
  // Two at once, of different sizes: one may be refused, and the pair left is one run's.
  const std::string exe = CHAINBREAK_EXE;
  const auto both = cb::test::run_shell(
      "(" + exe + " render " + kBreaking + args + " --size 320x180 >/dev/null 2>&1; echo a$?) & (" +
      exe + " render " + kBreaking + args + " --size 256x144 >/dev/null 2>&1; echo b$?) & wait");
  INFO(both.out);
  const bool a_ok = both.out.find("a0") != std::string::npos;
  const bool b_ok = both.out.find("b0") != std::string::npos;
  CHECK((a_ok || b_ok));
  CHECK((a_ok || both.out.find("a2") != std::string::npos));
  CHECK((b_ok || both.out.find("b2") != std::string::npos));
  REQUIRE(dir.names() == std::vector<std::string>{"clip.json", "clip.mp4"});
  const json side = read_json(dir.file("clip.json"));
  const cb::test::Decoded video = cb::test::decode(mp4, -1);
  CHECK(video.width == side["width"].get<int>());
  CHECK(video.height == side["height"].get<int>());
  CHECK(video.frames == side["frames"].get<int>());
}

TEST_CASE("render: bad outputs exit 2, name the path and create nothing", "[render_cli]") {
  TempDir dir;
  fs::path target;
  if (::geteuid() == 0) {
    // Root writes into a chmod 0555 folder anyway: use a path under a regular file instead.
    std::FILE* f = std::fopen(dir.file("afile").c_str(), "w");
    REQUIRE(f);
    std::fclose(f);
    target = dir.path / "afile" / "out.mp4";
  } else {
    fs::create_directory(dir.path / "ro");
    fs::permissions(dir.path / "ro", fs::perms::owner_read | fs::perms::owner_exec);
    target = dir.path / "ro" / "out.mp4";
  }
  const auto before = dir.names();
  const std::string base = "render " + kBreaking + kSmall + " --set integrator.t_end=5 -o ";
  const auto r = chainbreak(base + target.string());
  CHECK(r.status == 2);
  CHECK_THAT(r.err, Catch::Contains(target.string()));
  CHECK(r.out.empty());
  CHECK(dir.names() == before);
  if (::geteuid() != 0) CHECK(fs::is_empty(dir.path / "ro"));

  const auto avi = chainbreak(base + dir.file("out.avi"));
  CHECK(avi.status == 2);
  CHECK_THAT(avi.err, Catch::Contains("out.avi") && Catch::Contains(".mp4") &&
                          Catch::Contains(".webm") && Catch::Contains(".gif"));
  CHECK(dir.names() == before);
}

TEST_CASE("render --dry-run prints the plan and writes nothing", "[render_cli]") {
  TempDir dir;
  const std::string mp4 = dir.file("plan.mp4");
  const auto r = chainbreak("render " + kBreaking + " -o " + mp4 + kSmall +
                            " --set integrator.t_end=24 --dry-run");
  INFO(r.err);
  REQUIRE(r.status == 0);
  const json plan = json::parse(r.out);
  CHECK(plan["output"] == mp4);
  CHECK(plan["codec"] == "h264");
  CHECK(plan["frames"] == 25);
  CHECK_FALSE(plan.contains("gl"));  // nothing drawn
  CHECK(dir.names().empty());
}
