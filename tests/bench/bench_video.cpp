// Video throughput at 1080p60: the whole `chainbreak render` pipeline against libx264 alone
// on the same frames, at the same preset, in one run. Goal (the issue): render >= 90% of
// x264-alone frames/s. main() prints the medians and the ratios after the benchmarks.
//
// - Frames: the default scene (anomalous_breaking.toml, 1920x1080, 60 fps, 10 tau/s), its
//   first kFrames frames (tau 0 .. 39.8), made once before timing by the program itself
//   (`chainbreak render --frames` into /dev/shm, read back): the very pictures `render`
//   encodes, overlay and all, whatever it draws today.
// - BM_Video/preset, one iteration = one pair, run back to back in alternating order so
//   that both halves see the same machine (PLATFORM-NOTES.md: its speed drifts; other
//   jobs may share it):
//   x264 alone: those RGBA frames through swscale (RGBA -> yuv420p, BT.709 limited) and
//   libx264, set up as cb::VideoEncoder does (crf 18, 2 threads, key frame every 2 s,
//   bit-exact), packets dropped: no container, no file. Conversion and encoding run one
//   after the other on one thread, as on the encoder's worker thread.
//   render: the `chainbreak render` process on the same clip (--set integrator.t_end=39.9
//   gives the same kFrames frames), writing to /dev/shm; wall time from spawn to exit, so
//   process start, scene, pre-pass, GL context, physics, drawing, readback, conversion,
//   encoding, muxing and fsync all count.
//   With $CHAINBREAK_BENCH_BASELINE (another build's chainbreak) a third half times that
//   program on the same clip, so a change's cost shows as render/baseline in one run.
//   Counters: frames/s of each, their ratio, busy cores of each (CPU time / wall time), and
//   "others": cores busy with other processes meanwhile (/proc/stat minus ours), which
//   flags a repetition measured on a shared machine.
// - BM_EncodeReady/preset: libx264 alone on the same pictures already in Y'CbCr (no
//   conversion on the clock): the encoder's own ceiling.
// - BM_Convert: the conversion to yuv420p alone, on one thread: where the time goes.
// - BM_OverlayShare: render with and without its overlay (default preset): the overlay's
//   share of the frame time.
#include <benchmark/benchmark.h>
#include <fcntl.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

extern "C" {
#include <libavcodec/avcodec.h>
#include <libswscale/swscale.h>
}

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "bench_support.h"
#include "output/image.h"
#include "output/png_writer.h"
#include "output/yuv420.h"

