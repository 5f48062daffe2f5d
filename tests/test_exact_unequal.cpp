// The exact solution of chains of unequal beads and springs (issue #21): LAPACK's modes
// (exact/chain_modes.h) in ExactChain and the first-break search, against
//   tests/data/J_unequal_N10_gamma0.01.json  (tests/exact_unequal_reference.py: mpmath at 40
//     digits, cross-checked with DOP853 to 6.5e-12; the first break located there independently),
//   tests/data/I0_unequal_N12_gamma0.json    (shared/reference: 40-digit modes, cross-checked
//     by a tight ODE integration to 1.4e-11),
// and the uniform chain's closed form reached through the general (LAPACK) path.
#include <catch2/catch.hpp>
#include <cmath>
#include <nlohmann/json.hpp>
#include <numbers>
#include <string>
#include <vector>

#include "app/run_rows.h"
#include "drive/drive.h"
#include "exact/chain_modes.h"
#include "exact/exact_chain.h"
#include "exact/first_break.h"
#include "overlay/modes.h"
#include "scene/scene.h"
#include "support/chain_test_support.h"

namespace {

using cb::test::load_test_data;
using cb::test::ramp_drive;
using nlohmann::json;

cb::ChainParams chain_from(const json& ref) {
  cb::ChainParams c;
  c.mass = ref["masses"].get<std::vector<double>>();
  c.stiffness = ref["stiffness"].get<std::vector<double>>();
  c.beads = static_cast<int>(c.mass.size());
  c.gamma = ref["gamma"].get<double>();
  if (ref.contains("thresholds")) c.thresholds = ref["thresholds"].get<std::vector<double>>();
  return c;
}

// max_j,tau |phi_j - ref| over a file's rows (key "phi" or "psi").
double worst_deviation(const cb::ExactChain& exact, const json& ref, const char* key) {
  const auto taus = ref["tau"].get<std::vector<double>>();
  const auto rows = ref[key].get<std::vector<std::vector<double>>>();
  double worst = 0.0;
  std::vector<double> values;
  for (std::size_t i = 0; i < taus.size(); ++i) {
    if (std::string(key) == "phi")
      exact.phi(taus[i], values);
    else
      exact.psi(taus[i], values);
    for (std::size_t j = 0; j < values.size(); ++j)
      worst = std::max(worst, std::abs(values[j] - rows[i][j]));
  }
  return worst;
}

// A uniform chain written with arrays of ones: normalize() is not called, so ExactChain takes
// the LAPACK path for what is the paper's chain.
cb::ChainParams unit_arrays(int beads, double gamma) {
  cb::ChainParams c;
  c.beads = beads;
  c.gamma = gamma;
  c.mass.assign(static_cast<std::size_t>(beads), 1.0);
  c.stiffness.assign(static_cast<std::size_t>(beads), 1.0);
  return c;
}

}  // namespace

TEST_CASE("Unequal chain J (N = 10, gamma = 0.01): phi and psi against mpmath",
          "[exact][unequal]") {
  const json ref = load_test_data("J_unequal_N10_gamma0.01.json");
  const cb::ChainParams chain = chain_from(ref);
  const cb::ExactChain exact(chain, ramp_drive(ref["beta"].get<double>()));
  REQUIRE_FALSE(exact.uniform());
  // Frequencies: LAPACK's against 40-digit eigenvalues, within chain_modes' stated bound.
  const auto omega2 = ref["omega2"].get<std::vector<double>>();
  const cb::ChainModes modes = cb::chain_modes(chain, chain.beads);
  for (int n = 0; n < chain.beads; ++n) {
    INFO("mode " << n);
    CHECK(std::abs(exact.frequency(n) * exact.frequency(n) - omega2[n]) <=
          modes.omega2_error + 4e-16 * omega2[n]);
  }
  // Values up to ~3 over tau <= 60; eps ||A|| / Omega_0^2 ~ 1e-14 relative: 1e-11 absolute is
  // the tolerance of the reference's own cross-check, with room.
  const double phi_err = worst_deviation(exact, ref, "phi");
  const double psi_err = worst_deviation(exact, ref, "psi");
  INFO("max |dphi| " << phi_err << ", max |dpsi| " << psi_err);
  CHECK(phi_err <= 1e-11);
  CHECK(psi_err <= 1e-11);
}

