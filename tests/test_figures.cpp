// The numbers behind `chainbreak figures`, checked against the exact solver, the paper's
// closed forms and each other's independent solver, never against the code that made them.
// No GL here; test_figures_gl.cpp checks the pictures.
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>

#include "exact/continuum.h"
#include "exact/exact_chain.h"
#include "exact/first_break.h"
#include "figure_test_support.h"
#include "figures/break_maps.h"
#include "physics/chain.h"
#include "physics/energy.h"

namespace {

using cb::test::built_figure;
using cb::test::series_of;

// Eq. (rescale2): a ramp beta tau with threshold phi_c breaks where the unit ramp with
// zeta_c = phi_c / beta does. Asked here as phi_c = 1 and beta = 1 / zeta_c, a different
// drive from the one the map was computed with.
cb::FirstBreak first_break_by_slope(double zeta_c, double gamma = 0.0) {
  cb::ChainParams chain;
  chain.beads = 30;
  chain.gamma = gamma;
  chain.threshold = 1.0;
  cb::DriveDesc drive;
  drive.type = cb::DriveType::Ramp;
  drive.beta = 1.0 / zeta_c;
  return cb::exact_first_break(chain, drive, 8.0 * zeta_c + 400.0);
}

cb::DriveDesc ramp() {
  cb::DriveDesc d;
  d.type = cb::DriveType::Ramp;
  d.beta = 1.0;
  return d;
}

}  // namespace

TEST_CASE("Breaking map N = 30, gamma = 0: spring N / not-N switches, by the exact solver",
          "[figures]") {
  const auto switches = cb::spring_n_boundaries(30, 0.0, 0.5, cb::kMapZetaMax, 250);
  // The continuum (Eq. (phij)) puts the switches at 2N, 4N, 6N, 8N; the discrete chain moves
  // them (by up to ~5 here: dispersion rounds the front), but not past the neighbouring one.
  REQUIRE(switches.size() == 4);
  const double continuum[4] = {60.0, 120.0, 180.0, 240.0};
  for (int k = 0; k < 4; ++k) {
    const auto& s = switches[k];
    INFO("switch " << k << " at zeta_c = " << s.zeta << ", spring " << s.below << " -> "
                   << s.above);
    CHECK(std::abs(s.zeta - continuum[k]) < 8.0);
    CHECK(std::abs(s.zeta - continuum[k]) > 0.1);  // "the exact boundaries are not exactly there"
    // Below an even switch spring N breaks first, above it another; the odd ones go back.
    CHECK((s.below == 30) == (k % 2 == 0));
    CHECK((s.above == 30) == (k % 2 == 1));
    // Independently: the exact first break either side, asked through the drive's slope.
    for (double side : {-1e-6, 1e-6}) {
      const cb::FirstBreak b = first_break_by_slope(s.zeta + side * s.zeta);
      REQUIRE(b.broke);
      CHECK((b.spring == 30) == ((side < 0) == (k % 2 == 0)));
    }
  }
  // Half-way between switches the map is what the switches say: N, not N, N, not N, N.
  const double middles[5] = {30.0, 90.0, 150.0, 210.0, 248.0};
  for (int k = 0; k < 5; ++k) {
    const cb::FirstBreak b = first_break_by_slope(middles[k]);
    INFO("zeta_c = " << middles[k] << ": spring " << b.spring);
    CHECK((b.spring == 30) == (k % 2 == 0));
  }
}

TEST_CASE("Breaking map N = 30, gamma = 0.01: friction closes all but one wall-side window",
          "[figures]") {
  // The paper (Sec. III): friction diminishes the anomaly and makes the wall side hard to
  // break. Up to zeta_c = 250 only one window of wall-side breaks is left, inside (2N, 4N).
  const auto switches = cb::spring_n_boundaries(30, 0.01, 0.5, cb::kMapZetaMax, 250);
  REQUIRE(switches.size() == 2);
  CHECK(switches[0].zeta > 60.0);
  CHECK(switches[1].zeta < 120.0);
  for (std::size_t k = 0; k < 2; ++k)
    for (double side : {-1e-6, 1e-6}) {
      const cb::FirstBreak b = first_break_by_slope(switches[k].zeta * (1 + side), 0.01);
      INFO("switch at " << switches[k].zeta << ", side " << side << ": spring " << b.spring);
      CHECK((b.spring == 30) == ((side < 0) == (k == 0)));
    }
}