namespace {

using cb::bench::median;

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
// CPU seconds of this process and of its children that were waited for.
double own_cpu_seconds() {
  rusage self{}, children{};
  getrusage(RUSAGE_SELF, &self);
  getrusage(RUSAGE_CHILDREN, &children);
  return cpu_seconds(self) + cpu_seconds(children);
}

// CPU seconds the whole machine was busy (every process), from /proc/stat.
double machine_cpu_seconds() {
  std::ifstream in("/proc/stat");
  std::string cpu;
  double user = 0, nice = 0, system = 0, idle = 0, iowait = 0, irq = 0, softirq = 0, steal = 0;
  in >> cpu >> user >> nice >> system >> idle >> iowait >> irq >> softirq >> steal;
  return (user + nice + system + irq + softirq + steal) / static_cast<double>(sysconf(_SC_CLK_TCK));
}

// Wall time, our busy cores and other processes' busy cores over a stretch of work.
struct Meter {
  Clock::time_point start = Clock::now();
  double own = own_cpu_seconds(), machine = machine_cpu_seconds();
  double seconds() const { return seconds_since(start); }
  double cores() const { return (own_cpu_seconds() - own) / seconds(); }
  double others() const {
    return std::max(0.0, (machine_cpu_seconds() - machine) - (own_cpu_seconds() - own)) / seconds();
  }
};

// What every repetition measured, by name ("x264/veryfast", "convert/exact", ...), for the
// summary main() prints.
std::map<std::string, std::vector<double>> g_values;

std::vector<cb::Image> g_frames;  // the clip, RGBA
std::string g_clip_error;         // why there is no clip

std::string scene_path() {
  return std::string(CHAINBREAK_SCENES) + "/anomalous_breaking.toml";
}

// Runs `chainbreak ARGS` (stdout to /dev/null); returns the wall time, or < 0 if it failed.
// posix_spawn, not fork: this process holds ~2 GB of frames, whose page tables a fork
// would copy on the clock.
double run_chainbreak(std::vector<std::string> args, const char* exe = CHAINBREAK_EXE) {
  args.insert(args.begin(), exe);
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);  // the path it prints
  const auto start = Clock::now();
  pid_t pid = 0;
  const int err = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (err != 0) return -1;
  int status = 0;  // waited for, so its CPU time counts in RUSAGE_CHILDREN (Meter)
  if (::waitpid(pid, &status, 0) != pid || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
    return -1;
  return seconds_since(start);
}

const std::string kClipEnd = std::string("integrator.t_end=") + kTauEnd;

// The frames `render` encodes for the default scene with integrator.t_end = kTauEnd.
void make_clip() {
  const fs::path dir = fs::path("/dev/shm") / ("bench_video-frames-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  if (run_chainbreak(
          {"render", scene_path(), "--frames", dir.string(), "--set", kClipEnd, "--quiet"}) < 0) {
    g_clip_error = "chainbreak render --frames failed (run it by hand to see why)";
  } else {
    for (int k = 0; k < kFrames && g_clip_error.empty(); ++k) {
      char name[64];
      std::snprintf(name, sizeof name, "anomalous_breaking_%06d.png", k);
      try {
        g_frames.push_back(cb::read_png((dir / name).string()));
      } catch (const std::exception& e) {
        g_clip_error = e.what();
      }
    }
    if (fs::exists(dir / "anomalous_breaking_000240.png"))
      g_clip_error = "chainbreak rendered more frames than the benchmark expects";
  }
  fs::remove_all(dir);
  if (g_clip_error.empty() && (g_frames[0].width != 1920 || g_frames[0].height != 1080))
    g_clip_error = "the default scene no longer renders at 1920x1080";
  if (!g_clip_error.empty()) g_frames.clear();
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

// Encodes the clip; returns the wall time (opening included: the render process opens an
// encoder too), or < 0 on an error. Adds the time spent converting to `convert`.
double encode_alone(const char* preset, double& convert) {
  const auto start = Clock::now();
  const cb::Image& first = g_frames.front();
  X264 x;
  if (!open_x264(x, first.width, first.height, 60, preset)) return -1;
  for (int k = 0; k < kFrames; ++k) {
    const cb::Image& image = g_frames[k];
    const auto t = Clock::now();
    if (av_frame_make_writable(x.frame) < 0) return -1;
    const std::uint8_t* src[1] = {image.rgba.data()};
    const int stride[1] = {image.width * 4};
    sws_scale(x.sws, src, stride, 0, image.height, x.frame->data, x.frame->linesize);
    convert += seconds_since(t);
    x.frame->pts = k;
    if (avcodec_send_frame(x.codec, x.frame) < 0 || !x.drain()) return -1;
  }
  if (avcodec_send_frame(x.codec, nullptr) < 0 || !x.drain()) return -1;  // the look-ahead
  return seconds_since(start);
}

// The encoder alone on pictures already in Y'CbCr (converted before the clock starts, by
// output/yuv420.h as `render` does), handed over without a copy as `render` hands them:
// the ceiling for any pipeline that feeds libx264 at this preset.
double encode_ready(const char* preset) {
  static std::vector<cb::Yuv420Image> ready;
  if (ready.empty())
    for (const cb::Image& image : g_frames) {
      ready.emplace_back();
      cb::rgba_to_yuv420({image.rgba.data(), image.width, image.height, image.width * 4, false},
                         image.width, image.height, ready.back());
    }
  const auto start = Clock::now();
  X264 x;
  if (!open_x264(x, ready.front().width, ready.front().height, 60, preset)) return -1;
  AVFrame* lent = av_frame_alloc();
  for (int k = 0; k < kFrames; ++k) {
    cb::Yuv420Image& p = ready[k];
    av_frame_unref(lent);
    lent->buf[0] = av_buffer_create(
        p.bytes.data(), p.bytes.size(), [](void*, std::uint8_t*) {}, nullptr, 0);
    lent->format = AV_PIX_FMT_YUV420P;
    lent->width = p.width;
    lent->height = p.height;
    for (int c = 0; c < 3; ++c) {
      lent->data[c] = p.plane(c);
      lent->linesize[c] = c == 0 ? p.luma_stride : p.chroma_stride();
    }
    lent->pts = k;
    if (avcodec_send_frame(x.codec, lent) < 0 || !x.drain()) {
      av_frame_free(&lent);
      return -1;
    }
  }
  av_frame_free(&lent);
  if (avcodec_send_frame(x.codec, nullptr) < 0 || !x.drain()) return -1;
  return seconds_since(start);
}

void BM_EncodeReady(benchmark::State& state) {
  const char* preset = kPresets[state.range(0)];
  state.SetLabel(preset);
  if (g_frames.empty()) return state.SkipWithError(g_clip_error.c_str());
  double seconds = -1;
  for (auto _ : state) {
    seconds = encode_ready(preset);
    if (seconds < 0) return state.SkipWithError("libx264 failed");
    state.SetIterationTime(seconds);
  }
  state.counters["fps"] = kFrames / seconds;
  g_values["ready/" + std::string(preset)].push_back(kFrames / seconds);
}

// ---- conversion alone ------------------------------------------------------------------------

// RGBA -> yuv420p on one thread, no encoder: 0 swscale with the encoder's flags (accurate
// rounding, bit-exact: the same bytes on every CPU), 1 swscale's fast SIMD path
// (SWS_BILINEAR alone), 2 chainbreak's own (output/yuv420.h), which `render` uses.
void BM_Convert(benchmark::State& state) {
  const int variant = static_cast<int>(state.range(0));
  const char* names[] = {"exact", "fast", "chainbreak"};
  state.SetLabel(names[variant]);
  if (g_frames.empty()) return state.SkipWithError(g_clip_error.c_str());
  const int w = g_frames.front().width, h = g_frames.front().height;
  SwsContext* sws =
      sws_getContext(w, h, AV_PIX_FMT_RGBA, w, h, AV_PIX_FMT_YUV420P,
                     SWS_BILINEAR | (variant == 0 ? SWS_ACCURATE_RND | SWS_BITEXACT : 0), nullptr,
                     nullptr, nullptr);
  const int* bt709 = sws_getCoefficients(SWS_CS_ITU709);
  sws_setColorspaceDetails(sws, bt709, 1, bt709, 0, 0, 1 << 16, 1 << 16);
  AVFrame* frame = av_frame_alloc();
  frame->format = AV_PIX_FMT_YUV420P;
  frame->width = w;
  frame->height = h;
  av_frame_get_buffer(frame, 0);
  cb::Yuv420Image ours;
  double total = 0.0;
  for (auto _ : state) {
    const auto start = Clock::now();
    for (const cb::Image& image : g_frames) {
      if (variant == 2) {
        cb::rgba_to_yuv420({image.rgba.data(), w, h, w * 4, false}, w, h, ours);
        continue;
      }
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
  g_values[std::string("convert/") + names[variant]].push_back(kFrames / total);
}

// ---- the render command against x264 alone --------------------------------------------------

// What one half of a pair measured.
struct Half {
  double seconds = -1, cores = 0, others = 0;
};

void BM_Video(benchmark::State& state) {
  const char* preset = kPresets[state.range(0)];
  state.SetLabel(preset);
  if (g_frames.empty()) return state.SkipWithError(g_clip_error.c_str());
  // tmpfs: the file system is not what is measured.
  const fs::path dir = fs::path("/dev/shm") / ("bench_video-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const fs::path out = dir / "anomalous_breaking.mp4";
  static int pairs = 0;  // rotates the order: no half always runs first
  // $CHAINBREAK_BENCH_BASELINE: another build's chainbreak (e.g. before a change), timed as a
  // third half of every repetition, so "did the change slow render" is answered in one run.
  const char* baseline_exe = std::getenv("CHAINBREAK_BENCH_BASELINE");
  const int halves = baseline_exe ? 3 : 2;
  Half alone, render, baseline;
  double convert = 0.0;
  for (auto _ : state) {
    for (int half = 0; half < halves; ++half) {
      const Meter meter;
      const int which = (half + pairs) % halves;
      if (which == 0) {
        alone.seconds = encode_alone(preset, convert);
        alone.cores = meter.cores(), alone.others = meter.others();
      } else {
        Half& h = which == 1 ? render : baseline;
        h.seconds = run_chainbreak({"render", scene_path(), "-o", out.string(), "--set", kClipEnd,
                                    "--preset", preset, "--quiet"},
                                   which == 1 ? CHAINBREAK_EXE : baseline_exe);
        h.cores = meter.cores(), h.others = meter.others();
      }
    }
    ++pairs;
    if (alone.seconds < 0 || render.seconds < 0 || (baseline_exe && baseline.seconds < 0)) break;
    state.SetIterationTime(alone.seconds + render.seconds + std::max(0.0, baseline.seconds));
  }
  // The same clip as the frames in memory: the sidecar must say kFrames frames at 1080p.
  std::ifstream in(dir / "anomalous_breaking.json");
  std::stringstream sidecar;
  sidecar << in.rdbuf();
  fs::remove_all(dir);
  if (alone.seconds < 0) return state.SkipWithError("libx264 failed");
  if (render.seconds < 0)
    return state.SkipWithError("chainbreak render failed (run it by hand to see why)");
  if (baseline_exe && baseline.seconds < 0)
    return state.SkipWithError("the baseline's render failed (CHAINBREAK_BENCH_BASELINE)");
  if (sidecar.str().find("\"frames\":" + std::to_string(kFrames) + ",") == std::string::npos ||
      sidecar.str().find("\"width\":1920,\"height\":1080") == std::string::npos)
    return state.SkipWithError("the render made another clip than the benchmark's frames");

  const double fx = kFrames / alone.seconds, fr = kFrames / render.seconds;
  state.counters["x264_fps"] = fx;
  state.counters["render_fps"] = fr;
  state.counters["ratio"] = fr / fx;
  state.counters["x264_cores"] = alone.cores;  // x264's threads included
  state.counters["render_cores"] = render.cores;
  state.counters["others"] = std::max(alone.others, render.others);
  state.counters["convert_ms"] = 1e3 * convert / kFrames;  // per frame, inside x264 alone
  const std::string p = preset;
  g_values["x264/" + p].push_back(fx);
  g_values["render/" + p].push_back(fr);
  g_values["ratio/" + p].push_back(fr / fx);
  g_values["x264_cpu/" + p].push_back(alone.cores / fx);  // CPU seconds per frame
  g_values["render_cpu/" + p].push_back(render.cores / fr);
  g_values["others/" + p].push_back(std::max(alone.others, render.others));
  if (baseline_exe) {
    const double fb = kFrames / baseline.seconds;
    state.counters["baseline_fps"] = fb;
    state.counters["baseline_ratio"] = fb / fx;
    g_values["baseline/" + p].push_back(fb);
    g_values["baseline_ratio/" + p].push_back(fb / fx);
  }
}

// The overlay's share of `render`'s frame time (issue goal: <= 15 %): the same clip at the
// default preset with and without it (--no-overlay), as pairs in alternating order.
void BM_OverlayShare(benchmark::State& state) {
  if (g_frames.empty()) return state.SkipWithError(g_clip_error.c_str());
  const fs::path dir = fs::path("/dev/shm") / ("bench_video-ov-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string out = (dir / "clip.mp4").string();
  static int pairs = 0;
  double with = -1, without = -1;
  for (auto _ : state) {
    for (int half = 0; half < 2; ++half) {
      std::vector<std::string> args = {"render", scene_path(), "-o",     out,
                                       "--set",  kClipEnd,     "--quiet"};
      const bool overlay = (half + pairs) % 2 == 0;
      if (!overlay) args.push_back("--no-overlay");
      (overlay ? with : without) = run_chainbreak(args);
    }
    ++pairs;
    if (with < 0 || without < 0) break;
    state.SetIterationTime(with + without);
  }
  fs::remove_all(dir);
  if (with < 0 || without < 0) return state.SkipWithError("chainbreak render failed");
  state.counters["fps_with"] = kFrames / with;
  state.counters["fps_without"] = kFrames / without;
  state.counters["share"] = 1.0 - without / with;  // of the frame time with the overlay
  g_values["overlay/with"].push_back(kFrames / with);
  g_values["overlay/without"].push_back(kFrames / without);
  g_values["overlay/share"].push_back(1.0 - without / with);
}

// One iteration is a whole clip (BM_Video: a pair of them), in seconds of wall time: x264's
// threads and the render process are not the benchmark thread. Repetitions interleave at
// random (main).
void common(benchmark::internal::Benchmark* b) {
  b->Iterations(1)->Repetitions(kRepetitions)->UseManualTime()->Unit(benchmark::kSecond);
}
BENCHMARK(BM_Convert)->DenseRange(0, 2)->Apply(common);
BENCHMARK(BM_Video)->DenseRange(0, 2)->Apply(common);
BENCHMARK(BM_EncodeReady)->DenseRange(0, 2)->Apply(common);
BENCHMARK(BM_OverlayShare)->Apply(common);

void print_summary() {
  auto m = [](const std::string& name) { return median(g_values[name]); };
  std::printf(
      "\nbench_video: %d frames of anomalous_breaking.toml at 1920x1080, 60 fps, crf 18; "
      "medians of %d\n",
      kFrames, kRepetitions);
  std::printf(
      "RGBA -> yuv420p alone, one thread, frames/s: swscale %.1f exact (as x264 alone does "
      "it), %.1f fast; chainbreak's own %.1f (as render does it)\n",
      m("convert/exact"), m("convert/fast"), m("convert/chainbreak"));
  std::printf("%-10s %8s %8s %8s %11s %11s %8s\n", "preset", "x264", "render", "ratio", "x264 cpu",
              "render cpu", "others");
  std::printf("%-10s %8s %8s %8s %11s %11s %8s\n", "", "fps", "fps", "", "ms/frame", "ms/frame",
              "cores");
  // CPU per frame: busy cores / frames per second. Their difference is what render does
  // besides encoding (physics, overlay history, drawing, readback, process start).
  for (const std::string p : kPresets)
    std::printf("%-10s %8.1f %8.1f %8.3f %11.1f %11.1f %8.2f\n", p.c_str(), m("x264/" + p),
                m("render/" + p), m("ratio/" + p), 1e3 * m("x264_cpu/" + p),
                1e3 * m("render_cpu/" + p), m("others/" + p));
  if (!g_values["baseline/veryfast"].empty()) {
    std::printf("baseline (%s), in the same repetitions:\n",
                std::getenv("CHAINBREAK_BENCH_BASELINE"));
    std::printf("%-10s %8s %8s %14s\n", "preset", "fps", "ratio", "render/baseline");
    for (const std::string p : kPresets)
      std::printf("%-10s %8.1f %8.3f %14.3f\n", p.c_str(), m("baseline/" + p),
                  m("baseline_ratio/" + p), m("ratio/" + p) / m("baseline_ratio/" + p));
  }
  std::printf(
      "render at veryfast: %.1f frames/s with the overlay, %.1f without: the overlay "
      "takes %.1f %% of the frame time\n",
      m("overlay/with"), m("overlay/without"), 100.0 * m("overlay/share"));
  std::printf("libx264 on ready Y'CbCr (no conversion), frames/s, and render against it:\n");
  for (const std::string p : kPresets)
    std::printf("%-10s %8.1f %8.3f\n", p.c_str(), m("ready/" + p),
                m("render/" + p) / m("ready/" + p));
}

}  // namespace

int main(int argc, char** argv) {
  av_log_set_level(AV_LOG_ERROR);  // x264's banner and statistics are noise here
  if (!cb::bench::initialize(argc, argv)) return 1;
  make_clip();
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  print_summary();
  return 0;
}
