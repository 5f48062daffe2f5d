// A hanging chain of anharmonic springs (issue #24 with #22), integrated in psi itself with its
// weight m_j G as a force (stencil.inc's Weighted policy, the tiled kernel only; coefficients.h
// says why not about its equilibrium), against
//   - its equilibrium K_j T(phi_eq,j) = G sum_{i>=j} m_i, which a chain with no pull keeps;
//   - every SIMD path and kernel option (each takes the tiled kernel: the same bytes);
//   - the energy books with the weight's potential, E = W - D - B, without and with friction;
//   - free fall: once the top spring breaks, nothing holds the chain, and its momentum
//     sum m_j psi_j' grows by exactly the weight's and the pull's impulses (the springs' forces
//     cancel in pairs), which a leftover load of the equilibrium frame would break.
// scipy's DOP853 and RK4's order on a hanging FPUT ramp: tests/test_fput.cpp.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "drive/drive.h"
#include "physics/energy.h"
#include "physics/integrator.h"
#include "physics/simd.h"
#include "support/chain_test_support.h"

namespace {

using cb::test::ramp_drive;
using cb::test::state_bytes;

cb::ChainParams hanging_fput(int beads, double gravity, double a, double b, double gamma = 0.0,
                             double threshold = std::numeric_limits<double>::infinity()) {
  cb::ChainParams p = cb::test::chain_of(beads, gamma, threshold, cb::BreakMode::Abs, false);
  p.gravity = gravity;
  p.fput_alpha = a;
  p.fput_beta = b;
  return p;
}

cb::DriveDesc no_pull() {
  cb::DriveDesc d;
  d.type = cb::DriveType::Step;
  d.amplitude = 0.0;
  return d;
}

}  // namespace

TEST_CASE("a hanging anharmonic chain with no pull stays in its equilibrium", "[fput][gravity]") {
  struct Case {
    const char* name;
    cb::ChainParams chain;
  };
  std::vector<Case> cases = {{"FPUT-beta b = 0.5", hanging_fput(20, 0.01, 0.0, 0.5)},
                             {"softening a = -0.3", hanging_fput(20, 0.01, -0.3, 0.0)}};
  // Unequal beads and springs, both terms: every phi_eq,j differs.
  cb::ChainParams unequal = hanging_fput(20, 0.01, 0.3, 0.5);
  unequal.mass.assign(20, 1.0);
  unequal.mass[6] = 3.0;
  unequal.stiffness.assign(20, 1.0);
  unequal.stiffness[12] = 0.5;
  cases.push_back({"unequal, a = 0.3, b = 0.5", unequal});
  const cb::Forcing none = cb::make_forcing(no_pull());
  for (const Case& c : cases) {
    INFO(c.name);
    const cb::ChainParams& p = c.chain;
    // The equilibrium solves K_j T(phi_j) = G sum_{i>=j} m_i (1e-12 relative; fput_extension
    // promises 1e-14 on T alone).
    const std::vector<double> phi = p.equilibrium_extensions();
    double below = 0.0;
    for (int j = p.beads; j >= 1; --j) {
      below += p.gravity * p.mass_of(j);
      const double held =
          p.stiffness_of(j) * cb::fput_tension(phi[j - 1], p.fput_alpha, p.fput_beta);
      CHECK(std::abs(held - below) <= 1e-12 * below);
    }
    const std::vector<double> eq = p.equilibrium_positions();
    REQUIRE(eq.back() > 1.0);  // a real offset, not a chain at rest at psi = 0
    for (cb::SimdPath simd : {cb::SimdPath::Sse2, cb::SimdPath::Avx2, cb::SimdPath::Avx512}) {
      if (!cb::simd_supported(simd)) continue;
      INFO(cb::simd_name(simd));
      cb::IntegratorOptions o;
      o.dt = 0.01;
      o.simd = simd;
      cb::Integrator sim(p, none, o);
      // The Weighted policy lives in the tiled kernel only: on every ISA the Integrator sends the
      // chain there.
      CHECK_FALSE(sim.small_chain_kernel());
      CHECK_FALSE(sim.block_window_kernel());
      // It starts in the equilibrium, and state() is psi itself.
      CHECK(std::memcmp(sim.state().psi.data(), eq.data(), eq.size() * sizeof(double)) == 0);
      double worst = 0.0, fastest = 0.0;
      for (std::int64_t step = 100; step <= 20000; step += 100) {  // tau = 200, gamma = 0
        REQUIRE(sim.advance_to(step));
        for (std::size_t i = 0; i < eq.size(); ++i) {
          worst = std::max(worst, std::abs(sim.state().psi[i] - eq[i]));
          fastest = std::max(fastest, std::abs(sim.state().vel[i]));
        }
      }
      INFO("max |psi - psi_eq| = " << worst << ", max |psi'| = " << fastest);
      CHECK(worst < 1e-10);
      CHECK(fastest < 1e-10);
      CHECK(cb::energy_balance_error(sim.state(), p) < 1e-10);
    }
  }
}

