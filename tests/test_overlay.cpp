// The overlay (src/overlay) without GL: the data behind every plot against its source (RK4
// points against ExactChain, the exact lines are ExactChain's values, the energy history is
// per_particle(energy()), a space-time row is phi_j / phi_c, a single normal mode shows
// alone), bounded histories, the layout and the switches. Drawn with GL: test_overlay_gl.cpp.
#include <unistd.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <memory>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "exact/exact_chain.h"
#include "gl/gl_context.h"
#include "gl_test_support.h"
#include "output/png_writer.h"
#include "overlay/modes.h"
#include "overlay/overlay.h"
#include "overlay/overlay_history.h"
#include "overlay/overlay_layout.h"
#include "overlay_test_support.h"
#include "physics/energy.h"
#include "physics/integrator.h"
#include "render/renderer.h"
#include "scene/scene.h"
#include "snapshot/snapshot.h"

using namespace cb::overlay_test;

namespace {

// What `render` does on its producer thread: step to frame k (k * substeps steps of dt) and
// record it. Returns the history after `frames` frames.
std::unique_ptr<cb::OverlayHistory> record_run(const cb::ChainParams& params,
                                               const cb::DriveDesc& drive, double dt,
                                               std::int64_t substeps, int frames) {
  cb::OverlaySetup setup;
  setup.tau_per_frame = dt * static_cast<double>(substeps);
  setup.tau_end = setup.tau_per_frame * (frames - 1);
  setup.strain_scale = params.breakable() ? params.threshold : 1.0;
  auto history = std::make_unique<cb::OverlayHistory>(params, drive, setup);
  cb::Integrator sim(params, cb::make_forcing(drive), {dt, 1});
  for (int k = 0; k < frames; ++k) {
    REQUIRE(sim.advance_to(k * substeps));
    history->record(k, sim.state(), sim.force_now());
  }
  return history;
}

cb::ChainState state_of(std::vector<double> psi, std::vector<double> vel, double tau = 0.0) {
  cb::ChainState s;
  s.psi = std::move(psi);
  s.vel = std::move(vel);
  s.tau = tau;
  return s;
}

}  // namespace

// ---- Data (no GL) -------------------------------------------------------------------------

TEST_CASE("Overlay: RK4 phi_1, phi_N/2, phi_N at the frame times follow ExactChain", "[overlay]") {
  // The default scene's chain and ramp (N = 30, beta = 0.02), unbreakable, 0.5 tau per frame
  // for 200 tau: across the wave's first round trip and back (Fig. 4(a)'s kinks).
  const cb::ChainParams params = chain(30);
  const cb::DriveDesc drive = ramp(0.02);
  const auto history = record_run(params, drive, 0.01, 50, 401);
  const cb::OverlayData& d = history->data();
  REQUIRE(d.spring_count == 3);
  CHECK(d.springs[0] == 1);
  CHECK(d.springs[1] == 15);
  CHECK(d.springs[2] == 30);
  REQUIRE(d.history_tau.size() == 401u);  // under the cap: every frame kept
  const cb::ExactChain exact(30, 0.0, drive);
  double worst = 0.0;
  for (std::size_t i = 0; i < d.history_tau.size(); ++i) {
    CHECK(d.history_tau[i] == Approx(0.5 * static_cast<double>(i)).margin(1e-9));
    for (int s = 0; s < 3; ++s)
      worst = std::max(worst, std::abs(d.phi[s][i] - exact.phi(d.springs[s], d.history_tau[i])));
  }
  // RK4 at dt = 0.01 against the exact modal solution: the error is O(dt^4) ~ 1e-9 here.
  INFO("largest |phi_RK4 - phi_exact| = " << worst);
  CHECK(worst < 1e-7);
}

