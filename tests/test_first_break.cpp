// The exact first break (src/exact/first_break): against a brute-force dense scan of the
// exact phi, the one-body experiment of Eq. (heald), and the breaking map of Fig. 4(c).
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "drive/drive.h"
#include "exact/exact_chain.h"
#include "exact/first_break.h"
#include "physics/chain.h"

namespace {

constexpr double kPi = std::numbers::pi;

cb::DriveDesc ramp(double beta, double t0 = 0.0) {
  cb::DriveDesc d;
  d.type = cb::DriveType::Ramp;
  d.beta = beta;
  d.t0 = t0;
  return d;
}

cb::ChainParams chain_of(int beads, double gamma, double threshold,
                         cb::BreakMode mode = cb::BreakMode::Abs) {
  cb::ChainParams p;
  p.beads = beads;
  p.gamma = gamma;
  p.threshold = threshold;
  p.break_on = mode;
  return p;
}

// Brute force: sample every phi_j every `dt` from 0; at the first sample where a spring is
// at the threshold, the spring whose linearly interpolated crossing is earliest. Any chain
// (unequal beads and springs through ExactChain's LAPACK modes), per-spring thresholds.
cb::FirstBreak dense_first_break(const cb::ChainParams& p, const cb::DriveDesc& d, double t_end,
                                 double dt) {
  const cb::ExactChain chain(p, d);
  const bool abs = p.break_on == cb::BreakMode::Abs;
  std::vector<double> prev(p.beads, 0.0), now;
  for (long k = 1; k * dt <= t_end; ++k) {
    const double tau = k * dt;
    chain.phi(tau, now);
    cb::FirstBreak best;
    best.tau = tau + 1.0;
    for (int j = 0; j < p.beads; ++j)
      for (double s : {1.0, -1.0}) {
        if (s < 0 && !abs) continue;
        const double c = p.threshold_of(j + 1);
        if (s * now[j] < c) continue;
        const double t = tau - dt * (s * now[j] - c) / (s * now[j] - s * prev[j]);
        if (t < best.tau) best = {true, j + 1, t};
      }
    if (best.broke) return best;
    prev = now;
  }
  return {};
}

// Eq. (heald) with T_c = 1: the upper string beta (tau - sin tau) reaches 1 at the root found
// here by bisection (tau - sin tau is non-decreasing, so the first crossing is the only one).
double upper_string_time(double beta) {
  double lo = 0.0, hi = 1.0 / beta + 2.0;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (beta * (mid - std::sin(mid)) >= 1.0 ? hi : lo) = mid;
  }
  return hi;
}

}  // namespace

TEST_CASE("First break of a ramp agrees with a dense scan of the exact phi", "[first_break]") {
  // Dense step 2e-3: the dense scan locates a crossing to within dt; it could only miss a
  // peak that overshoots the threshold by < |phi''| dt^2 / 8 ~ 1e-6, not the case for these zeta.
  const double dt = 2e-3;
  for (double gamma : {0.0, 0.01})
    for (double zeta : {3.7, 25.3, 61.0, 97.5, 133.3}) {
      const auto p = chain_of(30, gamma, zeta);
      const auto exact = cb::exact_first_break(p, ramp(1.0), 400.0);
      const auto dense = dense_first_break(p, ramp(1.0), 400.0, dt);
      INFO("gamma " << gamma << " zeta " << zeta << ": exact spring " << exact.spring << " at "
                    << exact.tau << ", dense " << dense.spring << " at " << dense.tau);
      REQUIRE(exact.broke);
      CHECK(exact.spring == dense.spring);
      CHECK(std::abs(exact.tau - dense.tau) <= dt);
      // The located time is a root of the exact phi: 1e-9 of zeta.
      CHECK(std::abs(std::abs(cb::ExactChain(30, gamma, ramp(1.0)).phi(exact.spring, exact.tau)) -
                     zeta) <= 1e-9 * zeta);
    }
}

