// Video throughput at 1080p60: the whole `chainbreak render` pipeline against libx264 alone
// on the same frames, at the same preset, in one run. Goal (the issue): render >= 90% of
// x264-alone frames/s. main() prints the medians and the ratios after the benchmarks.
//
// - Frames: the default scene (anomalous_breaking.toml, 1920x1080, 60 fps, 10 tau/s), its
//   first kFrames frames (tau 0 .. 39.8), made once in memory before timing: the physics,
//   the layout and the snapshots exactly as `render` makes them (render_plan.cpp: frame k at
//   k x 17 steps of dt = (1/6)/17; frames.cpp: the layout from a pre-pass), drawn by
//   cb::Renderer on the same GL backend (auto).
// - BM_X264Alone/preset: those RGBA frames through swscale (RGBA -> yuv420p, BT.709 limited)
//   and libx264, set up as cb::VideoEncoder does (crf 18, 2 threads, key frame every 2 s,
//   bit-exact), packets dropped: no container, no file. Conversion and encoding run one
//   after the other on one thread, as on the encoder's worker thread.
// - BM_Render/preset: the `chainbreak render` process on the same clip (--set
//   integrator.t_end=39.9 gives the same kFrames frames), writing to /dev/shm; wall time
//   from spawn to exit, so process start, scene, pre-pass, GL context, physics, drawing,
//   readback, conversion, encoding, muxing and fsync all count.
// - BM_Draw, BM_Convert: drawing and reading back those frames alone (no encoder), and their
//   conversion to yuv420p alone: where the time goes.
#include <benchmark/benchmark.h>
#include <fcntl.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavutil/opt.h>
#include <libswscale/swscale.h>
}

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "drive/drive.h"
#include "gl/gl_context.h"
#include "physics/integrator.h"
#include "render/renderer.h"
#include "scene/scene.h"
#include "snapshot/snapshot.h"

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

constexpr int kFrames = 240;             // 4 s of video at 60 fps
constexpr const char* kTauEnd = "39.9";  // floor(39.9 / (10/60)) + 1 = 240 frames
constexpr int kRepetitions = 5;          // ~30 s per repetition of everything
const char* const kPresets[] = {"ultrafast", "veryfast", "medium"};

