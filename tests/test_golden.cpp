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

#include "drive/drive.h"
#include "gl/gl_context.h"
#include "gl_test_support.h"
#include "golden_support.h"
#include "output/image.h"
#include "output/png_writer.h"
#include "physics/integrator.h"
#include "render/renderer.h"
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
}