TEST_CASE("Unequal chain I0 (N = 12, gamma = 0): phi against shared/reference",
          "[exact][unequal]") {
  const json ref = load_test_data("I0_unequal_N12_gamma0.json");
  const cb::ExactChain exact(chain_from(ref), ramp_drive(ref["beta"].get<double>()));
  const double err = worst_deviation(exact, ref, "phi");
  INFO("max |dphi| " << err);
  // phi up to ~6 over tau <= 60; the reference agrees with an ODE integration to 1.4e-11.
  CHECK(err <= 1e-11);
}

TEST_CASE("Arrays of ones through LAPACK give the uniform chain's closed form",
          "[exact][unequal]") {
  // N = 30 and N = 1000: the general path's error is chain_modes' bound carried into phi,
  // ~ eps ||A|| / Omega_0^2 relative (||A|| = 4, Omega_0^2 = (pi / 2N)^2 roughly).
  for (int n : {30, 1000}) {
    const cb::ChainParams ones = unit_arrays(n, 0.01);
    const cb::ChainModes modes = cb::chain_modes(ones, n);
    double worst_omega2 = 0.0;
    for (int m = 0; m < n; ++m) {
      const double k = (m + 0.5) * std::numbers::pi / (n + 0.5);
      const double closed = 4.0 * std::sin(0.5 * k) * std::sin(0.5 * k);
      worst_omega2 = std::max(worst_omega2, std::abs(modes.omega2[m] - closed));
    }
    INFO("N = " << n << ": max |d Omega^2| " << worst_omega2 << ", stated bound "
                << modes.omega2_error);
    CHECK(worst_omega2 <= modes.omega2_error);

    if (n > 200) continue;  // the O(N^2) tables: the value check at N = 30 is enough
    const cb::ExactChain general(ones, ramp_drive(1.0)), closed(n, 0.01, ramp_drive(1.0));
    REQUIRE_FALSE(general.uniform());
    std::vector<double> a, b;
    for (double tau : {0.5, 7.0, 31.0, 80.0, 200.0}) {
      general.phi(tau, a);
      closed.phi(tau, b);
      double worst = 0.0, scale = 0.0;
      for (int j = 0; j < n; ++j) {
        worst = std::max(worst, std::abs(a[j] - b[j]));
        scale = std::max(scale, std::abs(b[j]));
      }
      // The stated estimate (ExactChain::mode_error) for the slowest mode, which dominates:
      // 2 e / gap + N eps + e (1 / Omega_0^2 + tau / (2 Omega_0)) relative. Measured: 1.3e-12
      // of phi at tau = 200, 36x inside it (e itself, 4 sqrt(N) eps ||A||, is 5x the measured
      // eigenvalue error); an estimate 100x smaller fails here.
      INFO("tau " << tau << ": max |dphi| " << worst << " of max |phi| " << scale << ", estimate "
                  << general.mode_error(0, tau) * scale);
      CHECK(worst <= general.mode_error(0, tau) * scale);
    }
  }
}

TEST_CASE("Arrays of ones give the uniform chain's first breaks", "[first_break][unequal]") {
  for (double zeta : {3.7, 25.3, 61.0}) {
    cb::ChainParams ones = unit_arrays(30, 0.0);
    ones.threshold = zeta;
    ones.thresholds.assign(30, zeta);  // a threshold array of equal values, not normalized
    cb::ChainParams plain;
    plain.beads = 30;
    plain.threshold = zeta;
    const cb::FirstBreak a = cb::exact_first_break(ones, ramp_drive(1.0), 400.0);
    const cb::FirstBreak b = cb::exact_first_break(plain, ramp_drive(1.0), 400.0);
    INFO("zeta " << zeta << ": arrays spring " << a.spring << " at " << a.tau << ", uniform "
                 << b.spring << " at " << b.tau);
    REQUIRE(a.broke);
    REQUIRE(b.broke);
    CHECK(a.spring == b.spring);
    CHECK(std::abs(a.tau - b.tau) <= 1e-9 * b.tau);
  }
}

