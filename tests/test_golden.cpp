// Golden frames: whole scenes rendered at 480x270 and compared with the PNGs in tests/golden/
// within a stated tolerance, on both backends. States come from the Integrator with the
// scenes' parameters (no app process), except N = 1e5, which uses the continuum solution.
// CHAINBREAK_UPDATE_GOLDENS=1 rewrites the goldens from OSMesa instead (tests/golden/README.md);
// the tolerance is golden_support.h's.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "drive/drive.h"
#include "gl/gl_context.h"
#include "gl_test_support.h"
#include "golden_support.h"
#include "output/image.h"
#include "output/png_writer.h"
#include "physics/integrator.h"
#include "render/renderer.h"
#include "scene/scene.h"
#include "snapshot/snapshot.h"

namespace {

using cb::test::check_golden;
constexpr int kWidth = 480, kHeight = 270;

// The ranges the app's measure_run (src/app/frames.cpp) finds for a run: largest |psi|,
// |f| and |phi| up to the first break, so the layout is the one `chainbreak snapshot` uses.
cb::SnapshotStyle measured_style(const cb::ChainParams& params, const cb::DriveDesc& drive,
                                 double tau_end, cb::View view,
                                 cb::ThemeName theme = cb::ThemeName::Dark) {
  cb::Integrator sim(params, cb::make_forcing(drive), {0.01, 1});
  double psi = 0.0, force = 0.0, strain = 0.0;
  bool ok = true;
  while (ok && sim.state().tau < tau_end - 1e-9 && sim.state().breaks.empty()) {
    ok = sim.step();
    const auto& x = sim.state().psi;
    for (std::size_t i = 0; i < x.size(); ++i) {
      psi = std::max(psi, std::abs(x[i]));
      strain = std::max(strain, std::abs(x[i] - (i ? x[i - 1] : 0.0)));
    }
    force = std::max(force, std::abs(sim.force_now()));
  }
  REQUIRE(ok);
  cb::SnapshotStyle style;
  style.width = kWidth;
  style.height = kHeight;
  style.view = view;
  style.theme = theme;
  style.psi_range = std::max(psi, 1e-6);
  style.force_range = std::max(force, 1e-6);
  style.threshold = params.breakable() ? params.threshold : 0.0;
  style.strain_range = params.breakable() ? params.threshold : std::max(strain, 1e-6);
  return style;
}

cb::ChainParams chain(int beads, double threshold, bool pull_string = false) {
  cb::ChainParams p;
  p.beads = beads;
  p.threshold = threshold;
  p.pull_string = pull_string;
  return p;
}

cb::DriveDesc drive(cb::DriveType type, double value) {
  cb::DriveDesc d;
  d.type = type;
  d.amplitude = value;
  d.beta = value;
  return d;
}

// Steps to `step` (or the first step past the first break plus `after` when after >= 0) and
// builds the frame there.
cb::RenderSnapshot frame_at(const cb::ChainParams& params, const cb::DriveDesc& d,
                            const cb::SnapshotStyle& style, std::int64_t step, double after = -1) {
  cb::Integrator sim(params, cb::make_forcing(d), {0.01, 1});
  if (after >= 0) {
    bool ok = true;
    while (ok && sim.state().breaks.empty() && sim.state().step < 100000) ok = sim.step();
    REQUIRE(ok);
    REQUIRE_FALSE(sim.state().breaks.empty());
    step = sim.state().step + std::llround(after / 0.01);
  }
  REQUIRE(sim.advance_to(step));
  return cb::build_snapshot(sim.state(), params, sim.force_now(), style);
}

// scenes/step_pulse.toml (N = 30, f = u(tau), unbreakable) at tau = 45, both views: the front
// reflected off the wall at tau = 30 runs back with extension 2 behind it.
cb::RenderSnapshot step_pulse_reflecting(cb::ThemeName theme = cb::ThemeName::Dark) {
  const auto params = chain(30, std::numeric_limits<double>::infinity());
  const auto d = drive(cb::DriveType::Step, 1.0);
  return frame_at(params, d, measured_style(params, d, 120.0, cb::View::Both, theme), 4500);
}

// scenes/anomalous_breaking.toml (N = 30, phi_c = 3, ramp 0.02) 0.5 after spring 30 breaks at
// tau ~ 150: the flash, the recoiling halves, the marker and its label.
cb::RenderSnapshot anomalous_just_broken(cb::ThemeName theme = cb::ThemeName::Dark) {
  const auto params = chain(30, 3.0);
  const auto d = drive(cb::DriveType::Ramp, 0.02);
  return frame_at(params, d, measured_style(params, d, 400.0, cb::View::Longitudinal, theme), 0,
                  0.5);
}

// scenes/ball_pull.toml (N = 1 with a pull string, phi_c = 1, ramp 0.1) at tau = 8, before
// either string breaks (~10.5): the ball, the string, the force arrow.
cb::RenderSnapshot ball_with_pull_string() {
  const auto params = chain(1, 1.0, true);
  const auto d = drive(cb::DriveType::Ramp, 0.1);
  return frame_at(params, d, measured_style(params, d, 30.0, cb::View::Longitudinal), 800);
}

// N = 1e5 after a step f = 1, both views, at tau = 1.5 N. No integrator: reaching the wall
// takes N time units (1e12 bead-steps). The continuum solution (Eq. (exactpsi), d'Alembert)
// instead: extension 1 behind the incoming front, 2 behind the front reflected at tau = N,
// i.e. phi_j = 2 for j <= tau - N, 1 beyond; psi_j = j + min(j, tau - N).
cb::RenderSnapshot ribbon_1e5() {
  const int n = 100000;
  const double tau = 1.5 * n;
  cb::ChainState state;
  state.tau = tau;
  state.psi.resize(n);
  state.vel.assign(n, 0.0);
  for (int j = 1; j <= n; ++j) state.psi[j - 1] = j + std::min<double>(j, tau - n);
  cb::SnapshotStyle style;
  style.width = kWidth;
  style.height = kHeight;
  style.view = cb::View::Both;
  style.psi_range = state.psi.back();
  style.force_range = 1.0;
  style.strain_range = 2.0;  // unbreakable: the colour scale ends at the largest |phi|
  return cb::build_snapshot(state, chain(n, std::numeric_limits<double>::infinity()), 1.0, style);
}

// An unequal chain (issue #21) held in static equilibrium by a constant pull f = 0.6: every
// spring carries f, so phi_j = f / K_j and psi_j = sum_{i <= j} f / K_i (exact, no
// integrator). Springs 1-15 are stiff (K = 4) and drawn wider, beads 8 and 22 heavy (m = 4,
// drawn with 4x the area) and bead 25 light (m = 1/4); spring 20 is a weak link
// (phi_c,20 = 0.5 against 2 elsewhere): the colours, phi_j / phi_c,j, show it nearest to
// breaking (0.6 of the way for the soft springs, 0.075 for the stiff ones, 1.2 -> clamped for
// the weak link, which has just broken: the recoiling halves).
cb::RenderSnapshot unequal_chain(cb::ThemeName theme) {
  const int n = 30;
  const double f = 0.6;
  cb::ChainParams params = chain(n, 2.0);
  params.mass.assign(n, 1.0);
  params.mass[7] = params.mass[21] = 4.0;
  params.mass[24] = 0.25;
  params.stiffness.assign(n, 1.0);
  for (int j = 1; j <= 15; ++j) params.stiffness[j - 1] = 4.0;
  params.thresholds.assign(n, 2.0);
  params.thresholds[19] = 0.5;
  cb::ChainState state;
  state.tau = 41.0;
  state.vel.assign(n, 0.0);
  double psi = 0.0;
  for (int j = 1; j <= n; ++j) state.psi.push_back(psi += f / params.stiffness[j - 1]);
  state.broken = {20};
  state.breaks = {cb::BreakEvent{20, 40.0, 4000}};
  cb::SnapshotStyle style;
  style.width = kWidth;
  style.height = kHeight;
  style.theme = theme;
  style.psi_range = state.psi.back();
  style.force_range = 1.0;
  style.threshold = params.min_threshold();
  return cb::build_snapshot(state, params, f, style);
}

// A fast pull's cascade (scenes/units_example.toml's breaks: spring 30 first at tau 51.60,
// then 14 more near the wall within 0.35, and spring 4 at 58.88), each broken spring opened
// by 1.5: the first break's label in bold over an accent leader, the later ones muted and
// kept apart in a staircase, the rest counted.
cb::RenderSnapshot cascade_labels(cb::ThemeName theme) {
  const int n = 30;
  const std::vector<cb::BreakEvent> breaks{
      {30, 51.60, 0}, {19, 55.71, 0}, {20, 55.71, 0}, {14, 55.76, 0}, {10, 55.76, 0},
      {2, 55.77, 0},  {6, 55.79, 0},  {5, 55.79, 0},  {7, 55.81, 0},  {8, 55.82, 0},
      {12, 55.84, 0}, {16, 55.85, 0}, {17, 55.86, 0}, {22, 55.93, 0}, {4, 58.88, 0}};
  cb::ChainState state;
  state.tau = 60.0;
  state.breaks = breaks;
  for (const cb::BreakEvent& b : breaks) state.broken.push_back(b.spring);
  std::sort(state.broken.begin(), state.broken.end());
  double shift = 0.0;
  for (int j = 1; j <= n; ++j) {
    if (std::binary_search(state.broken.begin(), state.broken.end(), j)) shift += 1.5;
    state.psi.push_back(shift);
  }
  state.vel.assign(n, 0.0);
  cb::SnapshotStyle style;
  style.width = kWidth;
  style.height = kHeight;
  style.theme = theme;
  style.psi_range = state.psi.back();
  style.force_range = 1.0;
  style.threshold = 2.0;
  return cb::build_snapshot(state, chain(n, 2.0), 0.0, style);
}

// Issue #22's vertical view, from a scene of scenes/ with the Integrator: `after` tau past the
// first break (after >= 0), else at step `step`, laid out as `chainbreak snapshot` lays it
// out (render.view is "vertical" by default for these scenes; the layout measured up to the
// first break).
cb::RenderSnapshot hanging_scene(const char* file, cb::ThemeName theme, std::int64_t step,
                                 double after) {
  const cb::SceneDesc scene = cb::load_scene(std::string(CHAINBREAK_SCENES) + "/" + file);
  cb::View view = cb::View::Longitudinal;
  REQUIRE(cb::parse_view(scene.render.view, view));
  REQUIRE(view == cb::View::Vertical);
  const auto style = measured_style(scene.chain, scene.drive, scene.integrator.t_end, view, theme);
  return frame_at(scene.chain, scene.drive, style, step, after);
}

// scenes/hanging_chain.toml (N = 30, G = 0.01, ramp 0.005) 1 after the top spring breaks
// (tau ~ 141): the chain falls away from the ceiling, the flash, the first break's label.
cb::RenderSnapshot hanging_chain_just_broken(cb::ThemeName theme) {
  return hanging_scene("hanging_chain.toml", theme, 0, 1.0);
}

// scenes/inertia_ball.toml (Heald's ball, G = 0.05, ramp beta = 1/(2.5 pi)) at tau = 4,
// before either string breaks: the ceiling, the upper string stretched by the weight and the
// pull, the ball, the lower string and the arrow pointing down.
cb::RenderSnapshot inertia_ball(cb::ThemeName theme) {
  return hanging_scene("inertia_ball.toml", theme, 400, -1.0);
}

}  // namespace

