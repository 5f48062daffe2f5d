// The RK4 integrator against the independent reference values of shared/reference
// (exact modal expansion in 160-digit arithmetic, copied into tests/data), and its own
// invariants: fourth-order convergence, the energy books, thread independence.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <nlohmann/json.hpp>

#include "drive/drive.h"
#include "physics/energy.h"
#include "physics/integrator.h"
#include "support/chain_test_support.h"

namespace {

cb::ChainParams chain(int n, double gamma) {
  cb::ChainParams p;
  p.beads = n;
  p.gamma = gamma;
  return p;
}

std::int64_t steps_to(double tau, double dt) {
  return std::llround(tau / dt);
}

// |x - ref| <= atol + rtol |ref|, the comparison the reference README prescribes.
void check_close(double x, double ref, double atol, double rtol) {
  INFO("value " << x << " reference " << ref);
  CHECK(std::abs(x - ref) <= atol + rtol * std::abs(ref));
}

}  // namespace

TEST_CASE("RK4 at dt = 0.01 matches the exact ramp solution (reference A)", "[rk4]") {
  const auto ref = cb::test::load_test_data("A_ramp_N30_gamma0.json");
  cb::DriveDesc ramp;
  ramp.type = cb::DriveType::Ramp;
  ramp.beta = 1.0;
  const double dt = 0.01;
  cb::Integrator sim(chain(30, 0.0), cb::make_forcing(ramp), {dt, 1});
  // Records are sorted by tau; step to each and compare psi and phi. Tolerance from issue #2:
  // 1e-7 absolute + 1e-7 relative.
  for (const auto& r : ref["records"]) {
    REQUIRE(sim.advance_to(steps_to(r["tau"], dt)));
    const int j = r["j"];
    check_close(sim.state().psi[j - 1], r["psi"], 1e-7, 1e-7);
    check_close(cb::extension(sim.state(), j), r["phi"], 1e-7, 1e-7);
  }
}

TEST_CASE("RK4 energy per particle matches reference A, Eq. (energy)", "[rk4]") {
  const auto ref = cb::test::load_test_data("A_ramp_N30_gamma0.json");
  cb::DriveDesc ramp;
  ramp.type = cb::DriveType::Ramp;
  const double dt = 0.01;
  cb::Integrator sim(chain(30, 0.0), cb::make_forcing(ramp), {dt, 1});
  for (const auto& r : ref["energy"]) {
    REQUIRE(sim.advance_to(steps_to(r["tau"], dt)));
    const double eps = cb::per_particle(cb::energy(sim.state()).total(), 30);
    check_close(eps, r["eps"], 1e-9, 1e-7);
  }
}

TEST_CASE("RK4 step response with friction matches reference C", "[rk4]") {
  const auto ref = cb::test::load_test_data("C_step_N30_gamma0.01.json");
  cb::DriveDesc step;
  step.type = cb::DriveType::Step;
  step.amplitude = 1.0;
  const double dt = 0.01;
  cb::Integrator sim(chain(30, 0.01), cb::make_forcing(step), {dt, 1});
  for (const auto& r : ref["records"]) {
    REQUIRE(sim.advance_to(steps_to(r["tau"], dt)));
    check_close(sim.state().psi[int(r["j"]) - 1], r["psi"], 1e-7, 1e-7);
  }
}

TEST_CASE("RK4 with two velocity kicks matches reference E", "[rk4]") {
  const auto ref = cb::test::load_test_data("E_impulses_N30_gamma0.json");
  cb::DriveDesc kicks;
  kicks.type = cb::DriveType::Impulses;
  kicks.times = {0.0, 30.0};
  const double dt = 0.01;
  cb::Integrator sim(chain(30, 0.0), cb::make_forcing(kicks), {dt, 1});
  for (const auto& r : ref["records"]) {
    REQUIRE(sim.advance_to(steps_to(r["tau"], dt)));
    check_close(cb::extension(sim.state(), r["j"]), r["phi"], 1e-7, 1e-7);
  }
}

TEST_CASE("RK4 converges at fourth order", "[rk4]") {
  // Error at tau = 45 against the reference value psi_30(45) (reference A, j = 30), for
  // dt and dt/2: the ratio of errors is 2^4 = 16 for a fourth-order method. Accept 13..19
  // (the next order's terms and rounding move it a little).
  const auto ref = cb::test::load_test_data("A_ramp_N30_gamma0.json");
  double exact = 0.0;
  for (const auto& r : ref["records"])
    if (r["tau"] == 45 && r["j"] == 30) exact = r["psi"];
  REQUIRE(exact != 0.0);
  cb::DriveDesc ramp;
  ramp.type = cb::DriveType::Ramp;
  auto error_at = [&](double dt) {
    cb::Integrator sim(chain(30, 0.0), cb::make_forcing(ramp), {dt, 1});
    REQUIRE(sim.advance_to(steps_to(45.0, dt)));
    return std::abs(sim.state().psi[29] - exact);
  };
  const double e1 = error_at(0.2), e2 = error_at(0.1), e3 = error_at(0.05);
  INFO("errors " << e1 << " " << e2 << " " << e3);
  CHECK(e1 / e2 == Approx(16.0).margin(3.0));
  CHECK(e2 / e3 == Approx(16.0).margin(3.0));
}

