// `chainbreak snapshot`: PNG frames of a scene at exact times.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>

#include "app/commands.h"
#include "app/frame_source.h"
#include "app/frames.h"
#include "app/option_parsers.h"
#include "app/render_plan.h"
#include "app/run_set.h"
#include "app/snapshot_images.h"
#include "app/zoom.h"
#include "output/frame_writer.h"
#include "output/output_lock.h"
#include "output/png_writer.h"
#include "overlay/overlay.h"
#include "physics/integrator.h"
#include "resources/resources.h"
#include "snapshot/stack.h"

namespace cb {

namespace {

// What an interrupted snapshot leaves: the PNGs written whole before it.
std::string done_text(std::size_t written) {
  return written == 0 ? std::string("nothing written")
                      : std::to_string(written) + " PNG(s) written before it are complete";
}

// "<scene>_tau_000123.450.png": zero-padded so that names sort by time.
std::string snapshot_name(const std::string& scene, double tau) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "_tau_%010.3f.png", tau);
  return scene + buf;
}

// Ten digits: a frame time typed back as printed is accepted (within kFrameSlack).
std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.10g", v);
  return buf;
}
// How far (in frames) a requested tau may sit from a frame time: frame times such as k/6
// cannot be typed exactly.
constexpr double kFrameSlack = 1e-6;

// With an overlay: the video's frames at those times, made as `render` makes them (its plan,
// its FrameSource, its Overlay), so that a PNG equals the video's frame pixel for pixel.
int overlay_images(const SnapshotRequest& o, const SceneDesc& scene,
                   const SnapshotConsumer& consume, std::string& error) {
  const std::vector<double>& times = o.times;
  RenderOptions ro;
  ro.frames_dir = ".";  // PNGs: no video codec to check
  ro.frame = o.frame;
  ro.overlay = o.overlay;
  RenderPlan plan = plan_render(scene, ro);
  if (!plan.overlay_layout.enabled)
    throw SceneError("--overlay " + o.overlay + ": " +
                     (plan.overlay.any() ? "the frame is too small for the overlay (at least " +
                                               std::to_string(kOverlayMinWidth) + "x" +
                                               std::to_string(kOverlayMinHeight) + ")"
                                         : std::string("no part switched on")));
  measure_plan(scene, plan);
  std::vector<std::int64_t> frames;
  const FrameGrid& grid = plan.grid;
  const double last_tau = grid.tau(grid.frames() - 1);
  for (double tau : times) {
    // The frame clock (frame_grid.h) says which times are frames: within kFrameSlack of a
    // frame's step, in units of the normal frame step.
    const std::int64_t frame = grid.frame_at(tau, kFrameSlack * grid.tau_per_frame());
    if (tau > last_tau + kFrameSlack * grid.tau_per_frame())
      throw SceneError("--at " + o.at_text + ": tau " + number(tau) +
                       " is past the video's last frame (tau " + number(last_tau) +
                       "; see integrator.t_end and after_break)");
    if (frame < 0) {
      const std::int64_t after = grid.first_frame_at_or_after(tau);
      throw SceneError("--at " + o.at_text +
                       ": with --overlay each tau must be a frame time of the " +
                       "video (every speed / fps = " + number(grid.tau_per_frame()) +
                       " of tau, closer in slow motion); nearest to " + number(tau) + ": " +
                       number(grid.tau(std::max<std::int64_t>(0, after - 1))) + " or " +
                       number(grid.tau(after)) +
                       " (or change the frame times with --set render.fps=... / render.speed=...)");
    }
    frames.push_back(frame);
  }
  Canvas canvas = make_canvas(o.frame, plan.frame.width, plan.frame.height);
  Overlay overlay(plan.frame.width, plan.frame.height, plan.frame.fps, plan.overlay,
                  plan.style.theme);
  FrameSource source(scene, plan, 1);
  for (std::size_t i = 0; i < times.size(); ++i) {
    if (o.stop && *o.stop) return interrupt_status();
    const std::optional<RenderSnapshot> snap = source.frame(frames[i]);
    if (!snap && g_interrupted) return interrupt_status();
    if (!snap) {
      error = source.error();
      return 1;
    }
    canvas.renderer->draw(*snap);
    overlay.draw(*snap);
    Image image;
    canvas.renderer->read(image);
    consume(times[i], std::move(image));
  }
  return 0;
}

}  // namespace

