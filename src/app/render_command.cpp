// `chainbreak render`: the whole run as a video (MP4, WebM, GIF) or a PNG sequence.
//
// Design note: three stages overlap. A producer thread steps the physics and builds each
// frame's snapshot; this thread draws it with GL and reads the pixels back; the sink
// converts and encodes (VideoEncoder) or compresses PNGs (PngSequence) on its own threads.
// Bounded queues between them keep memory flat, so the slowest stage, normally the
// encoder, sets the pace. The overlay follows the same split: the producer records its
// histories (OverlayHistory) and hands each snapshot an immutable OverlayData; this thread
// draws it with ImGui over the renderer's frame, before the pixels are read back.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <thread>

#include "app/bounded_queue.h"
#include "app/commands.h"
#include "app/frame_source.h"
#include "app/frames.h"
#include "app/progress.h"
#include "app/render_plan.h"
#include "app/run_set.h"
#include "output/frame_writer.h"
#include "output/output_file.h"
#include "output/output_lock.h"
#include "output/video_encoder.h"
#include "overlay/overlay.h"
#include "resources/resources.h"

namespace cb {

namespace {

// The physics side of the pipeline, on its own thread: each frame's snapshot into the queue.
// Stops early on interruption or a non-finite state.
struct Producer {
  RunSet& runs;
  std::int64_t frames;
  BoundedQueue<RenderSnapshot>& queue;
  std::string error;