TEST_CASE("The energy books close: E = W - D - B", "[rk4][energy]") {
  cb::DriveDesc sine;
  sine.type = cb::DriveType::Sine;
  sine.amplitude = 0.5;
  sine.period = 40.0;
  sine.t0 = 3.005;  // a kink between grid points
  cb::ChainParams p = chain(20, 0.05);
  p.threshold = 4.0;
  cb::Integrator sim(p, cb::make_forcing(sine), {0.01, 1});
  REQUIRE(sim.advance_to(30000));
  // RK4's local error is O(h^5) in every integrated quantity, the work and the dissipation
  // included, so the books close to roughly 1e-8 relative here; 1e-7 leaves a margin.
  CHECK(cb::energy_balance_error(sim.state()) < 1e-7);
  CHECK(sim.state().dissipated > 0.0);
}

TEST_CASE("energy() in one pass has the bits of Eq. (energy)'s two sums written out",
          "[rk4][energy]") {
  // A state with springs broken at both ends and inside (1, 2, 7, N): the one-pass loop of
  // energy.cpp skips exactly these in the potential and keeps each sum's order of additions,
  // so the run summary's numbers stay those of the former two loops, bit for bit.
  const int n = 40;
  cb::ChainState s;
  for (int i = 0; i < n; ++i) {
    s.psi.push_back(std::sin(0.7 * i + 0.3) * (1.0 + 0.01 * i));
    s.vel.push_back(std::cos(1.3 * i) / 3.0);
  }
  s.broken = {1, 2, 7, n};
  s.work = 9.5;
  s.dissipated = 0.25;
  s.break_loss = 1.5;
  double kinetic = 0.0, potential = 0.0;
  for (int i = 0; i < n; ++i) kinetic += 0.5 * s.vel[i] * s.vel[i];
  for (int j = 1; j <= n; ++j)
    if (cb::spring_intact(s, j)) potential += 0.5 * cb::extension(s, j) * cb::extension(s, j);
  const cb::EnergyParts e = cb::energy(s);
  CHECK(e.kinetic == kinetic);  // exact: the same additions in the same order
  CHECK(e.potential == potential);
  const cb::EnergyBooks b = cb::energy_books(s);
  CHECK(b.parts.kinetic == kinetic);
  CHECK(b.parts.potential == potential);
  CHECK(b.work == s.work);
  CHECK(b.break_loss == s.break_loss);
  CHECK(b.balance_error == cb::energy_balance_error(s));
  const double total = kinetic + potential;
  CHECK(b.balance_error == std::abs(total - (9.5 - 0.25 - 1.5)) / std::max(std::abs(total), 9.5));
}

TEST_CASE("Results do not depend on the number of threads", "[rk4][determinism]") {
  cb::DriveDesc ramp;
  ramp.type = cb::DriveType::Ramp;
  ramp.beta = 0.3;
  cb::ChainParams p = chain(50000, 0.01);
  cb::Integrator one(p, cb::make_forcing(ramp), {0.05, 1});
  cb::Integrator two(p, cb::make_forcing(ramp), {0.05, 2});
  REQUIRE(one.advance_to(200));
  REQUIRE(two.advance_to(200));
  CHECK(one.state().psi == two.state().psi);  // bit for bit
  CHECK(one.state().vel == two.state().vel);
  CHECK(one.state().psi.back() != 0.0);
}

TEST_CASE("A non-finite state stops the run with a message naming the cause", "[rk4]") {
  cb::DriveDesc ramp;
  ramp.type = cb::DriveType::Ramp;
  const double limit = cb::rk4_stability_limit(10, 0.0);
  // Classical RK4 on an undamped oscillator is stable for h Omega <= 2 sqrt(2) (the
  // imaginary-axis end of its stability region); the chain's top frequency is
  // Omega_{N-1} = 2 sin(k_{N-1}/2), k_{N-1} = (N - 1/2) pi / (N + 1/2).
  const double top = 2.0 * std::sin(0.5 * 9.5 * M_PI / 10.5);
  CHECK(limit == Approx(2.0 * std::sqrt(2.0) / top).epsilon(1e-6));
  cb::Integrator sim(chain(10, 0.0), cb::make_forcing(ramp), {1.6, 1});
  bool ok = true;
  for (int i = 0; i < 5000 && ok; ++i) ok = sim.step();
  REQUIRE_FALSE(ok);
  CHECK_THAT(sim.error(), Catch::Contains("stability limit"));
}