TEST_CASE("Overlay: the exact lines are ExactChain's values on a grid finer than the frames",
          "[overlay]") {
  const cb::ChainParams params = chain(30);
  const cb::DriveDesc drive = ramp(0.02);
  const auto history = record_run(params, drive, 0.01, 50, 41);
  const cb::OverlayData& d = history->data();
  REQUIRE(d.exact);
  // kExactPerFrame samples per frame interval, the frame times among them.
  REQUIRE(d.exact_tau.size() == static_cast<std::size_t>(40 * cb::kExactPerFrame + 1));
  const cb::ExactChain exact(30, 0.0, drive);
  for (std::size_t i = 0; i < d.exact_tau.size(); ++i) {
    CHECK(d.exact_tau[i] ==
          Approx(0.5 * static_cast<double>(i) / cb::kExactPerFrame).margin(1e-12));
    for (int s = 0; s < 3; ++s)  // the same sums as ExactChain::phi, in the same order
      CHECK(d.exact_phi[s][i] == Approx(exact.phi(d.springs[s], d.exact_tau[i])).margin(1e-12));
  }
  CHECK(std::isnan(d.exact_end));
}

TEST_CASE("Overlay: the exact lines stop at the first break", "[overlay]") {
  // The pulled end breaks first for a fast pull: zeta_c = phi_c / beta = 10 < 2N.
  const cb::ChainParams params = chain(30, 1.0);
  const cb::DriveDesc drive = ramp(0.1);
  const auto history = record_run(params, drive, 0.01, 25, 81);  // to tau = 20
  const cb::OverlayData& d = history->data();
  REQUIRE_FALSE(d.breaks.empty());
  const double t_break = d.breaks.front().tau;
  CHECK(d.breaks.front().spring == 30);
  CHECK(d.exact_end == t_break);
  REQUIRE_FALSE(d.exact_tau.empty());
  CHECK(d.exact_tau.back() == t_break);  // the last sample is the break
  for (std::size_t i = 0; i + 1 < d.exact_tau.size(); ++i) CHECK(d.exact_tau[i] < t_break);
  const cb::ExactChain exact(30, 0.0, drive);
  CHECK(d.exact_phi[2].back() == Approx(exact.phi(30, t_break)).margin(1e-12));
  // The RK4 points go on after the break.
  CHECK(d.history_tau.back() == Approx(20.0).margin(1e-9));
}

TEST_CASE("Overlay: the energy history is per_particle(energy()) of each frame's state",
          "[overlay]") {
  const cb::ChainParams params = chain(12);
  const cb::DriveDesc drive = ramp(0.05);
  cb::OverlaySetup setup;
  setup.tau_per_frame = 0.25;
  cb::OverlayHistory history(params, drive, setup);
  cb::Integrator sim(params, cb::make_forcing(drive), {0.05, 1});
  for (int k = 0; k < 60; ++k) {
    REQUIRE(sim.advance_to(5 * k));
    history.record(k, sim.state(), sim.force_now());
    const cb::EnergyParts e = cb::energy(sim.state());
    const cb::OverlayData& d = history.data();
    // Exactly the same arithmetic: equal to the last bit.
    CHECK(d.energy_total.back() == cb::per_particle(e.total(), 12));
    CHECK(d.energy_kinetic.back() == cb::per_particle(e.kinetic, 12));
    CHECK(d.energy_potential.back() == cb::per_particle(e.potential, 12));
    CHECK(d.energy == d.energy_total.back());
    CHECK(d.force == sim.force_now());
    CHECK(d.tau == sim.state().tau);
  }
}

