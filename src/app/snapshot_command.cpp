// `chainbreak snapshot`: PNG frames of a scene at exact times.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>

#include "app/commands.h"
#include "app/frame_source.h"
#include "app/frames.h"
#include "app/render_plan.h"
#include "app/snapshot_images.h"
#include "output/frame_writer.h"
#include "output/png_writer.h"
#include "overlay/overlay.h"
#include "physics/integrator.h"

namespace cb {

namespace {

std::vector<double> parse_times(const std::string& text) {
  std::vector<double> out;
  std::size_t start = 0;
  while (start <= text.size()) {
    const auto end = std::min(text.find(',', start), text.size());
    const std::string part = text.substr(start, end - start);
    char* stop = nullptr;
    const double t = std::strtod(part.c_str(), &stop);
    if (part.empty() || *stop != '\0' || !(t >= 0.0) || !std::isfinite(t))
      throw SceneError("--at " + text +
                       ": expected times tau >= 0 separated by commas, e.g. --at 0,30,60.5");
    out.push_back(t);
    start = end + 1;
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
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
  for (double tau : times) {
    const double k = tau / plan.tau_per_frame;
    const auto frame = static_cast<std::int64_t>(std::llround(k));
    if (std::abs(k - static_cast<double>(frame)) > kFrameSlack)
      throw SceneError(
          "--at " + o.at_text + ": with --overlay each tau must be a frame time of the " +
          "video, a multiple of speed / fps = " + number(plan.tau_per_frame) + "; nearest to " +
          number(tau) + ": " + number(std::floor(k) * plan.tau_per_frame) + " or " +
          number(std::ceil(k) * plan.tau_per_frame) +
          " (or change the frame times with --set render.fps=... / render.speed=...)");
    if (frame >= plan.frames)
      throw SceneError("--at " + o.at_text + ": tau " + number(tau) +
                       " is past the video's last frame (tau " +
                       number(static_cast<double>(plan.frames - 1) * plan.tau_per_frame) +
                       "; see integrator.t_end and after_break)");
    frames.push_back(frame);
  }
  Canvas canvas = make_canvas(o.frame, plan.frame.width, plan.frame.height);
  Overlay overlay(plan.frame.width, plan.frame.height, plan.frame.fps, plan.overlay);
  FrameSource source(scene, plan, 1);
  for (std::size_t i = 0; i < times.size(); ++i) {
    if (o.stop && *o.stop) return 130;
    const std::optional<RenderSnapshot> snap = source.frame(frames[i]);
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

int snapshot_images(const SceneDesc& scene, const SnapshotRequest& o,
                    const SnapshotConsumer& consume, std::string& error) {
  // Themes: the one place a requested theme reaches the pictures. Until the theme option
  // of SnapshotStyle lands, the chain is drawn in its built-in dark theme only.
  if (!o.theme.empty() && o.theme != "dark")
    throw SceneError("theme " + o.theme +
                     ": this build draws snapshots in the dark theme only; use theme=\"dark\"");
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
    if (o.stop && *o.stop) return 130;
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
      error = sim.error();
      return 1;
    }
    const RenderSnapshot snap = build_snapshot(sim.state(), scene.chain, sim.force_now(), style);
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
  std::string error;
  const int status = snapshot_images(
      scene, request,
      [&](double tau, Image&& image) {
        const std::string path =
            (std::filesystem::path(o.out_dir) / snapshot_name(scene.name, tau)).string();
        write_png(path, image);
        std::printf("%s\n", path.c_str());
      },
      error);
  if (status == 1) std::fprintf(stderr, "chainbreak: %s\n", error.c_str());
  return status;
}

}  // namespace cb