TEST_CASE("First break of other drives agrees with a dense scan", "[first_break]") {
  const double dt = 1e-3;
  cb::DriveDesc sine, kicks, step, table;
  sine.type = cb::DriveType::Sine;
  sine.amplitude = 2.0;
  sine.period = 23.0;
  kicks.type = cb::DriveType::Impulses;
  kicks.times = {0.0, 3.3, 7.1};
  kicks.strengths = {1.0, 1.0, -2.0};
  step.type = cb::DriveType::Step;
  step.amplitude = 1.0;
  step.t0 = 1.5;
  table.type = cb::DriveType::Table;
  table.table = {{0.0, 0.0}, {4.0, 3.0}, {6.0, -1.0}};
  struct Case {
    cb::DriveDesc drive;
    cb::ChainParams chain;
  };
  const std::vector<Case> cases = {
      {sine, chain_of(8, 0.02, 1.9)}, {sine, chain_of(8, 0.0, 2.2, cb::BreakMode::Stretch)},
      {kicks, chain_of(8, 0.0, 0.8)}, {kicks, chain_of(8, 0.05, 0.7, cb::BreakMode::Stretch)},
      {step, chain_of(10, 0.0, 1.5)}, {step, chain_of(10, 1.3, 0.9)},  // over-damped low modes
      {table, chain_of(6, 0.1, 1.6)}, {table, chain_of(6, 0.0, 1.8, cb::BreakMode::Stretch)},
  };
  for (const auto& c : cases) {
    const auto exact = cb::exact_first_break(c.chain, c.drive, 120.0);
    const auto dense = dense_first_break(c.chain, c.drive, 120.0, dt);
    INFO(cb::drive_type_name(c.drive.type)
         << " N " << c.chain.beads << " gamma " << c.chain.gamma << ": exact spring "
         << exact.spring << " at " << exact.tau << ", dense " << dense.spring << " at "
         << dense.tau);
    REQUIRE(exact.broke == dense.broke);
    CHECK(exact.spring == dense.spring);
    CHECK(std::abs(exact.tau - dense.tau) <= dt);
  }
}

TEST_CASE("A threshold a hair below the highest peak is found, a hair above is not",
          "[first_break]") {
  // The scan samples every 0.25; a peak that pokes 1e-9 above the threshold is ~1e-4 wide,
  // so it is found only if the interpolation bound really bounds phi between samples.
  cb::DriveDesc sine;
  sine.type = cb::DriveType::Sine;
  sine.period = 11.0;
  const cb::ExactChain chain(8, 0.0, sine);
  const double t_end = 30.0;
  // The highest |phi_j| on [0, t_end]: a dense scan, then bisection on phi_j' = 0.
  std::vector<double> phi;
  double peak = 0.0, peak_tau = 0.0;
  int spring = 0;
  for (double tau = 0.0; tau <= t_end; tau += 1e-3) {
    chain.phi(tau, phi);
    for (int j = 0; j < 8; ++j)
      if (std::abs(phi[j]) > peak) {
        peak = std::abs(phi[j]);
        peak_tau = tau;
        spring = j + 1;
      }
  }
  std::vector<double> rate;
  auto slope_sign = [&](double tau) {
    chain.phi_rate(tau, rate);
    return rate[spring - 1] * (chain.phi(spring, peak_tau) > 0 ? 1.0 : -1.0);
  };
  double lo = peak_tau - 1e-3, hi = peak_tau + 1e-3;
  REQUIRE(slope_sign(lo) > 0.0);
  REQUIRE(slope_sign(hi) < 0.0);
  for (int i = 0; i < 100; ++i) (slope_sign(0.5 * (lo + hi)) > 0.0 ? lo : hi) = 0.5 * (lo + hi);
  peak_tau = 0.5 * (lo + hi);
  peak = std::abs(chain.phi(spring, peak_tau));
  INFO("peak |phi_" << spring << "| = " << peak << " at tau = " << peak_tau);
  const auto below = cb::exact_first_break(chain_of(8, 0.0, peak * (1 - 1e-9)), sine, t_end);
  CHECK(below.spring == spring);
  CHECK(std::abs(below.tau - peak_tau) < 1e-3);  // sqrt(2e-9 peak / |phi''|) ~ 1e-4
  CHECK_FALSE(cb::exact_first_break(chain_of(8, 0.0, peak * (1 + 1e-9)), sine, t_end).broke);
}