TEST_CASE("a hanging anharmonic chain gives the same bytes on every path",
          "[fput][gravity][simd]") {
  using Path = cb::test::KernelPath;
  constexpr const auto& kPaths = cb::test::kKernelPaths;
  struct Case {
    cb::ChainParams chain;
    cb::DriveDesc drive;
    std::int64_t steps;
  };
  cb::DriveDesc step;
  step.type = cb::DriveType::Step;
  step.amplitude = 0.9;  // T(phi) = 0.9 at phi ~ 0.82: spring N breaks at once
  // A breaking ramp on a small chain, and a chain of several tiles under a step with friction.
  const Case cases[] = {{hanging_fput(30, 0.01, 0.3, 0.5, 0.0, 1.0), ramp_drive(0.02), 8000},
                        {hanging_fput(3001, 1e-4, -0.3, 0.5, 0.02, 0.8), step, 400}};
  for (const Case& c : cases) {
    auto run = [&](cb::SimdPath simd, const Path& path) {
      cb::IntegratorOptions o;
      o.dt = 0.01;
      o.simd = simd;
      o.tiled_only = path.tiled_only;
      o.block_steps = path.block_steps;
      o.threads = path.threads;
      cb::Integrator sim(c.chain, cb::make_forcing(c.drive), o);
      REQUIRE(sim.advance_to(c.steps));
      return sim.state();
    };
    const cb::ChainState ref = run(cb::SimdPath::Sse2, kPaths[1]);
    CHECK(!ref.breaks.empty());
    for (cb::SimdPath simd : {cb::SimdPath::Sse2, cb::SimdPath::Avx2, cb::SimdPath::Avx512}) {
      if (!cb::simd_supported(simd)) continue;
      for (const Path& path : kPaths) {
        INFO(c.chain.beads << " beads, " << cb::simd_name(simd) << ", " << path.name);
        CHECK(state_bytes(ref) == state_bytes(run(simd, path)));
      }
    }
  }
}

TEST_CASE("a hanging anharmonic chain's energy books include the weight's potential",
          "[fput][gravity]") {
  // E = kinetic + anharmonic springs - G sum m_j psi_j, counted from the hanging equilibrium
  // (energy.h, as for linear hanging chains); W - D - B closes it to RK4's accuracy.
  for (double gamma : {0.0, 0.02})
    for (double threshold : {std::numeric_limits<double>::infinity(), 1.0}) {
      const cb::ChainParams p = hanging_fput(20, 0.01, 0.3, 0.5, gamma, threshold);
      cb::Integrator sim(p, cb::make_forcing(ramp_drive(0.02)), {0.01});
      REQUIRE(sim.advance_to(10000));  // tau = 100
      const cb::EnergyBooks books = cb::energy_books(sim.state(), p);
      INFO("gamma " << gamma << ", threshold " << threshold << ": balance " << books.balance_error
                    << ", work " << books.work << ", weight " << books.parts.weight);
      if (std::isfinite(threshold)) CHECK(!sim.state().breaks.empty());
      CHECK(books.balance_error < 1e-8);
      // The same state booked as a chain without weight misses by the weight's work.
      cb::ChainParams table = p;
      table.gravity = 0.0;
      CHECK(cb::energy_balance_error(sim.state(), table) > 1e-3);
    }
}