TEST_CASE("A weak link: the first break against the independently located one",
          "[first_break][unequal]") {
  const json ref = load_test_data("J_unequal_N10_gamma0.01.json");
  const cb::DriveDesc drive = ramp_drive(ref["beta"].get<double>());
  const json& expected = ref["first_break"];
  const json& one = ref["first_break_one_threshold"];
  cb::ChainParams chain = chain_from(ref);
  chain.threshold = one["threshold"].get<double>();  // the pull string's; none here

  // The script bisects its crossing to 1e-25 at 40 digits; ours is polished to ~1e-12 and
  // carries LAPACK's relative error (1e-14 here) divided by phi' ~ 0.1: 1e-10 in time.
  const cb::FirstBreak weak = cb::exact_first_break(chain, drive, expected["t_end"].get<double>());
  INFO("weak link: spring " << weak.spring << " at " << weak.tau);
  REQUIRE(weak.broke);
  CHECK(weak.spring == expected["spring"].get<int>());
  CHECK(std::abs(weak.tau - expected["tau"].get<double>()) <= 1e-10);

  // The same chain with one threshold breaks elsewhere, later.
  cb::ChainParams even = chain;
  even.thresholds.clear();
  const cb::FirstBreak plain = cb::exact_first_break(even, drive, expected["t_end"].get<double>());
  INFO("one threshold: spring " << plain.spring << " at " << plain.tau);
  REQUIRE(plain.broke);
  CHECK(plain.spring == one["spring"].get<int>());
  CHECK(std::abs(plain.tau - one["tau"].get<double>()) <= 1e-10);

  // The breaking map of this chain at zeta_c = min phi_c / beta is the same question.
  const double zeta = 0.5 / ref["beta"].get<double>();
  const auto map = cb::breaking_map(chain, {zeta}, expected["t_end"].get<double>() * 2.0);
  REQUIRE(map[0].broke);
  CHECK(map[0].spring == expected["spring"].get<int>());
  // Eq. (rescale2): phi is linear in beta, so the unit ramp reaches zeta_c at the same tau.
  CHECK(std::abs(map[0].tau - expected["tau"].get<double>()) <= 1e-9);
}

TEST_CASE("continuum refuses a chain of unequal beads or springs", "[exact][unequal]") {
  cb::SceneDesc scene;
  scene.path = "heavy.toml";
  scene.drive = ramp_drive(0.1);
  scene.integrator.t_end = 10.0;
  cb::RunRequest request;
  request.solver = cb::Solver::Continuum;
  CHECK_NOTHROW(cb::check_run_request(scene, request));  // the uniform chain: Eq. (sum)
  scene.chain.mass.assign(30, 1.0);
  scene.chain.mass[10] = 4.0;
  try {
    cb::check_run_request(scene, request);
    FAIL("an unequal chain was accepted by the continuum solver");
  } catch (const cb::SceneError& e) {
    const std::string what = e.what();
    INFO(what);
    CHECK(what.find("heavy.toml") != std::string::npos);      // where
    CHECK(what.find("uniform chain") != std::string::npos);   // what
    CHECK(what.find("--solver exact") != std::string::npos);  // how to fix
  }
  request.solver = cb::Solver::Exact;
  CHECK_NOTHROW(cb::check_run_request(scene, request));
}

TEST_CASE("Mode bars of an unequal chain: the chain's own modes carry its energy",
          "[overlay][unequal]") {
  // With all N modes, sum_n A_n^2 / 2 = sum_j (m_j psi_j'^2 + K_j phi_j^2) / 2 for any state:
  // true only if the shapes are mass-orthonormal eigenvectors of K with eigenvalues Omega_n^2.
  const json ref = load_test_data("I0_unequal_N12_gamma0.json");
  const cb::ChainParams chain = chain_from(ref);
  const int n = chain.beads;
  cb::ChainState state;
  for (int j = 1; j <= n; ++j) {  // an arbitrary state
    state.psi.push_back(std::sin(1.3 * j) + 0.1 * j);
    state.vel.push_back(std::cos(0.7 * j * j));
  }
  double energy = 0.0;
  for (int j = 1; j <= n; ++j)
    energy += 0.5 * chain.mass_of(j) * state.vel[j - 1] * state.vel[j - 1] +
              0.5 * chain.stiffness_of(j) * cb::extension(state, j) * cb::extension(state, j);
  const cb::ModeBasis basis(chain, n);
  std::vector<double> amplitude;
  basis.amplitudes(state, amplitude);
  REQUIRE(amplitude.size() == static_cast<std::size_t>(n));
  double modal = 0.0;
  for (double a : amplitude) modal += 0.5 * a * a;
  INFO("energy " << energy << ", modal " << modal);
  CHECK(std::abs(modal - energy) <= 1e-13 * energy);

  // The sine basis is not this chain's: it gives another split (and another sum).
  std::vector<double> sines;
  cb::mode_amplitudes(state, n, sines);
  CHECK(std::abs(sines[0] - amplitude[0]) > 1e-3 * amplitude[0]);
}

