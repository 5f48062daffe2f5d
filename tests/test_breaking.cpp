// Breaking, Eq. (break): where the integrator locates a crossing, what a broken spring does,
// and the one-body pull-or-jerk experiment of the paper's introduction, Eq. (heald).
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <random>

#include "drive/drive.h"
#include "exact/first_break.h"
#include "physics/crossing.h"
#include "physics/energy.h"
#include "physics/integrator.h"

namespace {

cb::DriveDesc ramp(double beta) {
  cb::DriveDesc d;
  d.type = cb::DriveType::Ramp;
  d.beta = beta;
  return d;
}

// Runs until the first break (or max_tau) and returns it; spring -1 when nothing broke.
cb::BreakEvent first_break(const cb::ChainParams& p, const cb::DriveDesc& d, double dt,
                           double max_tau) {
  cb::Integrator sim(p, cb::make_forcing(d), {dt, 1});
  const auto last = std::llround(max_tau / dt);
  while (sim.state().breaks.empty() && sim.state().step < last) REQUIRE(sim.step());
  return sim.state().breaks.empty() ? cb::BreakEvent{-1, 0.0, 0} : sim.state().breaks.front();
}

cb::ChainParams one_body(double threshold = 1.0) {
  cb::ChainParams p;
  p.beads = 1;
  p.threshold = threshold;
  p.pull_string = true;
  return p;
}

// The upper string of the one-body experiment: psi = beta (tau - sin tau) (Eq. (heald) in
// dimensionless form) reaches 1 at the root of beta (tau - sin tau) - 1, found by bisection
// on that closed form (independent of the integrator).
double upper_string_time(double beta) {
  double lo = 0.0, hi = 1.0 / beta + 2.0;  // tau - sin tau >= tau - 1 reaches 1/beta by then
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    // tau - sin tau is nondecreasing, so the first crossing is the only sign change.
    (beta * (mid - std::sin(mid)) >= 1.0 ? hi : lo) = mid;
  }
  return hi;
}

}  // namespace

TEST_CASE("One body: the lower string breaks first exactly when sin(1/beta) > 0", "[breaking]") {
  // Inside the m-th window 1/beta = (2m + 1/2) pi the lower string (spring 0) must break, at
  // tau = 1/beta; between windows, 1/beta = (2m + 3/2) pi, the upper string (spring 1)
  // breaks first. m = 1 is the paper's anomalous window [alpha_c/3, alpha_c/2].
  for (int m = 0; m <= 4; ++m) {
    const double jerk_beta = 1.0 / ((2 * m + 0.5) * M_PI);
    const auto jerk = first_break(one_body(), ramp(jerk_beta), 0.01, 200.0);
    INFO("m = " << m << ", beta = " << jerk_beta);
    CHECK(jerk.spring == 0);
    CHECK(jerk.tau == Approx(1.0 / jerk_beta).margin(1e-9));

    const double pull_beta = 1.0 / ((2 * m + 1.5) * M_PI);
    const auto pull = first_break(one_body(), ramp(pull_beta), 0.01, 200.0);
    INFO("beta = " << pull_beta);
    CHECK(pull.spring == 1);
    // Located by Hermite interpolation: O(h^4) ~ 1e-8; the issue asks for 1e-6.
    CHECK(pull.tau == Approx(upper_string_time(pull_beta)).margin(1e-6));
  }
}

TEST_CASE("The windows of one_body_jerk_windows agree with the integrator", "[breaking]") {
  const auto windows = cb::one_body_jerk_windows(4);
  REQUIRE(windows.size() == 4);
  for (std::size_t m = 1; m < windows.size(); ++m) {
    const auto& w = windows[m];
    // sin(1/beta) > 0 <=> 1/beta in (2 m pi, (2m+1) pi).
    CHECK(w.lo == Approx(1.0 / ((2 * m + 1) * M_PI)).epsilon(1e-12));
    CHECK(w.hi == Approx(1.0 / (2 * m * M_PI)).epsilon(1e-12));
    const double inside = std::sqrt(w.lo * w.hi), below = w.lo * 0.97, above = w.hi * 1.03;
    CHECK(first_break(one_body(), ramp(inside), 0.01, 400.0).spring == 0);
    CHECK(first_break(one_body(), ramp(below), 0.01, 400.0).spring == 1);
    CHECK(first_break(one_body(), ramp(above), 0.01, 400.0).spring == 1);
  }
}