TEST_CASE("a hanging anharmonic chain falls freely once its top spring breaks", "[fput][gravity]") {
  // N = 30 under a slow ramp: spring 1 carries the pull and the whole weight, so it breaks first
  // (T(phi_c) = 1.5 at f ~ 1.2). From then on nothing holds the chain: with gamma = 0,
  // d/dtau sum m_j psi_j' = G sum m_j + f(tau) exactly, so over [t0, t1] the momentum grows by
  // G M (t1 - t0) + beta (t1^2 - t0^2) / 2, which RK4 integrates without error (a polynomial of
  // degree 1 in tau) but for rounding.
  const double beta = 0.005, gravity = 0.01;
  const cb::ChainParams p = hanging_fput(30, gravity, 0.0, 0.5, 0.0, 1.0);
  cb::Integrator sim(p, cb::make_forcing(ramp_drive(beta)), {0.01});
  while (sim.state().breaks.empty()) REQUIRE(sim.step());
  REQUIRE(sim.state().breaks.front().spring == 1);
  const double tau_break = sim.state().breaks.front().tau;
  INFO("spring 1 breaks at tau = " << tau_break);
  CHECK(tau_break > 200.0);  // quasi-static: f ~ T(1) - G N = 1.2 at tau ~ 240
  CHECK(tau_break < 280.0);
  auto momentum = [&] {
    double sum = 0.0;
    for (int j = 1; j <= p.beads; ++j) sum += p.mass_of(j) * sim.state().vel[j - 1];
    return sum;
  };
  const double t0 = sim.state().tau, p0 = momentum();
  REQUIRE(sim.advance_to(sim.state().step + 2000));  // 20 time units of free fall
  const double t1 = sim.state().tau, p1 = momentum();
  const double want = p0 + gravity * p.beads * (t1 - t0) + 0.5 * beta * (t1 * t1 - t0 * t0);
  INFO("momentum " << p0 << " -> " << p1 << ", expected " << want << " (off by " << p1 - want
                   << ")");
  CHECK(std::abs(p1 - want) <= 1e-11 * std::abs(want));
  // The break's time converges with dt (the crossing located by Hermite interpolation).
  cb::Integrator fine(p, cb::make_forcing(ramp_drive(beta)), {0.0025});
  while (fine.state().breaks.empty()) REQUIRE(fine.step());
  CHECK(fine.state().breaks.front().spring == 1);
  CHECK(std::abs(fine.state().breaks.front().tau - tau_break) < 1e-6);
}

TEST_CASE("a hanging anharmonic chain resumes from its state bit for bit", "[fput][gravity]") {
  // Checkpoints (issue #26) save integrated_state(): psi itself for this chain, the frame it
  // is integrated in.
  const cb::ChainParams p = hanging_fput(20, 0.01, 0.3, 0.5, 0.0, 1.0);
  const cb::Forcing pull = cb::make_forcing(ramp_drive(0.02));
  cb::Integrator first(p, pull, {0.01});
  REQUIRE(first.advance_to(5000));
  cb::Integrator resumed(p, pull, {0.01});
  resumed.restore(first.integrated_state(), first.cursor());
  REQUIRE(first.advance_to(12000));
  REQUIRE(resumed.advance_to(12000));
  CHECK(!first.state().breaks.empty());
  CHECK(state_bytes(first.state()) == state_bytes(resumed.state()));
}
