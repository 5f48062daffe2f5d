#include "app/render_plan.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "app/csv.h"
#include "output/output_file.h"
#include "output/video_encoder.h"
#include "scene/scene_hash.h"
#include "physics/simd.h"
#include "resources/resources.h"

namespace cb {

namespace fs = std::filesystem;

namespace {

std::string numbers_json(const std::vector<double>& values) {
  std::string out = "[";
  for (double v : values) out += (out.size() > 1 ? "," : "") + number_text(v);
  return out + "]";
}

std::string drive_json(const DriveDesc& d) {
  std::string j =
      "{\"type\":" + json_string(drive_type_name(d.type)) + ",\"t0\":" + number_text(d.t0);
  switch (d.type) {
    case DriveType::Step:
      j += ",\"amplitude\":" + number_text(d.amplitude);
      break;
    case DriveType::Ramp:
      j += ",\"beta\":" + number_text(d.beta);
      break;
    case DriveType::Sine:
      j += ",\"amplitude\":" + number_text(d.amplitude) + ",\"period\":" + number_text(d.period);
      break;
    case DriveType::Impulses:
      j += ",\"times\":" + numbers_json(d.times) + ",\"strengths\":" + numbers_json(d.strengths);
      break;
    case DriveType::Table:
      j += ",\"file\":" + json_string(d.table_file);
      break;
    case DriveType::Expr:
      j += ",\"expr\":" + json_string(d.expr);
      break;
  }
  return j + "}";
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
    throw SceneError("--slowmo " + number_text(slow.factor) +
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
  p.extent = measure_run(scene, scene.integrator.t_end, p.grid.dt(),
                         p.overlay_layout.enabled ? p.grid.substeps() : 0,
                         p.grid.slow_motion().on());
  std::vector<double> breaks;
  for (const BreakEvent& b : p.extent.breaks) breaks.push_back(b.tau);
  p.grid.lay_out(p.extent.tau_stop, breaks);
  lay_out_frame(scene, p, p.frame.width, p.frame.height);
  if (p.overlay_layout.enabled) {
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

void lay_out_frame(const SceneDesc& scene, RenderPlan& p, int width, int height) {
  p.frame.width = width;
  p.frame.height = height;
  p.overlay_layout = overlay_layout(width, height, p.overlay);
  p.style = snapshot_style(scene, p.frame, p.extent);
  if (p.overlay_layout.enabled)
    p.style.chain_height = p.overlay_layout.chain_height;  // the plots take the rest
}

std::string plan_json(const SceneDesc& scene, const RenderPlan& p, const std::string& gl,
                      const std::vector<BreakEvent>& breaks) {
  const ChainParams& c = scene.chain;
  std::string j =
      "{\"title\":" + json_string(scene.title) + ",\"scene\":" + json_string(scene.path);
  j += ",\"scene_hash\":" + json_string(p.scene_hash);
  j += ",\"chain\":{\"beads\":" + std::to_string(c.beads) + ",\"gamma\":" + number_text(c.gamma) +
       ",\"threshold\":" + (c.breakable() ? number_text(c.threshold) : std::string("null")) +
       ",\"break_on\":" + json_string(c.break_on == BreakMode::Abs ? "abs" : "stretch") +
       ",\"pull_string\":" + (c.pull_string ? "true" : "false") + "}";
  j += ",\"drive\":" + drive_json(scene.drive);
  j += ",\"integrator\":{\"dt\":" + number_text(scene.integrator.dt) +
       ",\"dt_used\":" + number_text(p.grid.dt()) + ",\"t_end\":" + number_text(scene.integrator.t_end) +
       ",\"after_break\":" +
       (scene.integrator.after_break ? number_text(*scene.integrator.after_break)
                                     : std::string("null")) +
       "}";
  j += ",\"output\":" + json_string(p.output) + ",\"codec\":" + json_string(p.codec);
  j += ",\"width\":" + std::to_string(p.frame.width) +
       ",\"height\":" + std::to_string(p.frame.height);
  j += ",\"view\":" + json_string(p.frame.view);
  j += ",\"overlay\":" +
       json_string(p.overlay_layout.enabled ? overlay_switches_text(p.overlay) : "none");
  const std::int64_t frames = p.title_frames + p.grid.frames();
  j += ",\"frames\":" + std::to_string(frames) + ",\"fps\":" + number_text(p.frame.fps);
  j += ",\"duration\":" + number_text(static_cast<double>(frames) / p.frame.fps);
  j += ",\"title_card_frames\":" + std::to_string(p.title_frames);
  j += ",\"tau_per_second\":" + number_text(p.frame.speed) +
       ",\"tau_end\":" + number_text(p.grid.tau(p.grid.frames() - 1));
  j += ",\"slowmo\":" +
       (p.grid.slow_motion().on()
            ? "{\"factor\":" + number_text(p.grid.slow_motion().factor) +
                  ",\"window\":" + number_text(p.grid.slow_motion().window) + "}"
            : std::string("null"));
  if (!gl.empty()) j += ",\"gl\":" + json_string(gl);
  j += ",\"simd\":" + json_string(simd_name(active_simd()));  // the path the frames ran on
  j += ",\"breaks\":" + breaks_json(p, breaks);
  // Every video frame's tau: the title card's frames show the chain at rest (tau 0).
  std::vector<double> taus(static_cast<std::size_t>(p.title_frames), 0.0);
  const std::vector<double> grid = p.grid.taus();
  taus.insert(taus.end(), grid.begin(), grid.end());
  j += ",\"frame_tau\":" + numbers_json(taus);
  return j + "}";
}

std::string breaks_json(const RenderPlan& p, const std::vector<BreakEvent>& breaks) {
  std::string j = "[";
  for (std::size_t i = 0; i < breaks.size(); ++i) {
    // The first frame that shows the break.
    const std::int64_t frame = p.title_frames + p.grid.first_frame_at_or_after(breaks[i].tau);
    j += (i ? "," : "") + std::string("{\"spring\":") + std::to_string(breaks[i].spring) +
         ",\"tau\":" + number_text(breaks[i].tau) + ",\"frame\":" + std::to_string(frame) + "}";
  }
  return j + "]";
}

std::string sidecar_path(const SceneDesc& scene, const RenderPlan& p) {
  return (p.codec == "png" ? fs::path(p.output) / (scene.name + ".json")
                           : fs::path(p.output).replace_extension(".json"))
      .string();
}

}  // namespace cb