TEST_CASE("Golden frames match within tolerance", "[golden]") {
  const cb::GlBackend backend = GENERATE(cb::GlBackend::OSMesa, cb::GlBackend::Egl);
  INFO("backend " << cb::gl_backend_name(backend));
  auto context = cb::test::create_or_skip(backend);
  if (!context) return;
  cb::Renderer renderer(kWidth, kHeight);

  const auto anomalous = anomalous_just_broken();
  REQUIRE(anomalous.breaks_shown.size() == 1);
  CHECK(anomalous.breaks_shown[0].spring == 30);  // what the scene is about
  check_golden("anomalous_just_broken", backend, renderer.render(anomalous));

  check_golden("step_pulse_reflecting", backend, renderer.render(step_pulse_reflecting()));
  // The light theme (paper, handouts): the same frames from the same drawing code.
  check_golden("anomalous_just_broken_light", backend,
               renderer.render(anomalous_just_broken(cb::ThemeName::Light)));
  check_golden("step_pulse_reflecting_light", backend,
               renderer.render(step_pulse_reflecting(cb::ThemeName::Light)));

  const auto ball = ball_with_pull_string();
  CHECK(ball.breaks_shown.empty());
  CHECK(ball.arrow_length > 0.0);
  check_golden("ball_with_pull_string", backend, renderer.render(ball));

  const auto ribbon = ribbon_1e5();
  CHECK(ribbon.ribbon);
  check_golden("ribbon_1e5", backend, renderer.render(ribbon));

  // Issue #21's pictures: an unequal chain, and a cascade's labels, in both themes.
  for (const cb::ThemeName theme : {cb::ThemeName::Dark, cb::ThemeName::Light}) {
    const std::string suffix = theme == cb::ThemeName::Light ? "_light" : "";
    const auto unequal = unequal_chain(theme);
    CHECK(unequal.break_labels.size() == 1);
    check_golden("unequal_chain" + suffix, backend, renderer.render(unequal));
    const auto cascade = cascade_labels(theme);
    CHECK(cascade.break_labels.front().first);
    CHECK(cascade.break_labels.front().spring == 30);
    check_golden("cascade_labels" + suffix, backend, renderer.render(cascade));
  }

  // Issue #22's vertical view: a hanging chain and Heald's ball on two strings, both themes.
  for (const cb::ThemeName theme : {cb::ThemeName::Dark, cb::ThemeName::Light}) {
    const std::string suffix = theme == cb::ThemeName::Light ? "_light" : "";
    const auto chain = hanging_chain_just_broken(theme);
    REQUIRE(!chain.break_labels.empty());
    CHECK(chain.break_labels.front().spring == 1);  // the top spring holds the whole weight
    check_golden("hanging_chain" + suffix, backend, renderer.render(chain));
    const auto ball = inertia_ball(theme);
    CHECK(ball.breaks_shown.empty());
    CHECK(ball.arrow_length > 0.0);  // down the frame, the way the pull acts
    check_golden("inertia_ball" + suffix, backend, renderer.render(ball));
  }
}