TEST_CASE("Overlay: a space-time row is phi_j / phi_c of its state", "[overlay]") {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  cb::OverlaySetup setup;
  setup.tau_per_frame = 1.0;
  setup.strain_scale = 1.5;

  SECTION("N <= 256: one column per spring; broken springs are NaN") {
    const int n = 40;
    std::vector<double> psi(n);
    for (double& p : psi) p = u(rng);
    cb::ChainState s = state_of(psi, std::vector<double>(n, 0.0));
    s.broken = {3, 17};
    cb::OverlayHistory history(chain(n, 1.5), ramp(0.01), setup);
    history.record(0, s, 0.0);
    const cb::OverlayData& d = history.data();
    REQUIRE(d.spacetime_columns == n);
    REQUIRE(d.spacetime_rows() == 1);
    for (int j = 1; j <= n; ++j) {
      const float v = d.spacetime[j - 1];
      if (j == 3 || j == 17) {
        CHECK(std::isnan(v));
      } else {  // stored as float: within its rounding
        CHECK(v == Approx(cb::extension(s, j) / 1.5).epsilon(1e-7));
      }
    }
  }
  SECTION("N > 256: column c holds the most strained spring of its block") {
    const int n = 1000, columns = cb::kMaxSpacetimeColumns;
    std::vector<double> psi(n);
    for (double& p : psi) p = u(rng);
    const cb::ChainState s = state_of(psi, std::vector<double>(n, 0.0));
    cb::OverlayHistory history(chain(n, 1.5), ramp(0.01), setup);
    history.record(0, s, 0.0);
    const cb::OverlayData& d = history.data();
    REQUIRE(d.spacetime_columns == columns);
    for (int c = 0; c < columns; ++c) {
      // Springs floor(c N / C) + 1 .. floor((c + 1) N / C), as overlay_data.h documents.
      double best = 0.0;
      for (int j = c * n / columns + 1; j <= (c + 1) * n / columns; ++j)
        if (std::abs(cb::extension(s, j)) > std::abs(best)) best = cb::extension(s, j);
      CHECK(d.spacetime[c] == Approx(best / 1.5).epsilon(1e-7));
    }
  }
}

TEST_CASE("Overlay: histories stay bounded and on frame times", "[overlay]") {
  // 5000 frames of a small chain: every history decimates (strides double) and stays capped.
  const int n = 4;
  cb::OverlaySetup setup;
  setup.tau_per_frame = 0.1;
  cb::OverlayHistory history(chain(n), ramp(0.01), setup);
  const int frames = 5000;
  for (int k = 0; k < frames; ++k) {
    const double tau = 0.1 * k;
    history.record(k,
                   state_of(std::vector<double>(n, 0.01 * tau), std::vector<double>(n, 0.0), tau),
                   0.01 * tau);
  }
  const cb::OverlayData& d = history.data();
  CHECK(static_cast<int>(d.history_tau.size()) <= cb::kMaxHistory);
  CHECK(d.spacetime_rows() <= cb::kMaxSpacetimeRows);
  CHECK(static_cast<int>(d.exact_tau.size()) <= cb::kMaxHistory * cb::kExactPerFrame);
  CHECK(d.history_stride == 4);                           // 5000 frames / 2048 -> stride 4
  CHECK(d.spacetime_stride == 16);                        // 5000 / 512 -> 16
  for (std::size_t i = 0; i < d.history_tau.size(); ++i)  // evenly spaced, from frame 0
    CHECK(d.history_tau[i] == Approx(0.1 * d.history_stride * static_cast<double>(i)).margin(1e-9));
  for (std::size_t i = 0; i < d.spacetime_tau.size(); ++i)
    CHECK(d.spacetime_tau[i] ==
          Approx(0.1 * d.spacetime_stride * static_cast<double>(i)).margin(1e-9));
  CHECK(d.phi[0].size() == d.history_tau.size());
  CHECK(d.energy_total.size() == d.history_tau.size());
  CHECK(d.exact_phi[0].size() == d.exact_tau.size());
}

TEST_CASE("Overlay: a single normal mode shows alone", "[overlay]") {
  // psi_j = sin(k_2 j), at rest: a_2 = 1 and a_n = 0 otherwise (the paper's orthogonality),
  // so A_2 = Omega_2 = 2 sin(k_2 / 2) and every other A_n vanishes to rounding.
  for (int n : {30, 5000}) {
    INFO("N = " << n);
    const double k2 = 2.5 * std::numbers::pi / (n + 0.5);
    std::vector<double> psi(n);
    for (int j = 1; j <= n; ++j) psi[j - 1] = std::sin(k2 * j);
    std::vector<double> amp;
    cb::mode_amplitudes(state_of(psi, std::vector<double>(n, 0.0)), 16, amp);
    REQUIRE(amp.size() == 16u);
    CHECK(amp[2] == Approx(2.0 * std::sin(0.5 * k2)).epsilon(1e-10));
    for (int m = 0; m < 16; ++m)
      if (m != 2) CHECK(amp[m] < 1e-10 * amp[2]);
  }
  // A velocity in mode 5 alone: a_5' = 1, so A_5 = 1.
  const int n = 30;
  const double k5 = 5.5 * std::numbers::pi / (n + 0.5);
  std::vector<double> vel(n);
  for (int j = 1; j <= n; ++j) vel[j - 1] = std::sin(k5 * j);
  std::vector<double> amp;
  cb::mode_amplitudes(state_of(std::vector<double>(n, 0.0), vel), n, amp);
  for (int m = 0; m < n; ++m) CHECK(amp[m] == Approx(m == 5 ? 1.0 : 0.0).margin(1e-12));
}

