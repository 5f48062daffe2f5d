#include "app/frames.h"
#include "app/zoom.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <tuple>

#include "app/option_parsers.h"
#include "interrupt/interrupt.h"
#include "overlay/overlay_history.h"
#include "physics/energy.h"
#include "physics/integrator.h"
#include "physics/run_loop.h"

namespace cb {

namespace {

struct Preset {
  const char* name;
  int width, height;
  double fps;
};
// As lecturers know them from Manim: low, medium, high, 4k.
constexpr Preset kPresets[] = {
    {"l", 854, 480, 15}, {"m", 1280, 720, 30}, {"h", 1920, 1080, 60}, {"k", 3840, 2160, 60}};

}  // namespace

RenderDesc frame_settings(const SceneDesc& scene, const FrameOptions& o) {
  RenderDesc d = scene.render;
  if (!o.quality.empty()) {
    const Preset* found = nullptr;
    for (const Preset& p : kPresets)
      if (o.quality == p.name) found = &p;
    if (!found)
      throw SceneError("-q " + o.quality + ": expected l (854x480@15), m (1280x720@30), " +
                       "h (1920x1080@60) or k (3840x2160@60)");
    d.width = found->width;
    d.height = found->height;
    d.fps = found->fps;
  }
  if (!o.size.empty()) std::tie(d.width, d.height) = parse_size(o.size);
  if (!o.view.empty()) {
    View v;
    if (!parse_view(o.view, v))
      throw SceneError("--view " + o.view + ": expected longitudinal, transverse, both or vertical");
    d.view = o.view;
  }
  if (!o.theme.empty()) {
    if (!parse_theme(o.theme)) throw SceneError("--theme " + o.theme + ": expected dark or light");
    d.theme = o.theme;
  }
  if (!o.zoom.empty()) d.zoom = o.zoom;
  if (!o.caption.empty()) d.caption = o.caption;
  parse_zoom(d.zoom, scene.chain.beads, o.zoom.empty() ? "render.zoom =" : "--zoom");
  return d;
}

namespace {

// The overlay's extremes at one sample: phi of the plotted springs and the energy.
void sample_overlay(const ChainState& state, const ChainParams& params, RunExtent& e) {
  int springs[kPlottedSprings];
  const int count = plotted_springs(params.beads, springs);
  for (int s = 0; s < count; ++s) {
    if (!spring_intact(state, springs[s])) continue;
    const double phi = extension(state, springs[s]);
    e.phi_min = std::min(e.phi_min, phi);
    e.phi_max = std::max(e.phi_max, phi);
  }
  e.energy_max = std::max(e.energy_max, per_particle(energy(state, params).total(), params.beads));
}

}  // namespace

RunExtent measure_run(const SceneDesc& scene, double tau_stop, double dt,
                      std::int64_t sample_every, bool every_break) {
  Integrator sim(scene.chain, make_forcing(scene.drive), {dt, 1});
  RunExtent e;
  e.tau_stop = tau_stop;
  double psi = 0.0, force = 0.0, strain = 0.0;
  const auto last = static_cast<std::int64_t>(std::llround(tau_stop / dt));
  // Nothing is measured after the first break, so the pre-pass ends there.
  const StopRule stop{last, std::nullopt, true, &g_interrupted};
  const Observer watch{
      1, false, [&](const Integrator& s) {
        if (sample_every > 0 && s.state().breaks.empty() && s.state().step % sample_every == 0)
          sample_overlay(s.state(), scene.chain, e);
        const auto& x = s.state().psi;
        for (std::size_t i = 0; i < x.size(); ++i) {
          psi = std::max(psi, std::abs(x[i]));
          strain = std::max(strain, std::abs(x[i] - (i ? x[i - 1] : 0.0)));
        }
        force = std::max(force, std::abs(s.force_now()));
      }};
  const RunEnd end = run_until(sim, stop, {watch});
  if (end == RunEnd::Failed) throw std::runtime_error(sim.error());
  if (end == RunEnd::Cancelled) throw Interrupted();  // the pre-pass of a long run takes a while
  if (!sim.state().breaks.empty() && scene.integrator.after_break)
    e.tau_stop = std::min(tau_stop, sim.state().breaks.front().tau + *scene.integrator.after_break);
  if (every_break && !sim.state().breaks.empty()) {
    // Slow motion needs every break the video shows: on to where the video stops.
    const StopRule rest{static_cast<std::int64_t>(std::floor(e.tau_stop / dt + 1e-9)), std::nullopt,
                        false, &g_interrupted};
    const RunEnd rest_end = run_until(sim, rest);
    if (rest_end == RunEnd::Failed) throw std::runtime_error(sim.error());
    if (rest_end == RunEnd::Cancelled) throw Interrupted();
  }
  for (const BreakEvent& b : sim.state().breaks)
    if (b.tau <= e.tau_stop) e.breaks.push_back(b);
  e.psi_range = std::max(psi, 1e-6);
  e.force_range = std::max(force, 1e-6);
  e.strain_range = std::max(strain, 1e-6);
  return e;
}

bool advance_watching(Integrator& sim, std::int64_t target_step) {
  const StopRule rule{target_step, std::nullopt, false, &g_interrupted};
  return run_until(sim, rule) == RunEnd::Reached;
}

SnapshotStyle snapshot_style(const SceneDesc& scene, const RenderDesc& frame,
                             const RunExtent& extent) {
  SnapshotStyle s;
  s.width = frame.width;
  s.height = frame.height;
  parse_view(frame.view, s.view);
  s.theme = parse_theme(frame.theme).value_or(ThemeName::Dark);
  s.caption = frame.caption;
  const ZoomSpec zoom = parse_zoom(frame.zoom, scene.chain.beads, "--zoom");
  if (zoom.mode == ZoomSpec::Mode::Fixed) {
    s.zoom_first = zoom.first;
    s.zoom_last = zoom.last;
  }
  s.psi_range = extent.psi_range;
  s.force_range = extent.force_range;
  // Springs with thresholds of their own are coloured by phi_j / phi_c,j; the legend's scale
  // and the zoom's window use the smallest (the uniform chain's phi_c).
  s.threshold = scene.chain.breakable() ? scene.chain.min_threshold() : 0.0;
  s.strain_range = scene.chain.breakable() ? scene.chain.min_threshold() : extent.strain_range;
  return s;
}

Canvas make_canvas(const FrameOptions& o, int width, int height) {
  Canvas c;
  c.context = create_gl_context(choose_gl_backend(o.gl));
  c.renderer = std::make_unique<Renderer>(width, height);
  return c;
}

}  // namespace cb