TEST_CASE("Breaking map figure: exact and RK4 agree away from the switches, both gammas",
          "[figures]") {
  const cb::Figure& f = built_figure("breaking_map");
  for (const char* gamma : {"\u03B3 = 0", "\u03B3 = 0.01"}) {
    const cb::Series& exact = series_of(f, std::string("exact ") + gamma);
    const cb::Series& rk4 = series_of(f, std::string("RK4 ") + gamma);
    const double g = std::string(gamma) == "\u03B3 = 0" ? 0.0 : 0.01;
    const auto switches = cb::spring_n_boundaries(30, g, 0.5, cb::kMapZetaMax, 250);
    int compared = 0, same = 0;
    for (std::size_t i = 0; i < rk4.x.size(); ++i) {
      bool near_switch = false;
      for (const auto& s : switches) near_switch |= std::abs(rk4.x[i] - s.zeta) < 1.0;
      if (near_switch) continue;
      const cb::FirstBreak b = first_break_by_slope(rk4.x[i], g);
      ++compared;
      // N / not N is robust; which wall-side spring wins can flip where two are within RK4's
      // error of each other, so count those.
      CHECK((rk4.y[i] == 30) == (b.spring == 30));
      same += rk4.y[i] == b.spring;
    }
    INFO(gamma << ": " << same << " of " << compared << " RK4 springs equal the exact ones");
    CHECK(same >= 0.9 * compared);
    // The plotted exact line is the exact solver's map (spot checks through the slope).
    for (std::size_t i = 0; i < exact.x.size(); i += 97) {
      INFO("zeta_c = " << exact.x[i]);
      CHECK(exact.y[i] == first_break_by_slope(exact.x[i], g).spring);
    }
  }
}

TEST_CASE("Continuum breaking rule: bands of Eq. (phij)", "[figures]") {
  // phi_N = tau reaches zeta at tau = zeta; phi_1 = 2 (tau - N) reaches it at N + zeta / 2.
  CHECK(cb::continuum_ramp_break(30, 59.0).pulled_end);
  CHECK_FALSE(cb::continuum_ramp_break(30, 61.0).pulled_end);
  CHECK(cb::continuum_ramp_break(30, 61.0).last_spring == Approx(60.0 - 30.5));
  CHECK(cb::continuum_ramp_break(30, 121.0).pulled_end);  // anomalous
  CHECK_FALSE(cb::continuum_ramp_break(30, 181.0).pulled_end);
  // And the piecewise-linear phi_j agree: at tau = N + zeta / 2, springs 1..last reach zeta.
  const double zeta = 100.0, tau = 30.0 + zeta / 2.0;
  const double last = cb::continuum_ramp_break(30, zeta).last_spring;
  CHECK(cb::continuum_phij(30, 1.0, static_cast<int>(last), tau) == Approx(zeta));
  CHECK(cb::continuum_phij(30, 1.0, static_cast<int>(last) + 2, tau) < zeta);
  CHECK(cb::continuum_phiN(1.0, tau) < zeta);
}

TEST_CASE("Fig. 4(a): RK4 points on the exact solution, lines on Eq. (extension)", "[figures]") {
  const cb::Figure& f = built_figure("fig4a");
  const cb::ExactChain exact(30, 0.0, ramp());
  const int springs[3] = {1, 15, 30};
  const char* names[3] = {"\u03C6\u2081", "\u03C6\u2081\u2085", "\u03C6\u2083\u2080"};
  for (int k = 0; k < 3; ++k) {
    const cb::Series& rk4 = series_of(f, std::string(names[k]) + " RK4");
    REQUIRE(rk4.x.size() == 101);  // tau = 0, 1.5, ..., 150
    for (std::size_t i = 0; i < rk4.x.size(); ++i)
      // RK4 at dt = 0.01: global error ~ dt^4 tau; 1e-6 absolute is ample (phi ~ 100).
      REQUIRE(rk4.y[i] == Approx(exact.phi(springs[k], rk4.x[i])).margin(1e-6));
    // The piecewise-linear lines against the Fourier series of Eq. (extension) (2000 terms:
    // truncation error ~ 8N / (pi^2 4000) ~ 0.01 away from the kinks). Eq. (phi1) is the
    // series at xi = 0 (the wall), Eq. (phij) at xi = j.
    const cb::Series& line = series_of(f, std::string(names[k]) + " continuum");
    const double xi = springs[k] == 1 ? 0.0 : springs[k];
    for (std::size_t i = 3; i < line.x.size(); i += 10) {
      const double series = cb::continuum_phi_series(30, 1.0, xi, line.x[i], 2000);
      INFO("tau = " << line.x[i]);
      CHECK(line.y[i] == Approx(series).margin(0.1));
    }
  }
}