TEST_CASE("Overlay: the modes carry the energy, (2N+1)/8 sum A_n^2 = E", "[overlay]") {
  // modes.h: for an intact chain the squared amplitudes of all N modes add up to the energy.
  std::mt19937_64 rng(3);
  std::normal_distribution<double> g(0.0, 1.0);
  const int n = 50;
  std::vector<double> psi(n), vel(n);
  for (int j = 0; j < n; ++j) {
    psi[j] = g(rng);
    vel[j] = g(rng);
  }
  const cb::ChainState s = state_of(psi, vel);
  std::vector<double> amp;
  cb::mode_amplitudes(s, n, amp);
  double sum = 0.0;
  for (double a : amp) sum += a * a;
  CHECK((2.0 * n + 1.0) / 8.0 * sum == Approx(cb::energy(s).total()).epsilon(1e-12));
}

TEST_CASE("Overlay layout: the chain's band on top, panels below it, apart", "[overlay]") {
  const cb::OverlaySwitches all;
  for (auto [w, h] : {std::pair{1920, 1080}, {3840, 2160}, {1280, 720}, {854, 480}, {1080, 1920}}) {
    INFO(w << "x" << h);
    const cb::OverlayLayout l = cb::overlay_layout(w, h, all);
    REQUIRE(l.enabled);
    CHECK(l.chain_height > h / 3);
    const cb::Box panels[] = {l.hud, l.phi, l.energy, l.spacetime, l.modes};
    for (const cb::Box& p : panels) {
      REQUIRE_FALSE(p.empty());
      CHECK(p.y >= l.chain_height);  // nothing of the overlay over the chain's band
      CHECK(p.x >= 0);
      CHECK(p.right() <= w);
      CHECK(p.bottom() <= h);
      for (const cb::Box& q : panels) {
        if (&p == &q) continue;
        const bool apart =
            p.right() <= q.x || q.right() <= p.x || p.bottom() <= q.y || q.bottom() <= p.y;
        CHECK(apart);
      }
    }
  }
  // 1.8% of the height: 19 px at 1080p, 39 px at 4K.
  CHECK(cb::overlay_layout(1920, 1080, all).font_px == 22);  // theme/fonts.h: 2% of the height
  CHECK(cb::overlay_layout(3840, 2160, all).font_px == 43);
  CHECK(cb::overlay_layout(854, 480, all).font_px == 14);  // never under 14 px
  // Too small, or nothing on: no overlay, the chain keeps the whole frame.
  CHECK_FALSE(cb::overlay_layout(320, 180, all).enabled);
  CHECK_FALSE(
      cb::overlay_layout(1920, 1080, cb::OverlaySwitches{false, false, false, false}).enabled);
  // Only some parts: the others get no room.
  const cb::OverlayLayout hud = cb::overlay_layout(1920, 1080, {true, false, false, false});
  CHECK_FALSE(hud.hud.empty());
  CHECK(hud.phi.empty());
  CHECK(hud.chain_height > cb::overlay_layout(1920, 1080, all).chain_height);
}