TEST_CASE("A pull string breaks when f reaches phi_c, unless a spring is first", "[first_break]") {
  // A fast ramp: the string (spring 0) at tau = t0 + phi_c / beta exactly.
  auto p = chain_of(30, 0.0, 5.0);
  p.pull_string = true;
  auto fb = cb::exact_first_break(p, ramp(3.0, 2.0), 100.0);
  CHECK(fb.spring == 0);
  CHECK(fb.tau == Approx(2.0 + 5.0 / 3.0).epsilon(1e-15));
  // Without the string the same chain breaks a spring later.
  p.pull_string = false;
  fb = cb::exact_first_break(p, ramp(3.0, 2.0), 100.0);
  CHECK(fb.spring >= 1);
  CHECK(fb.tau > 2.0 + 5.0 / 3.0);
  // Nothing breaks before t_end.
  CHECK_FALSE(cb::exact_first_break(p, ramp(3.0, 2.0), 3.0).broke);
  // A sine 2 sin(2 pi tau / 20) reaches 1 at tau = 20 / 12; a table 0 -> 3 over 4 at 4/3 + t0.
  p.pull_string = true;
  p.threshold = 1.0;
  cb::DriveDesc sine, table;
  sine.type = cb::DriveType::Sine;
  sine.amplitude = 2.0;
  sine.period = 20.0;
  fb = cb::exact_first_break(p, sine, 100.0);
  CHECK(fb.spring == 0);
  CHECK(fb.tau == Approx(20.0 / 12.0).epsilon(1e-14));
  table.type = cb::DriveType::Table;
  table.table = {{0.0, 0.0}, {4.0, 3.0}};
  table.t0 = 0.5;
  fb = cb::exact_first_break(p, table, 100.0);
  CHECK(fb.spring == 0);
  CHECK(fb.tau == Approx(0.5 + 4.0 / 3.0).epsilon(1e-14));
}

TEST_CASE("One body: the string breaks first exactly when sin(1/beta) > 0", "[first_break]") {
  // N = 1 is the ball of Fig. 1: phi_1 = beta (tau - sin tau), string f = beta tau, phi_c = 1.
  auto p = chain_of(1, 0.0, 1.0);
  p.pull_string = true;
  const auto windows = cb::one_body_jerk_windows(5);
  REQUIRE(windows.size() == 5);
  for (int m = 0; m <= 4; ++m) {
    CHECK(windows[m].lo == Approx(1.0 / ((2 * m + 1) * kPi)).epsilon(1e-15));
    if (m > 0) CHECK(windows[m].hi == Approx(1.0 / (2 * m * kPi)).epsilon(1e-15));
    // Well inside the window, 1/beta = (2m + 1/2) pi: the string, at tau = 1/beta.
    const double inside = 1.0 / ((2 * m + 0.5) * kPi);
    auto fb = cb::exact_first_break(p, ramp(inside), 500.0);
    INFO("m " << m);
    CHECK(fb.spring == 0);
    CHECK(fb.tau == Approx(1.0 / inside).epsilon(1e-14));
    // Well outside, 1/beta = (2m + 3/2) pi: the upper spring, at the root of Eq. (heald)
    // (bisection above, to 1e-10).
    const double outside = 1.0 / ((2 * m + 1.5) * kPi);
    fb = cb::exact_first_break(p, ramp(outside), 500.0);
    CHECK(fb.spring == 1);
    CHECK(fb.tau == Approx(upper_string_time(outside)).margin(1e-10));
    // Just inside and just outside both edges of the window (1% of the edge).
    CHECK(cb::exact_first_break(p, ramp(windows[m].lo * 1.01), 500.0).spring == 0);
    CHECK(cb::exact_first_break(p, ramp(windows[m].lo * 0.99), 500.0).spring == 1);
    if (m > 0) {
      CHECK(cb::exact_first_break(p, ramp(windows[m].hi * 0.99), 500.0).spring == 0);
      CHECK(cb::exact_first_break(p, ramp(windows[m].hi * 1.01), 500.0).spring == 1);
    }
  }
}

