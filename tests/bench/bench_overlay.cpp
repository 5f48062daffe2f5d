// What the overlay costs per 1080p frame (issue goal: <= 15 % of the frame time).
//
// The frames are the default scene's chain as `render` feeds them (overlay_test_support.h's
// Video: N = 30, phi_c = 3, ramp beta = 0.02, a frame every 0.5 tau up to tau 169.5, past
// the first break, so the plots are full and the space-time picture tall). One frame here is
// what `render`'s drawing thread does per frame: Renderer::draw, then Overlay::draw or not,
// then the read-back into Y'CbCr (Renderer::read_yuv420), cycling over the last 50 frames.
// - BM_Frame/overlay:0|1, OSMesa: wall time per frame (UseRealTime; llvmpipe draws on its own
//   threads) and the process's CPU time per frame (counter cpu_ms), which other processes
//   disturb less. The overlay's share is (with - without) / with, printed by main().
// - The producer-side cost (OverlayHistory::record + share per frame) is printed too.
#include <benchmark/benchmark.h>
#include <time.h>

#include <algorithm>
#include <cstdio>
#include <map>
#include <memory>
#include <vector>

#include "bench_support.h"
#include "gl/gl_context.h"
#include "output/image.h"
#include "overlay/overlay.h"
#include "overlay_test_support.h"
#include "render/renderer.h"

namespace {

using cb::bench::median;

constexpr int kW = 1920, kH = 1080;
constexpr int kCycle = 50;  // frames drawn in turn
std::vector<cb::RenderSnapshot> g_frames;
double g_record_ms = 0.0;
std::map<std::string, std::vector<double>> g_values;  // per repetition, for main's summary

double cpu_ms() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return 1e3 * static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_nsec);
}

void BM_Frame(benchmark::State& state) {
  const bool with = state.range(0) != 0;
  state.SetLabel(with ? "with overlay" : "without");
  std::unique_ptr<cb::GlContext> context;
  try {
    context = cb::create_gl_context(cb::GlBackend::OSMesa);
  } catch (const cb::GlError& e) {
    return state.SkipWithError(e.what());
  }
  cb::Renderer renderer(kW, kH);
  std::unique_ptr<cb::Overlay> overlay;
  if (with) overlay = std::make_unique<cb::Overlay>(kW, kH, 60.0, cb::OverlaySwitches{});
  cb::Yuv420Image picture;
  const auto frame = [&](int k) {
    const cb::RenderSnapshot& snap = g_frames[g_frames.size() - kCycle + k % kCycle];
    renderer.draw(snap);
    if (overlay) overlay->draw(snap);
    renderer.read_yuv420(picture, kW, kH);
  };
  for (int k = 0; k < 5; ++k) frame(k);  // warm up: font atlas, textures, shaders
  int k = 0;
  const double c0 = cpu_ms();
  for (auto _ : state) frame(k++);
  const double per_frame = (cpu_ms() - c0) / static_cast<double>(state.iterations());
  state.counters["cpu_ms"] = per_frame;
  state.counters["fps"] =
      benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  g_values[with ? "cpu/with" : "cpu/without"].push_back(per_frame);
}
BENCHMARK(BM_Frame)
    ->ArgName("overlay")
    ->DenseRange(0, 1)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MinTime(2.0)
    ->Repetitions(5);

// Wall-time medians come from Google Benchmark's own aggregates; this adds the CPU view.
class Summary : public benchmark::ConsoleReporter {
 public:
  void ReportRuns(const std::vector<Run>& runs) override {
    for (const Run& r : runs)
      if (r.aggregate_name == "median")
        wall_[r.run_name.args] = r.GetAdjustedRealTime();  // ms per frame
    ConsoleReporter::ReportRuns(runs);
  }
  void print() {
    const double a = wall_["overlay:0"], b = wall_["overlay:1"];
    const double ca = median(g_values["cpu/without"]), cb_ = median(g_values["cpu/with"]);
    std::printf(
        "\nbench_overlay, 1920x1080, OSMesa, medians of 5: wall %.2f ms without the overlay, "
        "%.2f ms with: the overlay is %.1f %% of the frame time; CPU %.2f / %.2f ms: %.1f %%.\n"
        "Recording its data on the producer thread: %.3f ms per frame.\n",
        a, b, 100.0 * (b - a) / b, ca, cb_, 100.0 * (cb_ - ca) / cb_, g_record_ms);
  }

 private:
  std::map<std::string, double> wall_;
};

}  // namespace

int main(int argc, char** argv) {
  if (!cb::bench::initialize(argc, argv)) return 1;
  const cb::overlay_test::Video video(kW, kH);
  g_frames = video.frames(340, &g_record_ms);  // to tau 169.5, past the first break
  Summary summary;
  benchmark::RunSpecifiedBenchmarks(&summary);
  summary.print();
  benchmark::Shutdown();
  return 0;
}
