// `chainbreak snapshot`: PNG frames of a scene at exact times.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>

#include "app/commands.h"
#include "app/frame_source.h"
#include "app/frames.h"
#include "app/option_parsers.h"
#include "app/zoom.h"
#include "app/render_plan.h"
#include "app/snapshot_images.h"
#include "output/frame_writer.h"
#include "output/output_lock.h"
#include "output/png_writer.h"
#include "overlay/overlay.h"
#include "physics/integrator.h"
#include "resources/resources.h"

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
      throw SceneError("--at " + o.at_text + ": with --overlay each tau must be a frame time of the " +
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

int snapshot_images(const SceneDesc& scene, const SnapshotRequest& request,
                    const SnapshotConsumer& consume, std::string& error) {
  // The requested theme reaches the pictures through the frame options, as --theme does.
  SnapshotRequest o = request;
  if (!o.theme.empty()) o.frame.theme = o.theme;
  // Two runs at most at once (the grid's and an off-grid time's, or the pre-pass), and a frame.
  MemoryEstimate memory;
  memory.needs.push_back({"RK4 state", 2 * rk4_bytes(scene.chain.beads)});
  require_memory(memory, machine_memory(), "snapshot " + scene.name,
                 "use fewer beads (chain.beads)");
  if (!o.overlay.empty() && o.overlay != "none") return overlay_images(o, scene, consume, error);
  const std::vector<double>& times = o.times;
  const RenderDesc frame = frame_settings(scene, o.frame);
  const double dt = scene.integrator.dt;
  const RunExtent extent = measure_run(scene, times.back(), dt);
  const SnapshotStyle style = snapshot_style(scene, frame, extent);
  Canvas canvas = make_canvas(o.frame, frame.width, frame.height);

  // On-grid times (sorted) share one run; an off-grid time gets a run of its own.
  Integrator grid_run(scene.chain, make_forcing(scene.drive), {dt, 1});
  for (double tau : times) {
    if (o.stop && *o.stop) return interrupt_status();
    // The integrator lands exactly on tau: on the scene's grid when tau is a multiple of dt,
    // otherwise with the step shrunk to tau / ceil(tau / dt) (never larger than dt).
    const double steps = tau / dt;
    const bool on_grid = std::abs(steps - std::round(steps)) < 1e-9 * std::max(1.0, steps);
    const auto count = static_cast<std::int64_t>(on_grid ? std::llround(steps) : std::ceil(steps));
    const double step_dt = on_grid || count == 0 ? dt : tau / static_cast<double>(count);
    std::optional<Integrator> own_run;
    if (!on_grid)
      own_run.emplace(scene.chain, make_forcing(scene.drive), IntegratorOptions{step_dt, 1});
    Integrator& sim = on_grid ? grid_run : *own_run;
    if (!advance_watching(sim, count)) {
      if (g_interrupted) return interrupt_status();
      error = sim.error();
      return 1;
    }
    // auto / break zoom: a single picture has no camera history, so it settles at once.
    SnapshotStyle at_tau = style;
    ZoomCamera camera(parse_zoom(frame.zoom, scene.chain.beads, "--zoom"), scene.chain.beads,
                      extent.breaks.empty() ? 0 : extent.breaks.front().spring,
                      extent.breaks.empty() ? -1.0 : extent.breaks.front().tau);
    camera.frame(sim.state(), at_tau.zoom_first, at_tau.zoom_last, true);
    const RenderSnapshot snap = build_snapshot(sim.state(), scene.chain, sim.force_now(), at_tau);
    consume(tau, canvas.renderer->render(snap));
  }
  return 0;
}

int snapshot_command(const SnapshotOptions& o) {
  const SceneDesc scene = load_scene(o.scene, o.overrides);
  SnapshotRequest request;
  request.times = parse_times(o.at);
  request.at_text = o.at;
  request.frame = o.frame;
  request.overlay = o.overlay;
  request.stop = &g_interrupted;
  require_distinct_names(scene.name, request.times);
  require_writable_dir(o.out_dir);
  // One snapshot of this scene into this folder at a time (issue #12, row 9): two would
  // write the same names, each renaming its PNG over the other's.
  const OutputLock lock((std::filesystem::path(o.out_dir) / (scene.name + "_tau")).string());
  std::string error;
  std::size_t written = 0;
  const int status = snapshot_images(
      scene, request,
      [&](double tau, Image&& image) {
        const std::string path =
            (std::filesystem::path(o.out_dir) / snapshot_name(scene.name, tau)).string();
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
