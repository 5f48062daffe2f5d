#include "viewer/session.h"

#include "physics/run_loop.h"
#include "snapshot/snapshot.h"

namespace cb {

Session::Session(SceneDesc scene, RenderOptions options)
    : scene_(std::move(scene)), options_(std::move(options)) {
  restart();
}

Session::~Session() = default;

void Session::restart() {
  // The plan's frame grid follows the speed asked for now: a recording then plays at it.
  options_.speed = scene_.render.speed;
  // Everything that can throw (a bad setting, a drive that does not compile, a pre-pass that
  // blows up) happens before anything is replaced: a failed restart leaves the run as it was.
  RenderPlan plan = plan_render(scene_, options_);
  measure_plan(scene_, plan);
  auto sim = std::make_unique<Integrator>(scene_.chain, make_forcing(scene_.drive),
                                          IntegratorOptions{plan.grid.dt(), 1});
  plan_ = std::move(plan);
  sim_ = std::move(sim);
  history_.reset();
  if (plan_.overlay_layout.enabled)
    history_ = std::make_unique<OverlayHistory>(scene_.chain, scene_.drive, plan_.overlay_setup);
  phi_history_.reset(scene_.chain.beads, plan_.grid.tau_per_frame());
  frame_ = 0;
  error_.clear();
  record();
}

void Session::set_view(const std::string& view) {
  options_.frame.view = view;
  plan_.frame.view = view;
  // As measure_plan lays it out, without the pre-pass: the run's extent has not changed.
  lay_out_frame(scene_, plan_, plan_.frame.width, plan_.frame.height);
}

RenderPlan Session::plan_at(int width, int height) const {
  RenderPlan p = plan_;
  // The histories are kept only when the plan's own frame has the overlay (its axes come
  // from the pre-pass then): a picture larger than that frame gets none either.
  if (!history_) p.overlay = OverlaySwitches{false, false, false, false};
  lay_out_frame(scene_, p, width, height);
  return p;
}

void Session::advance(std::int64_t count) {
  for (std::int64_t i = 0; i < count && !at_end() && error_.empty(); ++i) {
    const StopRule next_frame{plan_.grid.step(frame_ + 1), std::nullopt, false, nullptr};
    if (run_until(*sim_, next_frame) == RunEnd::Failed) {
      error_ = sim_->error();
      return;
    }
    ++frame_;
    record();
  }
}

void Session::record() {
  if (history_) history_->record(frame_, sim_->state(), sim_->force_now());
  phi_history_.record(frame_, sim_->state());
}

RenderSnapshot Session::snapshot() const {
  return snapshot(plan_.style);
}

RenderSnapshot Session::snapshot(const SnapshotStyle& style) const {
  RenderSnapshot snap = build_snapshot(sim_->state(), scene_.chain, sim_->force_now(), style);
  if (history_) snap.overlay = history_->share();
  return snap;
}

}  // namespace cb