TEST_CASE("The breaking map of Fig. 4(c): N = 30, gamma = 0", "[first_break]") {
  std::vector<double> zeta;
  for (int i = 0; i < 420; ++i) zeta.push_back(1.0 + 299.0 * i / 419.0);
  const auto map = cb::breaking_map(30, 0.0, cb::BreakMode::Abs, zeta, 1000.0);
  REQUIRE(map.size() == zeta.size());
  for (std::size_t i = 0; i < zeta.size(); ++i) {
    INFO("zeta " << zeta[i] << " spring " << map[i].spring);
    REQUIRE(map[i].broke);
    // The map is one sweep for all zeta: each entry is the single-threshold answer.
    if (i % 60 == 0) {
      const auto one = cb::exact_first_break(chain_of(30, 0.0, zeta[i]), ramp(1.0), 1000.0);
      CHECK(one.spring == map[i].spring);
      CHECK(one.tau == Approx(map[i].tau).margin(1e-9));
    }
    // Large beta (small zeta_c): spring N, the earliest to extend (bottom arrow).
    if (zeta[i] < 40.0) CHECK(map[i].spring == 30);
    // 2N < zeta_c < 4N: phi_1 ~ 2 (tau - N) overtakes phi_N ~ tau: a spring nearer the
    // wall (middle arrow); the continuum says every j <= xi* ties, the exact chain picks one.
    if (zeta[i] > 70.0 && zeta[i] < 110.0) CHECK(map[i].spring != 30);
  }
  // Anomalous breaking (top arrow): spring N again at a larger zeta_c, i.e. a smaller beta.
  // The continuum puts the first such window at 4N < zeta_c < 6N, while phi_1 rests at 4N
  // (Eq. (phi1)); the exact chain is O(1) off the continuum, hence the margins of 10.
  std::size_t i = 0;
  while (i < map.size() && map[i].spring == 30) ++i;
  while (i < map.size() && map[i].spring != 30) ++i;
  REQUIRE(i < map.size());
  const double start = zeta[i];
  while (i < map.size() && map[i].spring == 30) ++i;
  REQUIRE(i < map.size());
  const double end = zeta[i];
  INFO("anomalous window " << start << " <= zeta_c < " << end);
  CHECK(start > 4.0 * 30 - 10.0);
  CHECK(start < 4.0 * 30 + 10.0);
  CHECK(end > 6.0 * 30 - 10.0);
  CHECK(end < 6.0 * 30 + 10.0);
}

TEST_CASE("Stretch mode ignores compression, expr drives are refused", "[first_break]") {
  cb::DriveDesc push;
  push.type = cb::DriveType::Step;
  push.amplitude = -1.5;
  CHECK_FALSE(
      cb::exact_first_break(chain_of(5, 0.0, 1.0, cb::BreakMode::Stretch), push, 50.0).broke);
  const auto abs = cb::exact_first_break(chain_of(5, 0.0, 1.0), push, 50.0);
  CHECK(abs.spring == 5);  // the driven spring is compressed first
  CHECK_FALSE(cb::exact_first_break(cb::ChainParams{}, push, 50.0).broke);  // unbreakable
  cb::DriveDesc expr;
  expr.type = cb::DriveType::Expr;
  expr.expr = "t";
  CHECK_THROWS_AS(cb::exact_first_break(chain_of(5, 0.0, 1.0), expr, 50.0), std::invalid_argument);
}

TEST_CASE("Per-spring thresholds and unequal chains agree with a dense scan",
          "[first_break][unequal]") {
  // A weak link in the paper's chain (closed-form modes) and a heavy bead with a stiff segment
  // (LAPACK's modes), both with a lower threshold at spring 12, under fast and slow ramps.
  const double dt = 2e-3;
  for (bool unequal : {false, true})
    for (double gamma : {0.0, 0.01})
      for (double zeta : {5.0, 100.0, 160.0}) {
        cb::ChainParams p = chain_of(30, gamma, zeta);
        p.thresholds.assign(30, zeta);
        p.thresholds[11] = 0.7 * zeta;
        if (unequal) {
          p.mass.assign(30, 1.0);
          p.mass[19] = 5.0;
          p.stiffness.assign(30, 1.0);
          for (int j = 5; j < 10; ++j) p.stiffness[j] = 3.0;
        }
        const auto exact = cb::exact_first_break(p, ramp(1.0), 400.0);
        const auto dense = dense_first_break(p, ramp(1.0), 400.0, dt);
        INFO("unequal " << unequal << " gamma " << gamma << " zeta " << zeta << ": exact spring "
                        << exact.spring << " at " << exact.tau << ", dense " << dense.spring
                        << " at " << dense.tau);
        REQUIRE(exact.broke);
        CHECK(exact.spring == dense.spring);
        CHECK(std::abs(exact.tau - dense.tau) <= dt);
        // The located time is a root of the exact phi at that spring's own threshold.
        const double c = p.threshold_of(exact.spring);
        CHECK(std::abs(std::abs(cb::ExactChain(p, ramp(1.0)).phi(exact.spring, exact.tau)) - c) <=
              1e-9 * c);
      }
}