TEST_CASE("run --solver exact: an unequal chain's energy is the drive's work", "[exact][unequal]") {
  // gamma = 0: sum_j (m_j psi_j'^2 + K_j phi_j^2) / 2 = W(tau) = int_0^tau f psi_N' dt
  // = beta (tau psi_N(tau) - int_0^tau psi_N dt) for f = beta t; the integral by Simpson on
  // psi_N at step 0.005 (error ~1e-12 here). Only right with the masses and stiffnesses in the
  // energy books.
  const json ref = load_test_data("I0_unequal_N12_gamma0.json");
  cb::SceneDesc scene;
  scene.path = "i0.toml";
  scene.chain = chain_from(ref);
  const double beta = ref["beta"].get<double>();
  scene.drive = ramp_drive(beta);
  scene.integrator.dt = 0.01;
  scene.integrator.t_end = 40.0;
  struct Rows : cb::RowSink {
    std::vector<double> tau, energy;
    void begin(int, bool, std::int64_t) override {}
    void row(const cb::RunRow& r) override {
      tau.push_back(r.tau);
      energy.push_back(r.energy);
    }
  } rows;
  cb::RunRequest request;
  request.solver = cb::Solver::Exact;
  request.every = 500;  // tau = 0, 5, ..., 40
  REQUIRE(cb::run_scene(scene, request, &rows).status == 0);
  REQUIRE(rows.tau.size() == 9);
  const cb::ExactChain exact(scene.chain, scene.drive);
  const int n = scene.chain.beads;
  const double cube = static_cast<double>(n) * n * n;  // rows are per particle, Eq. (energy)
  for (std::size_t i = 1; i < rows.tau.size(); ++i) {
    const double tau = rows.tau[i];
    const int steps = static_cast<int>(std::lround(tau / 0.005));
    const double h = tau / steps;
    double integral = exact.psi(n, 0.0) + exact.psi(n, tau);
    for (int k = 1; k < steps; ++k) integral += (k % 2 ? 4.0 : 2.0) * exact.psi(n, k * h);
    integral *= h / 3.0;
    const double work = beta * (tau * exact.psi(n, tau) - integral);
    INFO("tau " << tau << ": energy " << rows.energy[i] * cube << ", work " << work);
    CHECK(std::abs(rows.energy[i] * cube - work) <= 1e-9 * work);
  }
}

TEST_CASE("One heavy bead on a soft spring: a step's response in closed form", "[exact][unequal]") {
  // N = 1, m = 4, K = 0.25, gamma = 0, f = 1 for tau > 0: psi = (1 - cos(Omega tau)) / K with
  // Omega = sqrt(K / m) = 1/4 (the smallest LAPACK problem, against the textbook oscillator).
  cb::ChainParams chain;
  chain.beads = 1;
  chain.mass = {4.0};
  chain.stiffness = {0.25};
  cb::DriveDesc step;
  step.type = cb::DriveType::Step;
  step.amplitude = 1.0;
  const cb::ExactChain exact(chain, step);
  CHECK(std::abs(exact.frequency(0) - 0.25) <= 1e-15);
  for (double tau : {0.3, 2.0, 11.0, 40.0}) {
    const double expected = (1.0 - std::cos(0.25 * tau)) / 0.25;
    INFO("tau " << tau);
    CHECK(std::abs(exact.psi(1, tau) - expected) <= 1e-13 * (1.0 + expected));
    CHECK(std::abs(exact.phi(1, tau) - expected) <= 1e-13 * (1.0 + expected));
  }
}