TEST_CASE("Fig. 4(b): the energy is Eq. (energy) of the exact state", "[figures]") {
  const cb::Figure& f = built_figure("fig4b");
  const cb::Series& kinetic = series_of(f, "kinetic");
  const cb::Series& potential = series_of(f, "potential");
  const cb::ExactChain exact(30, 0.0, ramp());
  std::vector<double> psi, vel;
  for (std::size_t i = 0; i < kinetic.x.size(); i += 40) {
    cb::ChainState s;
    exact.evaluate(kinetic.x[i], &psi, &vel, nullptr, nullptr);
    s.psi = psi;
    s.vel = vel;
    const cb::EnergyParts e = cb::energy(s);
    INFO("tau = " << kinetic.x[i]);
    CHECK(kinetic.y[i] == Approx(cb::per_particle(e.kinetic, 30)).epsilon(1e-7).margin(1e-12));
    CHECK(potential.y[i] == Approx(cb::per_particle(e.potential, 30)).epsilon(1e-7).margin(1e-12));
  }
  // The paper: the kinetic part has period 4N.
  CHECK(kinetic.y[4 * 120] == Approx(0.0).margin(1e-3));  // tau = 120: at rest again
}

TEST_CASE("Fig. 4(c): each threshold is first reached where the exact phi says", "[figures]") {
  const cb::Figure& f = built_figure("fig4c");
  const cb::Series& hl = series_of(f, "thresholds");
  REQUIRE(hl.y.size() == 3);
  const cb::ExactChain exact(30, 0.0, ramp());
  const bool pulled_end[3] = {true, false, true};  // fast, slow, anomalous (the caption)
  for (std::size_t k = 0; k < 3; ++k) {
    const double zeta = hl.y[k], tau = hl.x[k];
    std::vector<double> phi;
    exact.phi(tau, phi);
    const double largest = *std::max_element(phi.begin(), phi.end());
    INFO("zeta_c = " << zeta << " at tau = " << tau);
    CHECK(largest == Approx(zeta).epsilon(1e-9));
    CHECK((phi[29] == Approx(zeta).epsilon(1e-9)) == pulled_end[k]);
    for (double t = 0.5; t < tau - 1e-3; t += 0.5) {  // below the threshold before
      exact.phi(t, phi);
      REQUIRE(*std::max_element(phi.begin(), phi.end()) < zeta);
    }
  }
}

TEST_CASE("Figs. 3(c), 4(d), 5: RK4 points on the exact solution", "[figures]") {
  struct Case {
    const char* figure;
    const char* series;
    int spring;
    double gamma;
    bool sine;
    std::size_t panel = 0;
  };
  for (const Case& c : {Case{"fig3c", "\u03C6\u2081 RK4", 1, 0.0, true},
                        Case{"fig3c", "\u03C6\u2083\u2080 RK4", 30, 0.0, true},
                        Case{"fig4d", "\u03C6\u2081 RK4", 1, 0.01, false},
                        Case{"fig4d", "\u03C6\u2083\u2080 RK4", 30, 0.01, false},
                        Case{"fig5", "\u03C6\u2081 RK4", 1, 0.0, false},
                        Case{"fig5", "\u03C6\u2081 RK4 (inset)", 1, 0.0, false, 1}}) {
    cb::DriveDesc d = ramp();
    if (c.sine) {
      d.type = cb::DriveType::Sine;
      d.period = 120.0;
    }
    const cb::ExactChain exact(30, c.gamma, d);
    const cb::Series& s = series_of(built_figure(c.figure), c.series, c.panel);
    REQUIRE(s.x.size() > 50);
    for (std::size_t i = 0; i < s.x.size(); ++i) {
      INFO(c.figure << " " << c.series << " tau = " << s.x[i]);
      REQUIRE(s.y[i] == Approx(exact.phi(c.spring, s.x[i])).margin(1e-6));
    }
  }
}

TEST_CASE("Fig. 4(d): with friction phi_1 ends below phi_N (the caption)", "[figures]") {
  const cb::Figure& f = built_figure("fig4d");
  const cb::Series& first = series_of(f, "\u03C6\u2081 exact");
  const cb::Series& last = series_of(f, "\u03C6\u2083\u2080 exact");
  int compared = 0;
  for (std::size_t i = 0; i < first.x.size(); ++i)
    if (first.x[i] >= 200.0) {
      REQUIRE(first.y[i] < last.y[i]);
      ++compared;
    }
  CHECK(compared > 100);
  // Without friction it is the other way round there: Eq. (phi1) gives phi_1 = 2 (tau - 3N)
  // on 5N..7N, above phi_N = tau from 6N on (tau = 205: 230 > 205).
  CHECK(cb::continuum_phi1(30, 1.0, 205.0) > cb::continuum_phiN(1.0, 205.0));
  CHECK(cb::ExactChain(30, 0.0, ramp()).phi(1, 205.0) >
        cb::ExactChain(30, 0.0, ramp()).phi(30, 205.0));
}