double seconds_since(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

// CPU seconds (user + system) in a rusage: with the wall time, how many cores were busy.
double cpu_seconds(const rusage& u) {
  return u.ru_utime.tv_sec + u.ru_stime.tv_sec + 1e-6 * (u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}
double process_cpu_seconds() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return cpu_seconds(u);
}

// What every benchmark measured, by name, for the summary main() prints: frames/s, and
// busy cores (CPU time / wall time).
std::map<std::string, std::vector<double>> g_fps, g_cores;

struct Clip {
  std::unique_ptr<cb::GlContext> context;
  std::unique_ptr<cb::Renderer> renderer;
  std::vector<cb::RenderSnapshot> snapshots;
  std::vector<cb::Image> frames;
  std::string error;  // why the clip could not be made
};
Clip g_clip;

std::string scene_path() {
  return std::string(CHAINBREAK_SCENES) + "/anomalous_breaking.toml";
}

// The frames `render` makes for the default scene with integrator.t_end = kTauEnd.
void make_clip() {
  const cb::SceneDesc scene = cb::load_scene(
      scene_path(), {cb::parse_override(std::string("integrator.t_end=") + kTauEnd)});
  const cb::RenderDesc& r = scene.render;
  // render_plan.cpp: the step shrunk so that a whole number of steps lands on every frame.
  const double tau_per_frame = r.speed / r.fps;
  const auto substeps =
      static_cast<std::int64_t>(std::ceil(tau_per_frame / scene.integrator.dt - 1e-9));
  const double dt = tau_per_frame / static_cast<double>(substeps);
  // frames.cpp (measure_run): the layout's ranges from a pre-pass to t_end, no break here
  // (the first one is at tau ~ 150).
  double psi = 0.0, force = 0.0;
  {
    cb::Integrator pre(scene.chain, cb::make_forcing(scene.drive), {dt, 1});
    const auto last = static_cast<std::int64_t>(std::llround(scene.integrator.t_end / dt));
    while (pre.state().step < last) {
      if (!pre.step()) throw std::runtime_error(pre.error());
      for (double x : pre.state().psi) psi = std::max(psi, std::abs(x));
      force = std::max(force, std::abs(pre.force_now()));
    }
  }
  cb::SnapshotStyle style;
  style.width = r.width;
  style.height = r.height;
  cb::parse_view(r.view, style.view);
  style.psi_range = std::max(psi, 1e-6);
  style.force_range = std::max(force, 1e-6);
  style.threshold = scene.chain.threshold;
  style.strain_range = scene.chain.threshold;

  g_clip.context = cb::create_gl_context(cb::GlBackend::Auto);
  g_clip.renderer = std::make_unique<cb::Renderer>(r.width, r.height);
  cb::Integrator sim(scene.chain, cb::make_forcing(scene.drive), {dt, 1});
  for (int k = 0; k < kFrames; ++k) {
    sim.advance_to(k * substeps);
    g_clip.snapshots.push_back(
        cb::build_snapshot(sim.state(), scene.chain, sim.force_now(), style));
    g_clip.frames.push_back(g_clip.renderer->render(g_clip.snapshots.back()));
  }
}

// ---- libx264 alone ------------------------------------------------------------------------

struct X264 {
  AVCodecContext* codec = nullptr;
  AVFrame* frame = nullptr;
  AVPacket* packet = nullptr;
  SwsContext* sws = nullptr;
  ~X264() {
    sws_freeContext(sws);
    av_packet_free(&packet);
    av_frame_free(&frame);
    avcodec_free_context(&codec);
  }
  // Every packet the encoder has ready, dropped; returns false on an error.
  bool drain() {
    int err;
    while ((err = avcodec_receive_packet(codec, packet)) == 0) av_packet_unref(packet);
    return err == AVERROR(EAGAIN) || err == AVERROR_EOF;
  }
};

// Opened as video_encoder.cpp's open_codec() does for .mp4 (settings at their defaults).
bool open_x264(X264& x, int w, int h, int fps, const char* preset) {
  const AVCodec* encoder = avcodec_find_encoder_by_name("libx264");
  if (!encoder) return false;
  x.codec = avcodec_alloc_context3(encoder);
  x.codec->width = w;
  x.codec->height = h;
  x.codec->sample_aspect_ratio = AVRational{1, 1};
  x.codec->time_base = AVRational{1, fps};
  x.codec->framerate = AVRational{fps, 1};
  x.codec->pix_fmt = AV_PIX_FMT_YUV420P;
  x.codec->flags |= AV_CODEC_FLAG_BITEXACT | AV_CODEC_FLAG_GLOBAL_HEADER;  // MP4 wants it
  x.codec->thread_count = 2;
  x.codec->gop_size = 2 * fps;
  x.codec->color_range = AVCOL_RANGE_MPEG;
  x.codec->color_primaries = AVCOL_PRI_BT709;
  x.codec->color_trc = AVCOL_TRC_BT709;
  x.codec->colorspace = AVCOL_SPC_BT709;
  AVDictionary* options = nullptr;
  av_dict_set(&options, "preset", preset, 0);
  av_dict_set_int(&options, "crf", 18, 0);
  const int err = avcodec_open2(x.codec, encoder, &options);
  av_dict_free(&options);
  if (err < 0) return false;
  x.frame = av_frame_alloc();
  x.packet = av_packet_alloc();
  x.frame->format = AV_PIX_FMT_YUV420P;
  x.frame->width = w;
  x.frame->height = h;
  if (av_frame_get_buffer(x.frame, 0) < 0) return false;
  x.sws = sws_getContext(w, h, AV_PIX_FMT_RGBA, w, h, AV_PIX_FMT_YUV420P,
                         SWS_BILINEAR | SWS_ACCURATE_RND | SWS_BITEXACT, nullptr, nullptr, nullptr);
  if (!x.sws) return false;
  const int* bt709 = sws_getCoefficients(SWS_CS_ITU709);
  sws_setColorspaceDetails(x.sws, bt709, 1, bt709, 0, 0, 1 << 16, 1 << 16);
  return true;
}

void BM_X264Alone(benchmark::State& state) {
  const char* preset = kPresets[state.range(0)];
  state.SetLabel(preset);
  if (g_clip.frames.empty()) return state.SkipWithError(g_clip.error.c_str());
  const cb::Image& first = g_clip.frames.front();
  double convert = 0.0, total = 0.0, cpu = 0.0;
  for (auto _ : state) {
    const double cpu_start = process_cpu_seconds();  // x264's threads included
    const auto start = Clock::now();  // opening counts: the render process opens one too
    X264 x;
    if (!open_x264(x, first.width, first.height, 60, preset))
      return state.SkipWithError("cannot open libx264");
    for (int k = 0; k < kFrames; ++k) {
      const cb::Image& image = g_clip.frames[k];
      const auto t = Clock::now();
      if (av_frame_make_writable(x.frame) < 0) return state.SkipWithError("out of memory");
      const std::uint8_t* src[1] = {image.rgba.data()};
      const int stride[1] = {image.width * 4};
      sws_scale(x.sws, src, stride, 0, image.height, x.frame->data, x.frame->linesize);
      convert += seconds_since(t);
      x.frame->pts = k;
      if (avcodec_send_frame(x.codec, x.frame) < 0 || !x.drain())
        return state.SkipWithError("libx264 failed");
    }
    if (avcodec_send_frame(x.codec, nullptr) < 0 || !x.drain())  // flush the look-ahead
      return state.SkipWithError("libx264 failed");
    total = seconds_since(start);
    cpu = process_cpu_seconds() - cpu_start;
    state.SetIterationTime(total);
  }
  state.counters["fps"] = kFrames / total;
  state.counters["cores"] = cpu / total;  // busy cores on average (2 vCPUs here)
  g_cores[std::string("x264/") + preset].push_back(cpu / total);
  state.counters["convert_ms"] = 1e3 * convert / kFrames;  // per frame, of the above
  g_fps[std::string("x264/") + preset].push_back(kFrames / total);
}

// ---- conversion alone ------------------------------------------------------------------------

// RGBA -> yuv420p on one thread, no encoder: 0 with the encoder's flags (accurate rounding,
// bit-exact: the same bytes on every CPU), 1 with swscale's fast SIMD path (SWS_BILINEAR
// alone), to show what the encoder's choice costs.
void BM_Convert(benchmark::State& state) {
  const bool exact = state.range(0) == 0;
  state.SetLabel(exact ? "accurate+bitexact" : "fast");
  if (g_clip.frames.empty()) return state.SkipWithError(g_clip.error.c_str());
  const int w = g_clip.frames.front().width, h = g_clip.frames.front().height;
  SwsContext* sws = sws_getContext(w, h, AV_PIX_FMT_RGBA, w, h, AV_PIX_FMT_YUV420P,
                                   SWS_BILINEAR | (exact ? SWS_ACCURATE_RND | SWS_BITEXACT : 0),
                                   nullptr, nullptr, nullptr);
  const int* bt709 = sws_getCoefficients(SWS_CS_ITU709);
  sws_setColorspaceDetails(sws, bt709, 1, bt709, 0, 0, 1 << 16, 1 << 16);
  AVFrame* frame = av_frame_alloc();
  frame->format = AV_PIX_FMT_YUV420P;
  frame->width = w;
  frame->height = h;
  av_frame_get_buffer(frame, 0);
  double total = 0.0;
  for (auto _ : state) {
    const auto start = Clock::now();
    for (const cb::Image& image : g_clip.frames) {
      const std::uint8_t* src[1] = {image.rgba.data()};
      const int stride[1] = {image.width * 4};
      sws_scale(sws, src, stride, 0, image.height, frame->data, frame->linesize);
    }
    total = seconds_since(start);
    state.SetIterationTime(total);
  }
  av_frame_free(&frame);
  sws_freeContext(sws);
  state.counters["ms_per_frame"] = 1e3 * total / kFrames;
  g_fps[exact ? "convert/exact" : "convert/fast"].push_back(kFrames / total);
}

// ---- the render command ---------------------------------------------------------------------

// Runs `chainbreak render` on the clip; returns the wall time, or < 0 if it failed, and
// the CPU time of the process in `cpu`.
// posix_spawn, not fork: this process holds ~2 GB of frames, whose page tables a fork
// would copy on the clock.
double run_render(const char* preset, const fs::path& out, double& cpu) {
  std::string exe = CHAINBREAK_EXE, scene = scene_path(), out_path = out.string();
  std::string t_end = std::string("integrator.t_end=") + kTauEnd, preset_name = preset;
  std::string words[] = {"render", "-o", "--set", "--preset", "--quiet"};
  char* argv[] = {exe.data(),         words[0].data(), scene.data(), words[1].data(),
                  out_path.data(),    words[2].data(), t_end.data(), words[3].data(),
                  preset_name.data(), words[4].data(), nullptr};
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);  // the path it prints
  const auto start = Clock::now();
  pid_t pid = 0;
  const int err = posix_spawn(&pid, exe.c_str(), &actions, nullptr, argv, environ);
  posix_spawn_file_actions_destroy(&actions);
  if (err != 0) return -1;
  int status = 0;
  rusage usage{};
  if (::wait4(pid, &status, 0, &usage) != pid || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
    return -1;
  cpu = cpu_seconds(usage);
  return seconds_since(start);
}

void BM_Render(benchmark::State& state) {
  const char* preset = kPresets[state.range(0)];
  state.SetLabel(preset);
  // tmpfs: the file system is not what is measured.
  const fs::path dir = fs::path("/dev/shm") / ("bench_video-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const fs::path out = dir / "anomalous_breaking.mp4";
  double total = 0.0, cpu = 0.0;
  for (auto _ : state) {
    total = run_render(preset, out, cpu);
    if (total < 0) {
      fs::remove_all(dir);
      return state.SkipWithError("chainbreak render failed (run it by hand to see why)");
    }
    state.SetIterationTime(total);
  }
  // The same clip as the others: the sidecar must say kFrames frames at 1920x1080.
  std::ifstream in(dir / "anomalous_breaking.json");
  std::stringstream sidecar;
  sidecar << in.rdbuf();
  fs::remove_all(dir);
  if (sidecar.str().find("\"frames\":" + std::to_string(kFrames) + ",") == std::string::npos ||
      sidecar.str().find("\"width\":1920,\"height\":1080") == std::string::npos)
    return state.SkipWithError("the render made another clip than the benchmark's frames");
  state.counters["fps"] = kFrames / total;
  state.counters["cores"] = cpu / total;
  g_cores[std::string("render/") + preset].push_back(cpu / total);
  g_fps[std::string("render/") + preset].push_back(kFrames / total);
}

// ---- drawing alone --------------------------------------------------------------------------

void BM_Draw(benchmark::State& state) {
  if (g_clip.frames.empty()) return state.SkipWithError(g_clip.error.c_str());
  double total = 0.0, cpu = 0.0;
  for (auto _ : state) {
    const double cpu_start = process_cpu_seconds();  // llvmpipe's raster threads included
    const auto start = Clock::now();
    for (const auto& snapshot : g_clip.snapshots)
      benchmark::DoNotOptimize(g_clip.renderer->render(snapshot).rgba.data());
    total = seconds_since(start);
    cpu = process_cpu_seconds() - cpu_start;
    state.SetIterationTime(total);
  }
  state.counters["fps"] = kFrames / total;
  state.counters["cores"] = cpu / total;
  g_cores["draw"].push_back(cpu / total);
  g_fps["draw"].push_back(kFrames / total);
}

// One iteration is a whole clip (seconds); wall time, because x264's and the render
// process's threads are not the benchmark thread. Repetitions interleave at random (main).
void common(benchmark::internal::Benchmark* b) {
  b->Iterations(1)->Repetitions(kRepetitions)->UseManualTime()->Unit(benchmark::kSecond);
}
BENCHMARK(BM_Draw)->Apply(common);
BENCHMARK(BM_Convert)->DenseRange(0, 1)->Apply(common);
BENCHMARK(BM_X264Alone)->DenseRange(0, 2)->Apply(common);
BENCHMARK(BM_Render)->DenseRange(0, 2)->Apply(common);

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

void print_summary() {
  std::printf(
      "\nbench_video: %d frames of anomalous_breaking.toml at 1920x1080, 60 fps, crf 18; "
      "medians of %d; frames/s (busy cores)\n",
      kFrames, kRepetitions);
  std::printf("draw + readback alone: %.1f (%.2f)\n", median(g_fps["draw"]),
              median(g_cores["draw"]));
  std::printf("RGBA -> yuv420p alone, one thread: %.1f as the encoder does it, %.1f fast\n",
              median(g_fps["convert/exact"]), median(g_fps["convert/fast"]));
  std::printf("%-10s %18s %18s %12s\n", "preset", "x264 alone", "render", "render/x264");
  for (const char* p : kPresets) {
    const std::string x = std::string("x264/") + p, r = std::string("render/") + p;
    const double fx = median(g_fps[x]), fr = median(g_fps[r]);
    std::printf("%-10s %11.1f (%.2f) %11.1f (%.2f) %12.3f\n", p, fx, median(g_cores[x]), fr,
                median(g_cores[r]), fx > 0 ? fr / fx : 0.0);
  }
}

}  // namespace

int main(int argc, char** argv) {
  av_log_set_level(AV_LOG_ERROR);  // x264's banner and statistics are noise here
  // Repetitions in random order, so a drift of the machine's speed (PLATFORM-NOTES.md)
  // spreads over every benchmark instead of biasing a ratio. A flag given later wins.
  std::vector<char*> args(argv, argv + argc);
  char interleave[] = "--benchmark_enable_random_interleaving=true";
  args.insert(args.begin() + 1, interleave);
  int count = static_cast<int>(args.size());
  benchmark::Initialize(&count, args.data());
  if (benchmark::ReportUnrecognizedArguments(count, args.data())) return 1;
  try {
    make_clip();
  } catch (const std::exception& e) {
    g_clip.error = std::string("cannot make the frames: ") + e.what();
    g_clip.frames.clear();
  }
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  print_summary();
  // GL objects, then the context, before exit: a context still alive in a static destructor
  // crashes inside OSMesa, whose own exit handlers have run by then.
  g_clip.renderer.reset();
  g_clip.context.reset();
  return 0;
}
