#include "app/render_plan.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "app/csv.h"
#include "output/output_file.h"
#include "output/video_encoder.h"

namespace cb {

namespace fs = std::filesystem;

namespace {

// FNV-1a over the scene file and the overrides: which inputs made this video.
std::string scene_hash(const SceneDesc& scene, const std::vector<Override>& overrides) {
  std::ifstream in(scene.path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  for (const auto& o : overrides) text << '\n' << o.key << '=' << o.value;
  std::uint64_t h = 1469598103934665603ull;
  for (unsigned char c : text.str()) h = (h ^ c) * 1099511628211ull;
  char buf[20];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
  return buf;
}

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
  // Frame k shows tau = k * speed / fps, reached in a whole number of integrator steps: the
  // step is shrunk (never grown) so that every frame lands exactly on its time.
  p.tau_per_frame = p.frame.speed / p.frame.fps;
  p.substeps = std::max<std::int64_t>(
      1, static_cast<std::int64_t>(std::ceil(p.tau_per_frame / scene.integrator.dt - 1e-9)));
  p.dt = p.tau_per_frame / static_cast<double>(p.substeps);
  p.overlay = overlay_switches(p.frame, o);
  p.overlay_layout = overlay_layout(p.frame.width, p.frame.height, p.overlay);
  p.scene_hash = scene_hash(scene, o.overrides);
  return p;
}

void measure_plan(const SceneDesc& scene, RenderPlan& p) {
  // With the overlay the pre-pass also samples, at the frame times, the plots' extremes.
  p.extent =
      measure_run(scene, scene.integrator.t_end, p.dt, p.overlay_layout.enabled ? p.substeps : 0);
  p.frames = static_cast<std::int64_t>(std::floor(p.extent.tau_stop / p.tau_per_frame + 1e-9)) + 1;
  p.style = snapshot_style(scene, p.frame, p.extent);
  if (p.overlay_layout.enabled) {
    p.style.chain_height = p.overlay_layout.chain_height;  // the plots take the rest
    OverlaySetup& s = p.overlay_setup;
    s.title = scene.title;
    s.omega0 = scene.units ? scene.units->omega0() : 0.0;
    s.tau_per_frame = p.tau_per_frame;
    s.tau_end = static_cast<double>(p.frames - 1) * p.tau_per_frame;
    s.phi_min = p.extent.phi_min;
    s.phi_max = p.extent.phi_max;
    s.energy_max = p.extent.energy_max;
    s.strain_scale = p.style.threshold > 0 ? p.style.threshold : p.style.strain_range;
  }
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
       ",\"dt_used\":" + number_text(p.dt) + ",\"t_end\":" + number_text(scene.integrator.t_end) +
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
  j += ",\"frames\":" + std::to_string(p.frames) + ",\"fps\":" + number_text(p.frame.fps);
  j += ",\"duration\":" + number_text(static_cast<double>(p.frames) / p.frame.fps);
  j += ",\"tau_per_second\":" + number_text(p.frame.speed) +
       ",\"tau_end\":" + number_text(static_cast<double>(p.frames - 1) * p.tau_per_frame);
  if (!gl.empty()) j += ",\"gl\":" + json_string(gl);
  j += ",\"breaks\":[";
  for (std::size_t i = 0; i < breaks.size(); ++i) {
    // The first frame that shows the break.
    const auto frame = static_cast<std::int64_t>(std::ceil(breaks[i].tau / p.tau_per_frame - 1e-9));
    j += (i ? "," : "") + std::string("{\"spring\":") + std::to_string(breaks[i].spring) +
         ",\"tau\":" + number_text(breaks[i].tau) + ",\"frame\":" + std::to_string(frame) + "}";
  }
  return j + "]}";
}

std::string sidecar_path(const SceneDesc& scene, const RenderPlan& p) {
  return (p.codec == "png" ? fs::path(p.output) / (scene.name + ".json")
                           : fs::path(p.output).replace_extension(".json"))
      .string();
}

void write_sidecar(const SceneDesc& scene, const RenderPlan& p, const std::string& gl,
                   const std::vector<BreakEvent>& breaks) {
  OutputFile out(sidecar_path(scene, p));
  out.write(plan_json(scene, p, gl, breaks) + "\n");
  out.commit();
}

}  // namespace cb