TEST_CASE("Overlay layout: x tick labels stay in the panel and never touch", "[overlay]") {
  const float font = 10.0f;
  // Room for all: centred under their ticks; the last ends exactly half a font past the edge.
  const auto roomy = cb::x_tick_label_lefts({0, 100, 200}, {10, 10, 10}, 200.0f, font);
  CHECK(roomy == std::vector<float>{-5.0f, 95.0f, 195.0f});
  // A wide last label would run past the edge: right-aligned at its tick.
  const auto wide = cb::x_tick_label_lefts({0, 100, 200}, {10, 10, 30}, 200.0f, font);
  CHECK(wide == std::vector<float>{-5.0f, 95.0f, 170.0f});
  // Crowded ("800" against a right-aligned "1000", as on the page's space-time panel): the
  // middle label would end 9 px into the last one's half-font gap, so it is left out; the
  // first still clears it.
  const auto crowded = cb::x_tick_label_lefts({0, 20, 40}, {16, 16, 16}, 40.0f, font);
  REQUIRE(crowded.size() == 3);
  CHECK(crowded[0] == -8.0f);
  CHECK(std::isnan(crowded[1]));
  CHECK(crowded[2] == 24.0f);
}

TEST_CASE("Overlay switches parse from --overlay lists", "[overlay]") {
  cb::OverlaySwitches s;
  std::string bad;
  REQUIRE(cb::parse_overlay_switches("plots,hud", s, bad));
  CHECK((s.hud && s.plots && !s.spacetime && !s.modes));
  CHECK(cb::overlay_switches_text(s) == "hud,plots");
  REQUIRE(cb::parse_overlay_switches("all", s, bad));
  CHECK(cb::overlay_switches_text(s) == "hud,plots,spacetime,modes");
  REQUIRE(cb::parse_overlay_switches("none", s, bad));
  CHECK_FALSE(s.any());
  CHECK_FALSE(cb::parse_overlay_switches("hud,graphs", s, bad));
  CHECK(bad == "graphs");
}

TEST_CASE("Overlay switches in the scene's render table", "[overlay]") {
  const cb::SceneDesc d = cb::parse_scene(R"(
[chain]
beads = 5
[drive]
type = "ramp"
beta = 0.1
[integrator]
t_end = 10
[render]
overlay_hud = false
overlay_modes = false
)",
                                          "switches.toml");
  CHECK(d.render.overlay);
  CHECK_FALSE(d.render.overlay_hud);
  CHECK(d.render.overlay_plots);
  CHECK(d.render.overlay_spacetime);
  CHECK_FALSE(d.render.overlay_modes);
}

TEST_CASE(
    "Snapshot: a chain band of the full height changes nothing; a shorter one keeps the "
    "chain above it",
    "[overlay]") {
  const cb::ChainParams params = chain(30, 3.0);
  const cb::DriveDesc drive = ramp(0.02);
  cb::Integrator sim(params, cb::make_forcing(drive), {0.01, 1});
  REQUIRE(sim.advance_to(6000));
  cb::SnapshotStyle style;
  style.width = 1920;
  style.height = 1080;
  style.psi_range = 8.0;
  style.force_range = 3.0;
  style.threshold = 3.0;
  const cb::RenderSnapshot whole = cb::build_snapshot(sim.state(), params, sim.force_now(), style);
  style.chain_height = 1080;
  const cb::RenderSnapshot same = cb::build_snapshot(sim.state(), params, sim.force_now(), style);
  REQUIRE(same.layers.size() == whole.layers.size());
  for (std::size_t i = 0; i < whole.layers.size(); ++i) {
    CHECK(same.layers[i].rects.size() == whole.layers[i].rects.size());
    for (std::size_t k = 0; k < whole.layers[i].beads.size(); ++k)
      CHECK(same.layers[i].beads[k].y == whole.layers[i].beads[k].y);
  }
  CHECK(same.layout.legend_y == whole.layout.legend_y);

  const cb::OverlayLayout l = cb::overlay_layout(1920, 1080, cb::OverlaySwitches{});
  style.chain_height = l.chain_height;
  const cb::RenderSnapshot top = cb::build_snapshot(sim.state(), params, sim.force_now(), style);
  CHECK(top.layout.legend_y + top.layout.legend_h < l.chain_height);
  CHECK(top.layout.panels[0].bottom <= l.chain_height);
  for (const auto& layer : top.layers) {
    for (const auto& b : layer.beads) CHECK(b.y + b.radius < l.chain_height);
    for (const auto& label : layer.labels) CHECK(label.y + label.size < l.chain_height);
  }
  CHECK(top.layout.text_size == whole.layout.text_size);  // text follows the frame, not the band
}