// Two times whose names round to the same file would overwrite one another.
void require_distinct_names(const std::string& scene, const std::vector<double>& times) {
  for (std::size_t i = 1; i < times.size(); ++i)
    if (snapshot_name(scene, times[i]) == snapshot_name(scene, times[i - 1]))
      throw SceneError("--at: tau " + number(times[i - 1]) + " and " + number(times[i]) +
                       " would both be written as " + snapshot_name(scene, times[i]) +
                       "; the file names keep 3 decimals, so give times at least 0.001 apart");
}

namespace {

// One scene's chain at increasing exact times, as snapshot data laid out for `frame`.
class ChainAtTimes {
 public:
  ChainAtTimes(const SceneDesc& scene, const RenderDesc& frame, double last_tau)
      : scene_(scene),
        extent_(measure_run(scene, last_tau, scene.integrator.dt)),
        style_(snapshot_style(scene, frame, extent_)),
        grid_run_(scene.chain, make_forcing(scene.drive), {scene.integrator.dt, 1}),
        camera_(parse_zoom(frame.zoom, scene.chain.beads, "--zoom"), scene.chain.beads,
                extent_.breaks.empty() ? 0 : extent_.breaks.front().spring,
                extent_.breaks.empty() ? -1.0 : extent_.breaks.front().tau) {}

  // Null when the state stopped being finite (error() says why) or on an interrupt.
  std::optional<RenderSnapshot> at(double tau) {
    // The integrator lands exactly on tau: on the scene's grid when tau is a multiple of dt,
    // otherwise with the step shrunk to tau / ceil(tau / dt) (never larger than dt), in a run
    // of its own.
    const double dt = scene_.integrator.dt;
    const double steps = tau / dt;
    const bool on_grid = std::abs(steps - std::round(steps)) < 1e-9 * std::max(1.0, steps);
    const auto count = static_cast<std::int64_t>(on_grid ? std::llround(steps) : std::ceil(steps));
    const double step_dt = on_grid || count == 0 ? dt : tau / static_cast<double>(count);
    std::optional<Integrator> own_run;
    if (!on_grid)
      own_run.emplace(scene_.chain, make_forcing(scene_.drive), IntegratorOptions{step_dt, 1});
    Integrator& sim = on_grid ? grid_run_ : *own_run;
    if (!advance_watching(sim, count)) {
      error_ = sim.error();
      return std::nullopt;
    }
    // auto / break zoom: a single picture has no camera history, so it settles at once.
    SnapshotStyle at_tau = style_;
    camera_.frame(sim.state(), at_tau.zoom_first, at_tau.zoom_last, true);
    return build_snapshot(sim.state(), scene_.chain, sim.force_now(), at_tau);
  }
  const std::string& error() const { return error_; }

 private:
  const SceneDesc& scene_;
  RunExtent extent_;
  SnapshotStyle style_;
  Integrator grid_run_;  // the on-grid times (sorted) share one run
  ZoomCamera camera_;    // settled at every picture (no history), so one serves them all
  std::string error_;
};

}  // namespace

