#include "web/web_session.h"

#include <algorithm>
#include <cmath>

#include "figures/break_maps.h"
#include "physics/run_loop.h"
#include "web/web_plots.h"

namespace cb {

namespace {

// The layout's pre-pass runs the physics to the first break (app/frames.h, measure_run). A
// long chain's whole run would hold the page for seconds: past this many bead-steps the
// pre-pass stops early and the chain may leave the frame late in the run.
constexpr double kPrePassBeadSteps = 3e8;

// The breaking map: this many exact first breaks, for chains up to this long.
constexpr int kMapSamples = 60;
constexpr int kMapMaxBeads = 100;
constexpr double kMapMaxZetaPerBead = 12.0;  // the paper's Fig. 4 spans zeta_c < 8N

}  // namespace

void WebSession::load(const std::string& text, const std::string& path,
                      std::vector<Override> overrides) {
  replace(parse_scene(text, path, overrides), text, path, std::move(overrides));
}

void WebSession::set(const std::string& key, const std::string& value) {
  std::vector<Override> o = overrides_;
  const auto same =
      std::find_if(o.begin(), o.end(), [&](const Override& x) { return x.key == key; });
  if (same != o.end())
    same->value = value;
  else
    o.push_back({key, value});
  // parse_override checks the key's form as the command line does ("--set" without '=').
  parse_override(key + "=" + value);
  replace(parse_scene(text_, path_, o), text_, path_, std::move(o));
}

void WebSession::replace(SceneDesc scene, std::string text, std::string path,
                         std::vector<Override> o) {
  // Everything that can throw happens before anything is replaced.
  const double dt = scene.integrator.dt;
  double tau_stop = scene.integrator.t_end;
  const double bead_steps = static_cast<double>(scene.chain.beads) * (tau_stop / dt);
  if (bead_steps > kPrePassBeadSteps) tau_stop *= kPrePassBeadSteps / bead_steps;
  // The plots' frames: at most kMaxHistory of them over the run, on the step grid.
  const std::int64_t frame_steps = std::max<std::int64_t>(
      1, static_cast<std::int64_t>(
             std::ceil(static_cast<double>(planned_steps(scene)) / kMaxHistory)));
  RunExtent extent = measure_run(scene, tau_stop, dt, frame_steps);
  OverlaySetup setup;
  setup.title = scene.title;
  setup.omega0 = scene.units ? scene.units->omega0() : 0.0;
  setup.tau_per_frame = static_cast<double>(frame_steps) * dt;
  setup.tau_end = std::max(setup.tau_per_frame, extent.tau_stop);
  setup.phi_min = extent.phi_min;
  setup.phi_max = extent.phi_max;
  setup.energy_max = extent.energy_max;
  setup.strain_scale = scene.chain.breakable() ? scene.chain.threshold : extent.strain_range;
  setup.exact = scene.chain.beads <= kExactMaxBeads;
#if defined(CHAINBREAK_NO_LAPACK)
  setup.exact = setup.exact && scene.chain.uniform_dynamics();  // unequal: LAPACK's modes
#endif
  auto sim = std::make_unique<Integrator>(scene.chain, make_forcing(scene.drive),
                                          IntegratorOptions{dt, 1});
  scene_ = std::move(scene);
  text_ = std::move(text);
  path_ = std::move(path);
  overrides_ = std::move(o);
  extent_ = std::move(extent);
  sim_ = std::move(sim);
  frame_steps_ = frame_steps;
  break_map_.reset();
  setup_ = setup;
  error_.clear();
  start_history();
}

void WebSession::start_history() {
  // A chain whose plots need what the page lacks (an unequal chain's modes need LAPACK) is
  // shown and run without them.
  try {
    history_ = std::make_unique<OverlayHistory>(scene_.chain, scene_.drive, setup_);
    history_->record(0, sim_->state(), sim_->force_now());
  } catch (const std::exception&) {
    history_.reset();
  }
}

void WebSession::restart() {
  sim_ = std::make_unique<Integrator>(scene_.chain, make_forcing(scene_.drive),
                                      IntegratorOptions{scene_.integrator.dt, 1});
  error_.clear();
  start_history();
}

std::int64_t WebSession::last_step() const {
  std::int64_t last = planned_steps(scene_);
  const ChainState& s = sim_->state();
  if (!s.breaks.empty() && scene_.integrator.after_break)
    last = std::min(last, after_break_step(s.breaks.front().tau, *scene_.integrator.after_break,
                                           scene_.integrator.dt));
  return last;
}

std::int64_t WebSession::step_at(double tau) const {
  // Clamped before the conversion: a tau past the run (or not a number) means its end.
  const double step = std::ceil(tau / scene_.integrator.dt - 1e-9);
  const auto last = planned_steps(scene_);
  if (!(step < static_cast<double>(last))) return last;
  return step > 0 ? static_cast<std::int64_t>(step) : 0;
}

bool WebSession::advance_to(std::int64_t step) {
  if (!error_.empty()) return false;
  // `run`'s own stop rule (t_end, after_break past the first break), capped at `step`.
  const StopRule stop{std::min(step, planned_steps(scene_)), scene_.integrator.after_break, false,
                      nullptr};
  std::vector<Observer> observers;
  if (history_)
    observers.push_back({frame_steps_, false, [this](const Integrator& s) {
                           history_->record(s.state().step / frame_steps_, s.state(),
                                            s.force_now());
                         }});
  if (run_until(*sim_, stop, observers) == RunEnd::Failed) {
    error_ = sim_->error();
    return false;
  }
  return true;
}

const WebBreakMap& WebSession::break_map() const {
  if (break_map_) return *break_map_;
  WebBreakMap map;
  const ChainParams& c = scene_.chain;
  // The map is the paper's for a ramp on the uniform chain (equal beads, springs and
  // thresholds; linear springs; no weight) under the abs rule, drawn for no other chain; a
  // long chain's exact first breaks would hold the page too long.
  if (scene_.drive.type == DriveType::Ramp && c.breakable() && c.uniform_thresholds() &&
      c.uniform_dynamics() && !c.anharmonic() && !c.hanging() && c.break_on == BreakMode::Abs &&
      !c.pull_string && c.beads <= kMapMaxBeads && scene_.drive.beta > 0) {
    map.beads = c.beads;
    map.current = c.threshold / scene_.drive.beta;
    // At most kMapMaxZetaPerBead N: an exact first break searches up to tau = 4 zeta_c + 8N,
    // so a threshold of 1e9 would hold the page for hours; a current zeta_c off the map is
    // simply not marked.
    const double hi =
        std::min(std::max(1.5 * map.current, 6.0 * c.beads), kMapMaxZetaPerBead * c.beads);
    for (int i = 1; i <= kMapSamples; ++i) {
      const double zeta = hi * i / kMapSamples;
      const FirstBreak b = ramp_first_break(c.beads, c.gamma, zeta);
      map.zeta.push_back(zeta);
      map.spring.push_back(b.broke ? b.spring : -1);
    }
  }
  break_map_ = std::move(map);
  return *break_map_;
}

RenderSnapshot WebSession::snapshot(int width, int height, const std::string& theme,
                                    const std::string& view, bool plots) const {
  FrameOptions o;
  o.size = std::to_string(width) + "x" + std::to_string(height);
  o.theme = theme;
  o.view = view;
  SnapshotStyle style = snapshot_style(scene_, frame_settings(scene_, o), extent_);
  const OverlayLayout layout = overlay_layout(width, height, web_plot_switches());
  plots = plots && layout.enabled && history_;
  if (plots) style.chain_height = layout.chain_height;
  RenderSnapshot snap = build_snapshot(sim_->state(), scene_.chain, sim_->force_now(), style);
  if (plots)
    snap.layers.push_back(web_plot_layer(history_->data(), break_map(), layout, style.theme));
  return snap;
}

}  // namespace cb
