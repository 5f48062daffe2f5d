#include "app/render_plan.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "app/csv.h"
#include "app/json_text.h"
#include "output/output_file.h"
#include "output/video_encoder.h"
#include "physics/simd.h"
#include "resources/resources.h"
#include "scene/scene_hash.h"

namespace cb {

namespace fs = std::filesystem;

namespace {

Json drive_json(const DriveDesc& d) {
  Json j = {{"type", drive_type_name(d.type)}, {"t0", d.t0}};
  switch (d.type) {
    case DriveType::Step:
      j["amplitude"] = d.amplitude;
      break;
    case DriveType::Ramp:
      j["beta"] = d.beta;
      break;
    case DriveType::Sine:
      j["amplitude"] = d.amplitude;
      j["period"] = d.period;
      break;
    case DriveType::Impulses:
      j["times"] = d.times;
      j["strengths"] = d.strengths;
      break;
    case DriveType::Table:
      j["file"] = d.table_file;
      break;
    case DriveType::Expr:
      j["expr"] = d.expr;
      break;
  }
  return j;
}

// The scene's [render] overlay switches, then the command line's.
OverlaySwitches overlay_switches(const RenderDesc& r, const RenderOptions& o) {
  OverlaySwitches s{r.overlay_hud, r.overlay_plots, r.overlay_spacetime, r.overlay_modes};
  if (!r.overlay) s = OverlaySwitches{false, false, false, false};
  if (!o.overlay.empty()) {
    std::string bad;
    if (!parse_overlay_switches(o.overlay, s, bad))
      throw SceneError("--overlay " + o.overlay + ": unknown part '" + bad +
                       "'; expected a comma-separated list of hud, plots, spacetime, modes " +
                       "(or all, none), e.g. --overlay hud,plots");
  }
  if (o.no_overlay) s = OverlaySwitches{false, false, false, false};
  return s;
}

// Counted in double before any integer holds them (issue #12, rows 5 and 6: --speed 1e-300
// made the frame count overflow; --speed 1e-6 planned billions of frames and hung in the
// pre-pass). The frames of the whole run (an after_break stop can only shorten it), and the
// integrator steps of one frame, which must fit the step counter.
// A count or a rate in 4 digits: the estimates above are not exact to the last frame.
std::string approx(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g", v);
  return buf;
}

// Counted in double before any integer holds them (at the normal pace: slow motion adds a
// few windows' worth).
void require_frame_budget(const SceneDesc& scene, const RenderPlan& p, double tau_per_frame) {
  const double t_end = scene.integrator.t_end;
  const double frames = std::floor(t_end / tau_per_frame + 1e-9) + 1;
  if (!(frames <= kMaxFrames))
    throw SceneError("render: " + approx(frames) + " frames (t_end = " + approx(t_end) + " at " +
                     approx(tau_per_frame) + " tau a frame: speed " + approx(p.frame.speed) +
                     " / fps " + approx(p.frame.fps) + ") is more than the limit of " +
                     approx(kMaxFrames) + " frames; raise --speed (e.g. --speed " +
                     approx(std::ceil(t_end * p.frame.fps / kMaxFrames * 10)) +
                     "), lower --fps, or shorten integrator.t_end");
  const double substeps = tau_per_frame / scene.integrator.dt;
  if (!(substeps * frames <= kMaxRunSteps))
    throw SceneError("render: " + approx(std::ceil(substeps)) +
                     " integrator steps a frame (speed " + approx(p.frame.speed) + " / fps " +
                     approx(p.frame.fps) + " / dt " + approx(scene.integrator.dt) +
                     ") is more than the limit of " + approx(kMaxRunSteps) +
                     " steps in all; lower --speed");
}

}  // namespace

RenderPlan plan_render(const SceneDesc& scene, const RenderOptions& o) {
  RenderPlan p;
  p.frame = frame_settings(scene, o.frame);
  if (o.fps > 0) p.frame.fps = o.fps;
  if (o.speed > 0) p.frame.speed = o.speed;
  if (!o.frames_dir.empty()) {
    p.output = o.frames_dir;
    p.codec = "png";
  } else {
    p.output = o.output.empty() ? (fs::path("renders") / (scene.name + ".mp4")).string() : o.output;
    p.codec = video_codec_name(p.output);  // throws for an unsupported extension
    if (p.frame.fps != std::floor(p.frame.fps))
      throw SceneError("fps " + number_text(p.frame.fps) +
                       ": videos need a whole number of frames per second (e.g. --fps 30)");
  }
  // Frames every speed / fps of tau (slower around breaks with slow motion), each reached in
  // a whole number of integrator steps: the step is shrunk (never grown) so that every frame
  // lands exactly on its time (frame_grid.h).
  SlowMotion slow{p.frame.slowmo, p.frame.slowmo_window};
  if (o.slowmo >= 0) slow.factor = o.slowmo;
  if (o.slowmo_window > 0) slow.window = o.slowmo_window;
  if (!(slow.factor > 0.0 && slow.factor <= 1.0))
    throw SceneError(
        "--slowmo " + number_text(slow.factor) +
        ": expected a factor between 0 and 1, e.g. --slowmo 0.1 (a tenth of the speed)");
  p.frame.slowmo = slow.factor;
  p.frame.slowmo_window = slow.window;
  require_frame_budget(scene, p, p.frame.speed / p.frame.fps);
  p.grid = FrameGrid(p.frame.speed / p.frame.fps, scene.integrator.dt, slow);
  if (o.title_card >= 0) p.frame.title_card = o.title_card;
  p.overlay = overlay_switches(p.frame, o);
  p.overlay_layout = overlay_layout(p.frame.width, p.frame.height, p.overlay);
  p.scene_hash = scene_hash(scene.path, o.overrides);
  return p;
}

void measure_plan(const SceneDesc& scene, RenderPlan& p) {
  // With the overlay the pre-pass also samples, at the frame times, the plots' extremes.
  p.extent =
      measure_run(scene, scene.integrator.t_end, p.grid.dt(),
                  p.overlay_layout.enabled ? p.grid.substeps() : 0, p.grid.slow_motion().on());
  std::vector<double> breaks;
  for (const BreakEvent& b : p.extent.breaks) breaks.push_back(b.tau);
  p.grid.lay_out(p.extent.tau_stop, breaks);
  p.style = snapshot_style(scene, p.frame, p.extent);
  if (p.overlay_layout.enabled) {
    p.style.chain_height = p.overlay_layout.chain_height;  // the plots take the rest
    OverlaySetup& s = p.overlay_setup;
    s.title = scene.title;
    s.omega0 = scene.units ? scene.units->omega0() : 0.0;
    s.tau_per_frame = p.grid.tau_per_frame();
    s.tau_end = p.grid.tau(p.grid.frames() - 1);
    s.phi_min = p.extent.phi_min;
    s.phi_max = p.extent.phi_max;
    s.energy_max = p.extent.energy_max;
    s.strain_scale = p.style.threshold > 0 ? p.style.threshold : p.style.strain_range;
  }
}

Json plan_json(const SceneDesc& scene, const RenderPlan& p, const std::string& gl,
               const std::vector<BreakEvent>& breaks) {
  const ChainParams& c = scene.chain;
  Json j = {{"title", scene.title}, {"scene", scene.path}, {"scene_hash", p.scene_hash}};
  j["chain"] = {{"beads", c.beads},
                {"gamma", c.gamma},
                {"threshold", c.breakable() ? Json(c.threshold) : Json(nullptr)},
                {"break_on", c.break_on == BreakMode::Abs ? "abs" : "stretch"},
                {"pull_string", c.pull_string}};
  j["drive"] = drive_json(scene.drive);
  const auto& after = scene.integrator.after_break;
  j["integrator"] = {{"dt", scene.integrator.dt},
                     {"dt_used", p.grid.dt()},
                     {"t_end", scene.integrator.t_end},
                     {"after_break", after ? Json(*after) : Json(nullptr)}};
  j["output"] = p.output;
  j["codec"] = p.codec;
  j["width"] = p.frame.width;
  j["height"] = p.frame.height;
  j["view"] = p.frame.view;
  j["overlay"] = p.overlay_layout.enabled ? overlay_switches_text(p.overlay) : "none";
  const std::int64_t frames = p.title_frames + p.grid.frames();
  j["frames"] = frames;
  j["fps"] = p.frame.fps;
  j["duration"] = static_cast<double>(frames) / p.frame.fps;
  j["title_card_frames"] = p.title_frames;
  j["tau_per_second"] = p.frame.speed;
  j["tau_end"] = p.grid.tau(p.grid.frames() - 1);
  j["slowmo"] = p.grid.slow_motion().on() ? Json{{"factor", p.grid.slow_motion().factor},
                                                 {"window", p.grid.slow_motion().window}}
                                          : Json(nullptr);
  if (!gl.empty()) j["gl"] = gl;
  j["simd"] = simd_name(active_simd());  // the path the frames ran on
  j["breaks"] = breaks_json(p, breaks);
  // Every video frame's tau: the title card's frames show the chain at rest (tau 0).
  std::vector<double> taus(static_cast<std::size_t>(p.title_frames), 0.0);
  const std::vector<double> grid = p.grid.taus();
  taus.insert(taus.end(), grid.begin(), grid.end());
  j["frame_tau"] = taus;
  return j;
}

Json breaks_json(const RenderPlan& p, const std::vector<BreakEvent>& breaks) {
  Json j = Json::array();
  for (const BreakEvent& b : breaks) {
    // The first frame that shows the break.
    const std::int64_t frame = p.title_frames + p.grid.first_frame_at_or_after(b.tau);
    j.push_back({{"spring", b.spring}, {"tau", b.tau}, {"frame", frame}});
  }
  return j;
}

std::string sidecar_path(const SceneDesc& scene, const RenderPlan& p) {
  return (p.codec == "png" ? fs::path(p.output) / (scene.name + ".json")
                           : fs::path(p.output).replace_extension(".json"))
      .string();
}

}  // namespace cb