  void operator()() {
    for (std::int64_t k = 0; k < frames && !g_interrupted; ++k) {
      std::optional<RenderSnapshot> snap = runs.frame(k);
      if (!snap) {
        if (!g_interrupted) error = runs.error();
        break;
      }
      if (!queue.push(std::move(*snap))) break;
    }
    queue.close();
  }
};

std::unique_ptr<FrameSink> open_sink(const RenderOptions& o, const SceneDesc& scene,
                                     const RenderPlan& plan) {
  if (!o.frames_dir.empty()) return std::make_unique<PngSequence>(o.frames_dir, scene.name, 2);
  VideoSettings v;
  v.width = plan.frame.width;
  v.height = plan.frame.height;
  v.fps = static_cast<int>(plan.frame.fps);
  if (o.crf >= 0) v.crf = o.crf;
  if (!o.preset.empty()) v.preset = o.preset;
  return std::make_unique<VideoEncoder>(plan.output, v);
}

// Frames in flight: the snapshot queue (3) and the sink's pictures (read back, converting,
// encoding: at most 8 of them at once), each w x h x 4 bytes; and the physics.
MemoryEstimate render_memory(const SceneDesc& scene, const RenderPlan& plan) {
  const double beads = scene.chain.beads;
  const double frame_bytes = 4.0 * plan.frame.width * plan.frame.height;
  MemoryEstimate m;
  m.needs.push_back({"RK4 state", 2 * rk4_bytes(beads)});  // the pre-pass and the render
  m.needs.push_back({"frames in flight", 8 * frame_bytes});
  m.needs.push_back({"snapshots in flight", 3 * 64 * beads});
  return m;
}

}  // namespace

int render_scenes(std::vector<SceneDesc> scenes, const RenderOptions& o);

int render_command(const RenderOptions& o) {
  std::vector<SceneDesc> scenes;
  // The same --set applies to every scene of a side-by-side video.
  for (const std::string& path : o.scenes.empty() ? std::vector<std::string>{o.scene} : o.scenes)
    scenes.push_back(load_scene(path, o.overrides));
  return render_scenes(std::move(scenes), o);
}

int render_scene(const SceneDesc& scene, const RenderOptions& o) {
  return render_scenes({scene}, o);
}

int render_scenes(std::vector<SceneDesc> scenes, const RenderOptions& o) {
  choose_gl_backend(o.frame.gl);  // a misspelled backend fails now, not after the pre-pass
  RunSet runs(std::move(scenes), o);  // each plan refuses too many frames before any work
  const SceneDesc& scene = runs.scene(0);
  const RenderPlan& plan = runs.plan();
  const MachineMemory machine = machine_memory();
  const MemoryEstimate memory = render_memory(scene, plan);
  require_memory(memory, machine, "render " + scene.name,
                 "use fewer beads (chain.beads) or a smaller frame (--size, -q l)");
  // The default folder is made on demand; a dry run only checks it could be.
  const bool default_folder = o.output.empty() && o.frames_dir.empty();
  if (default_folder && !std::filesystem::exists("renders")) {
    if (o.dry_run)
      check_output_dir(".");
    else
      std::filesystem::create_directories("renders");
  }
  // Opening the sink checks the output folder and the encoder before any work (the physics
  // pre-pass below can take a while for a large chain).
  std::unique_ptr<FrameSink> sink;
  if (!(o.dry_run && default_folder && !std::filesystem::exists("renders")))
    sink = open_sink(o, scene, plan);
  // One render at a time per output (issue #12, row 9): held until the sidecar is in place,
  // so the video (or PNGs) and the JSON sidecar always come from the same run.
  std::optional<OutputLock> lock;
  if (!o.dry_run) lock.emplace(sidecar_path(scene, plan));
  runs.measure();
  if (o.dry_run) {
    std::string json = runs.json("");
    json.pop_back();  // the closing brace: the estimate joins the plan
    std::printf("%s,\"memory\":%s,\"memory_available_bytes\":%.0f,\"memory_source\":\"%s\"}\n",
                json.c_str(), memory.json().c_str(), machine.available_bytes,
                machine.source.c_str());
    return 0;  // the sink's destructor removes its temporary file
  }
  Canvas canvas = make_canvas(o.frame, plan.frame.width, plan.frame.height);
  const std::string gl = describe(*canvas.context);
  // Made here, before any frame: a missing font stops the run with nothing written.
  std::unique_ptr<Overlay> overlay;
  if (plan.overlay_layout.enabled)
    overlay = std::make_unique<Overlay>(plan.frame.width, plan.frame.height, plan.frame.fps,
                                        plan.overlay, plan.style.theme);
  if (!o.quiet) {
    std::fprintf(stderr, "render %s: %lld frames %dx%d at %g fps (%g tau/s, dt %g) -> %s\n",
                 scene.name.c_str(), static_cast<long long>(runs.frames()), plan.frame.width,
                 plan.frame.height, plan.frame.fps, plan.frame.speed, plan.grid.dt(),
                 plan.output.c_str());
    if (plan.overlay.any() && !plan.overlay_layout.enabled)
      std::fprintf(stderr, "render %s: no overlay below %dx%d (its text would not be readable)\n",
                   scene.name.c_str(), kOverlayMinWidth, kOverlayMinHeight);
  }

  BoundedQueue<RenderSnapshot> snapshots(3);
  runs.start(o.threads);
  Producer producer{runs, runs.frames(), snapshots, {}};
  std::thread physics(std::ref(producer));
  Progress progress("render " + scene.name, static_cast<double>(runs.frames()), o.quiet,
                    "frames");
  std::int64_t done = 0;
  // Video sinks take Y'CbCr converted here, as the pixels are read: less CPU per frame than
  // the encoder's own conversion (output/yuv420.h says why that matters).
  const std::optional<PictureSize> yuv = sink->yuv420_size();
  try {
    while (auto snap = snapshots.pop()) {
      canvas.renderer->draw(*snap);  // leaves its framebuffer bound for the overlay
      if (overlay) overlay->draw(*snap);
      if (yuv) {
        Yuv420Image picture = sink->spare_yuv420();
        canvas.renderer->read_yuv420(picture, yuv->width, yuv->height);
        sink->push_yuv420(std::move(picture));
      } else {
        Image image;
        canvas.renderer->read(image);
        sink->push(std::move(image));
      }
      progress.update(static_cast<double>(++done));
      if (o.on_frame) o.on_frame(done, runs.frames());
    }
  } catch (...) {
    snapshots.close();
    physics.join();
    throw;
  }
  physics.join();

  if (!producer.error.empty()) {
    std::fprintf(stderr, "chainbreak: %s\n", producer.error.c_str());
    return 1;  // the sink's destructor leaves nothing under the requested name
  }
  if (g_interrupted) {
    auto* video = dynamic_cast<VideoEncoder*>(sink.get());
    if (video) {
      const std::string partial = video->abort_partial();
      if (partial.empty())
        interrupted_status("before the first frame; nothing written");
      else
        interrupted_status("after " + std::to_string(done) +
                           " frames; what was rendered plays as " + partial);
    } else {
      sink->finish();
      interrupted_status("after " + std::to_string(done) + " frames (complete PNGs kept in " +
                         o.frames_dir + ")");
    }
    return interrupt_status();
  }
  sink->finish();
  OutputFile sidecar(sidecar_path(scene, plan));
  sidecar.write(runs.json(gl) + "\n");
  sidecar.commit();
  if (!o.quiet)
    std::fprintf(stderr, "render %s: wrote %s\n", scene.name.c_str(), plan.output.c_str());
  std::printf("%s\n", plan.output.c_str());
  return 0;
}

}  // namespace cb
