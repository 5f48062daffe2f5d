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
#include "app/render_plan.h"
#include "output/frame_writer.h"
#include "output/png_writer.h"
#include "overlay/overlay.h"
#include "physics/integrator.h"

namespace cb {

namespace {

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
int overlay_snapshots(const SnapshotOptions& o, const SceneDesc& scene,
                      const std::vector<double>& times) {
  RenderOptions ro;
  ro.frames_dir = o.out_dir;  // PNGs: no video codec to check
  ro.frame = o.frame;
  ro.overlay = o.overlay;
  RenderPlan plan = plan_render(scene, ro);
  if (!plan.overlay_layout.enabled)
    throw SceneError("--overlay " + o.overlay + ": " +
                     (plan.overlay.any() ? "the frame is too small for the overlay (at least " +
                                               std::to_string(kOverlayMinWidth) + "x" +
                                               std::to_string(kOverlayMinHeight) + ")"
                                         : std::string("no part switched on")));
  require_writable_dir(o.out_dir);
  measure_plan(scene, plan);
  std::vector<std::int64_t> frames;
  for (double tau : times) {
    const double k = tau / plan.tau_per_frame;
    const auto frame = static_cast<std::int64_t>(std::llround(k));
    if (std::abs(k - static_cast<double>(frame)) > kFrameSlack)
      throw SceneError("--at " + o.at + ": with --overlay each tau must be a frame time of the " +
                       "video, a multiple of speed / fps = " + number(plan.tau_per_frame) +
                       "; nearest to " + number(tau) + ": " +
                       number(std::floor(k) * plan.tau_per_frame) + " or " +
                       number(std::ceil(k) * plan.tau_per_frame) +
                       " (or change the frame times with --set render.fps=... / render.speed=...)");
    if (frame >= plan.frames)
      throw SceneError("--at " + o.at + ": tau " + number(tau) +
                       " is past the video's last frame (tau " +
                       number(static_cast<double>(plan.frames - 1) * plan.tau_per_frame) +
                       "; see integrator.t_end and after_break)");
    frames.push_back(frame);
  }
  Canvas canvas = make_canvas(o.frame, plan.frame.width, plan.frame.height);
  Overlay overlay(plan.frame.width, plan.frame.height, plan.frame.fps, plan.overlay);
  FrameSource source(scene, plan, 1);
  for (std::size_t i = 0; i < times.size(); ++i) {
    if (g_interrupted) return 130;
    const std::optional<RenderSnapshot> snap = source.frame(frames[i]);
    if (!snap) {
      std::fprintf(stderr, "chainbreak: %s\n", source.error().c_str());
      return 1;
    }
    canvas.renderer->draw(*snap);
    overlay.draw(*snap);
    Image image;
    canvas.renderer->read(image);
    const std::string path =
        (std::filesystem::path(o.out_dir) / snapshot_name(scene.name, times[i])).string();
    write_png(path, image);
    std::printf("%s\n", path.c_str());
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

int snapshot_command(const SnapshotOptions& o) {
  const SceneDesc scene = load_scene(o.scene, o.overrides);
  const std::vector<double> times = parse_times(o.at);
  require_distinct_names(scene.name, times);
  if (!o.overlay.empty() && o.overlay != "none") return overlay_snapshots(o, scene, times);
  const RenderDesc frame = frame_settings(scene, o.frame);
  require_writable_dir(o.out_dir);
  const double dt = scene.integrator.dt;
  const RunExtent extent = measure_run(scene, times.back(), dt);
  const SnapshotStyle style = snapshot_style(scene, frame, extent);
  Canvas canvas = make_canvas(o.frame, frame.width, frame.height);

  // On-grid times (sorted) share one run; an off-grid time gets a run of its own.
  Integrator grid_run(scene.chain, make_forcing(scene.drive), {dt, 1});
  for (double tau : times) {
    if (g_interrupted) return 130;
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
    if (!sim.advance_to(count)) {
      std::fprintf(stderr, "chainbreak: %s\n", sim.error().c_str());
      return 1;
    }
    const RenderSnapshot snap = build_snapshot(sim.state(), scene.chain, sim.force_now(), style);
    const std::string path =
        (std::filesystem::path(o.out_dir) / snapshot_name(scene.name, tau)).string();
    write_png(path, canvas.renderer->render(snap));
    std::printf("%s\n", path.c_str());
  }
  return 0;
}

}  // namespace cb