TEST_CASE("Fig. 3: the continuum fields against independent forms", "[figures]") {
  // (b): the propagator against its defining sum, sum_n (-1)^n / N 2 sin(kappa tau) cos(kappa xi).
  const cb::Heatmap& h = built_figure("fig3b").panels[0].heatmap;
  REQUIRE(h.columns * h.rows == static_cast<int>(h.values.size()));
  for (int r = 3; r < h.rows; r += 37)
    for (int c = 1; c < h.columns; c += 13) {
      double sum = 0.0;
      for (int n = 0; n < 30; ++n) {
        const double kappa = (n + 0.5) * std::numbers::pi / 30.0;
        sum += (n % 2 ? -1.0 : 1.0) / 30.0 * 2.0 * std::sin(kappa * h.y_at(r)) *
               std::cos(kappa * h.x_at(c));
      }
      REQUIRE(h.values[static_cast<std::size_t>(r) * h.columns + c] ==
              Approx(sum).margin(1e-5));  // float storage
    }
  // (d): Eq. (dg) sends each kick as a unit pulse at unit speed, flipping sign at the free
  // end: the two meet at the middle spring at tau = 1.5 N with the same sign (the first one
  // reflected off the wall, the second on its way in) and at tau = 2.5 N with opposite signs.
  const cb::Heatmap& d = built_figure("fig3d").panels[0].heatmap;
  const auto largest_near = [&](double xi, double tau) {
    double m = 0.0;
    for (int r = 0; r < d.rows; ++r)
      for (int c = 0; c < d.columns; ++c)
        if (std::abs(d.x_at(c) - xi) < 0.3 && std::abs(d.y_at(r) - tau) < 0.3)
          m = std::max(m, std::abs(double(d.values[static_cast<std::size_t>(r) * d.columns + c])));
    return m;
  };
  CHECK(largest_near(15.0, 45.0) > 1.5);  // constructive: ~2
  CHECK(largest_near(15.0, 75.0) < 0.5);  // destructive: ~0
  CHECK(largest_near(15.0, 15.0) > 0.7);  // a single pulse on its way in: ~1
  // (a): psi of a step is d/dtau of psi of a unit ramp, Eq. (example) (gamma = 0, N terms;
  // Eq. (example) keeps xi exactly where the N-term sum has its sine series: <= 0.1 inside).
  for (double xi : {5.0, 10.0, 20.0})
    for (double tau : {10.0, 45.0, 77.0}) {
      const double h_tau = 1e-4;
      const double derivative = (cb::continuum_psi_series(30, 1.0, xi, tau + h_tau, 30) -
                                 cb::continuum_psi_series(30, 1.0, xi, tau - h_tau, 30)) /
                                (2 * h_tau);
      INFO("xi = " << xi << ", tau = " << tau);
      CHECK(cb::continuum_psi_step(30, 0.0, xi, tau) == Approx(derivative).margin(0.1));
    }
  // With friction it settles on the particular solution psi = xi (the caption of Fig. 3(a)).
  for (double xi : {5.0, 15.0, 25.0})
    CHECK(cb::continuum_psi_step(30, 0.01, xi, 5000.0) == Approx(xi).margin(0.15));
}

TEST_CASE("One-body map: the lower string first exactly when sin(1/beta) > 0", "[figures]") {
  const cb::Figure& f = built_figure("one_body_map");
  for (const char* name : {"exact", "RK4"}) {
    const cb::Series& s = series_of(f, name);
    int checked = 0;
    for (std::size_t i = 0; i < s.x.size(); ++i) {
      const double phase = 1.0 / s.x[i];  // Eq. (heald): T_up(1/beta) = 1 - beta sin(1/beta)
      if (std::abs(std::sin(phase)) < 1e-3) continue;  // at a window's edge: a tie
      INFO(name << ": beta = " << s.x[i]);
      CHECK(s.y[i] == (std::sin(phase) > 0 ? 0.0 : 1.0));
      ++checked;
    }
    CHECK(checked > 0.95 * s.x.size());
  }
  // Every window inside the range is drawn: m = 1 .. 15 for beta >= 0.01, and the jerk one.
  const cb::Series& windows =
      series_of(f, "anomalous windows 1/((2m+1)\u03C0) < \u03B2 < 1/(2m\u03C0)");
  CHECK(windows.x.size() == 15);
  for (std::size_t m = 1; m <= windows.x.size(); ++m) {
    CHECK(windows.x2[m - 1] == Approx(std::min(1.0 / (2 * m * std::numbers::pi), 10.0)));
  }
}