int snapshot_images(const std::vector<SceneDesc>& scenes, const SnapshotRequest& request,
                    const SnapshotConsumer& consume, std::string& error) {
  if (scenes.empty() || scenes.size() > static_cast<std::size_t>(kMaxSideBySide))
    throw SceneError("snapshot: give 1 to " + std::to_string(kMaxSideBySide) +
                     " scenes (stacked), not " + std::to_string(scenes.size()));
  // The requested theme reaches the pictures through the frame options, as --theme does.
  SnapshotRequest o = request;
  if (!o.theme.empty()) o.frame.theme = o.theme;
  // Per scene two runs at most at once (the grid's and an off-grid time's, or the pre-pass).
  MemoryEstimate memory;
  for (const SceneDesc& scene : scenes)
    memory.needs.push_back({"RK4 state of " + scene.name, 2 * rk4_bytes(scene.chain.beads)});
  require_memory(memory, machine_memory(), "snapshot " + scenes[0].name,
                 "use fewer beads (chain.beads)");
  const bool overlay = !o.overlay.empty() && o.overlay != "none";
  if (overlay && scenes.size() > 1)
    throw SceneError(
        "--overlay: the overlay plots one run; stacked scenes are drawn without it "
        "(give one scene, or leave out --overlay)");
  if (overlay) return overlay_images(o, scenes[0], consume, error);

  // The picture's size and theme are the first scene's; 2-4 scenes each get a band of its
  // height, laid out as render's side-by-side video lays them out (run_set.h).
  const RenderDesc frame = frame_settings(scenes[0], o.frame);
  FrameOptions band_options = o.frame;
  if (scenes.size() > 1)
    band_options.size =
        std::to_string(frame.width) + "x" +
        std::to_string(std::max(16, frame.height / static_cast<int>(scenes.size())));
  std::vector<std::unique_ptr<ChainAtTimes>> chains;
  for (const SceneDesc& scene : scenes)
    chains.push_back(std::make_unique<ChainAtTimes>(
        scene, frame_settings(scene, scenes.size() > 1 ? band_options : o.frame), o.times.back()));
  const std::vector<std::string> labels =
      scenes.size() > 1 ? side_by_side_labels(scenes) : std::vector<std::string>{};
  Canvas canvas = make_canvas(o.frame, frame.width, frame.height);

  for (double tau : o.times) {
    if (o.stop && *o.stop) return interrupt_status();
    std::vector<RenderSnapshot> parts;
    for (std::size_t i = 0; i < chains.size(); ++i) {
      std::optional<RenderSnapshot> snap = chains[i]->at(tau);
      if (!snap) {
        if (g_interrupted) return interrupt_status();
        error = (scenes.size() > 1 ? scenes[i].name + ": " : "") + chains[i]->error();
        return 1;
      }
      parts.push_back(std::move(*snap));
    }
    consume(tau, canvas.renderer->render(
                     scenes.size() == 1
                         ? parts[0]
                         : stack_snapshots(std::move(parts), labels, frame.width, frame.height,
                                           parse_theme(frame.theme).value_or(ThemeName::Dark))));
  }
  return 0;
}

int snapshot_images(const SceneDesc& scene, const SnapshotRequest& request,
                    const SnapshotConsumer& consume, std::string& error) {
  return snapshot_images(std::vector<SceneDesc>{scene}, request, consume, error);
}

int snapshot_command(const SnapshotOptions& o) {
  std::vector<SceneDesc> scenes;
  for (const std::string& path : o.scenes.empty() ? std::vector<std::string>{o.scene} : o.scenes)
    scenes.push_back(load_scene(path, o.overrides));
  // Stacked scenes share one picture per time, named after all of them.
  std::string name = scenes[0].name;
  for (std::size_t i = 1; i < scenes.size(); ++i) name += "_vs_" + scenes[i].name;
  SnapshotRequest request;
  request.times = parse_times(o.at);
  request.at_text = o.at;
  request.frame = o.frame;
  request.overlay = o.overlay;
  request.stop = &g_interrupted;
  require_distinct_names(name, request.times);
  require_writable_dir(o.out_dir);
  // One snapshot of these scenes into this folder at a time (issue #12, row 9): two would
  // write the same names, each renaming its PNG over the other's.
  const OutputLock lock((std::filesystem::path(o.out_dir) / (name + "_tau")).string());
  std::string error;
  std::size_t written = 0;
  const int status = snapshot_images(
      scenes, request,
      [&](double tau, Image&& image) {
        const std::string path =
            (std::filesystem::path(o.out_dir) / snapshot_name(name, tau)).string();
        write_png(path, image);
        std::printf("%s\n", path.c_str());
        ++written;
      },
      error);
  if (status == 1) std::fprintf(stderr, "chainbreak: %s\n", error.c_str());
  if (status == 130 || status == 143) return interrupted_status(done_text(written));
  return status;
}

}  // namespace cb