TEST_CASE("The located first break matches the exact solution within 1e-6 at dt = 0.01",
          "[breaking]") {
  // N = 30 ramp chains: the exact first break comes from root finding on the exact modal
  // solution (src/exact), the simulated one from RK4 + Hermite location.
  for (double gamma : {0.0, 0.01}) {
    for (double zeta : {12.0, 45.0, 75.0, 150.0, 250.0}) {
      cb::ChainParams p;
      p.beads = 30;
      p.gamma = gamma;
      p.threshold = zeta;
      const auto exact = cb::exact_first_break(p, ramp(1.0), 600.0);
      const auto sim = first_break(p, ramp(1.0), 0.01, 600.0);
      INFO("gamma " << gamma << " zeta_c " << zeta);
      REQUIRE(exact.broke);
      CHECK(sim.spring == exact.spring);
      CHECK(sim.tau == Approx(exact.tau).margin(1e-6));
    }
  }
}

TEST_CASE("A broken spring exerts no force, later breaks are recorded in order", "[breaking]") {
  // A fast ramp breaks spring N first (paper, Fig. 4(c), small zeta_c). From then on bead N
  // is free: with gamma = 0 its velocity grows by int beta tau dtau = beta (t^2 - tb^2) / 2.
  cb::ChainParams p;
  p.beads = 10;
  p.threshold = 2.0;
  const double beta = 1.0;
  cb::Integrator sim(p, cb::make_forcing(ramp(beta)), {0.01, 1});
  while (sim.state().breaks.empty()) REQUIRE(sim.step());
  const auto first = sim.state().breaks.front();
  REQUIRE(first.spring == 10);
  REQUIRE(sim.advance_to(sim.state().step + 1000));
  // Velocity of bead N at the break, from the step's end state minus what the free ramp
  // added since: compare two later times instead, which avoids needing it.
  const double t1 = sim.state().tau, v1 = sim.state().vel[9];
  REQUIRE(sim.advance_to(sim.state().step + 500));
  const double t2 = sim.state().tau, v2 = sim.state().vel[9];
  CHECK(v2 - v1 == Approx(0.5 * beta * (t2 * t2 - t1 * t1)).epsilon(1e-10));
  // The books still close with the broken spring's energy written off.
  CHECK(cb::energy_balance_error(sim.state()) < 1e-8);
  // Keep pulling the rest of the chain? It is now unloaded; but the wall side still rings
  // and may break later: events must stay in time order.
  const auto& breaks = sim.state().breaks;
  for (std::size_t i = 1; i < breaks.size(); ++i) CHECK(breaks[i].tau >= breaks[i - 1].tau);
}

TEST_CASE("Stretch mode ignores compression", "[breaking]") {
  // A step pulled chain with a negative amplitude only compresses springs; with "stretch"
  // nothing breaks, with "abs" the same magnitude breaks spring N at once.
  cb::DriveDesc push;
  push.type = cb::DriveType::Step;
  push.amplitude = -1.5;
  cb::ChainParams p;
  p.beads = 5;
  p.threshold = 1.0;
  p.break_on = cb::BreakMode::Stretch;
  CHECK(first_break(p, push, 0.01, 50.0).spring == -1);
  p.break_on = cb::BreakMode::Abs;
  CHECK(first_break(p, push, 0.01, 50.0).spring >= 1);
}

TEST_CASE("Breaking: a crossing inside a step is located to the last bit", "[breaking]") {
  // On a step of h = 1 the returned time is s itself: the cubic Hermite interpolant reaches a
  // bound at s and not at the double just below it (bisection to neighbouring doubles, which
  // the search stops at once it gets there). Below s = 1/8 the search stops at a width of
  // 1e-17 instead, so those are not checked. Any inputs serve: the property holds for each.
  const double inf = std::numeric_limits<double>::infinity();
  std::mt19937_64 rng(2026);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int checked = 0;
  for (int i = 0; i < 100000; ++i) {
    const double upper = 1.0 + 0.5 * u(rng), lower = i % 2 ? -upper : -inf;
    const double p0 = 0.9 * u(rng), p1 = upper + 0.2 * u(rng), m0 = 3 * u(rng), m1 = 3 * u(rng);
    const double s = cb::detail::hermite_first_crossing(p0, p1, m0, m1, 1.0, upper, lower);
    if (s < 0.125) continue;
    const double a = p0, b = m0, q = -3.0 * p0 - 2.0 * m0 + 3.0 * p1 - m1,
                 d = 2.0 * p0 + m0 - 2.0 * p1 + m1;
    const auto reached = [&](double x) {
      const double p = a + x * (b + x * (q + x * d));
      return p - upper >= 0.0 || lower - p >= 0.0;
    };
    CHECK(reached(s));
    CHECK_FALSE(reached(std::nextafter(s, 0.0)));
    ++checked;
  }
  CHECK(checked > 20000);
}
