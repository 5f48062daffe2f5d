// Chains of unequal beads and springs (issue #21) on every kernel path: the PerBead policy of
// physics/stencil.inc against independent values (the exact solution in shared/reference, a
// DOP853 first break from tests/physics_oracle), against itself across paths (tiled, one-chain
// wavefront, temporal blocks, threads, SIMD paths, lanes: the same bits), and against the
// Uniform policy (unit arrays: the homogeneous chain's bytes).
#include <catch2/catch.hpp>
#include <cmath>
#include <cstring>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "drive/drive.h"
#include "physics/energy.h"
#include "physics/integrator.h"
#include "physics/lanes.h"
#include "physics/run_loop.h"
#include "physics/simd.h"
#include "support/chain_test_support.h"

namespace {

using cb::test::chain_of;
using cb::test::load_test_data;
using cb::test::state_bytes;
using cb::test::supported_paths;

// Every way Integrator can step a chain: the tiled kernel, the default (the one-chain wavefront
// for a small chain on AVX2 / AVX-512), temporal blocks with the window kernel and with tiles,
// two threads; on each SIMD path the CPU has.
struct PathCase {
  std::string name;
  cb::IntegratorOptions options;
};
std::vector<PathCase> path_cases(double dt, bool threads) {
  std::vector<PathCase> out;
  for (cb::SimdPath p : supported_paths()) {
    const std::string isa = cb::simd_name(p);
    cb::IntegratorOptions o{dt, 1, p};
    o.block_steps = 1;
    out.push_back({isa + " default", o});
    o.tiled_only = true;
    out.push_back({isa + " tiled", o});
    o.tiled_only = false;
    o.block_steps = 8;
    out.push_back({isa + " blocked window", o});
    o.tiled_only = true;
    out.push_back({isa + " blocked tiled", o});
    if (threads) {
      o.tiled_only = false;
      o.block_steps = 1;
      o.threads = 2;
      out.push_back({isa + " two threads", o});
      o.block_steps = 8;
      out.push_back({isa + " two threads blocked", o});
    }
  }
  return out;
}

cb::ChainState run(const cb::ChainParams& chain, const cb::DriveDesc& drive,
                   const cb::IntegratorOptions& o, std::int64_t steps) {
  cb::Integrator sim(chain, cb::make_forcing(drive), o);
  REQUIRE(cb::run_until(sim, {steps, std::nullopt, false, nullptr}) == cb::RunEnd::Reached);
  return sim.state();
}

// An unequal chain of n beads: masses, stiffnesses and thresholds that vary along it (smooth
// and abrupt: a heavy segment, a stiff one, a weak link), none of them 1.
cb::ChainParams unequal_chain(int n, double gamma, cb::BreakMode mode) {
  cb::ChainParams p;
  p.beads = n;
  p.gamma = gamma;
  p.break_on = mode;
  p.threshold = 0.8;
  for (int j = 1; j <= n; ++j) {
    p.mass.push_back((j % 7 == 3 ? 3.0 : 1.0) * (1.0 + 0.4 * std::sin(0.37 * j)));
    p.stiffness.push_back(j > n / 3 && j < n / 2 ? 2.5 : 0.6 + 0.3 * std::cos(0.11 * j));
    p.thresholds.push_back(j == n / 2 ? 0.35 : 0.7 + 0.2 * std::sin(0.05 * j));
  }
  return p;
}

}  // namespace

TEST_CASE("unit arrays give the homogeneous chain's bytes on every path", "[unequal]") {
  struct Scene {
    const char* name;
    cb::ChainParams chain;
    cb::DriveDesc drive;
    double dt;
    std::int64_t steps;
    bool threads;
  };
  using cb::BreakMode;
  std::vector<Scene> scenes;
  scenes.push_back({"ramp N=30 breaking", chain_of(30, 0.0, 1.0, BreakMode::Abs, false),
                    cb::test::ramp_drive(0.05), 0.01, 20000, false});
  Scene sine{"sine N=2053 friction",
             chain_of(2053, 0.05, 0.3, BreakMode::Abs, false),
             {},
             0.02,
             3000,
             false};
  sine.drive.type = cb::DriveType::Sine;
  sine.drive.amplitude = 0.6;
  sine.drive.period = 4.7;
  scenes.push_back(sine);
  Scene kicks{"kicks N=77 stretch",
              chain_of(77, 0.0, 0.9, BreakMode::Stretch, false),
              {},
              0.01,
              6000,
              false};
  kicks.drive.type = cb::DriveType::Impulses;
  kicks.drive.times = {0.0, 10.005, 31.0};
  kicks.drive.strengths = {0.7, -0.9, 1.3};
  scenes.push_back(kicks);
  Scene big{"step N=50001 stretch",
            chain_of(50001, 0.0, 0.6, BreakMode::Stretch, false),
            {},
            0.05,
            300,
            true};
  big.drive.type = cb::DriveType::Step;
  big.drive.amplitude = 0.7;
  scenes.push_back(big);
  for (const Scene& sc : scenes)
    for (const PathCase& pc : path_cases(sc.dt, sc.threads)) {
      INFO(sc.name << ", " << pc.name);
      const cb::ChainState uniform = run(sc.chain, sc.drive, pc.options, sc.steps);
      CHECK(!uniform.breaks.empty());  // the broken springs' general stencil is covered too
      // The PerBead policy with its arrays of ones.
      cb::IntegratorOptions o = pc.options;
      o.per_bead_policy = true;
      CHECK(state_bytes(run(sc.chain, sc.drive, o, sc.steps)) == state_bytes(uniform));
      // A chain written with arrays of ones (and thresholds all equal) is the uniform chain.
      cb::ChainParams ones = sc.chain;
      ones.mass.assign(ones.beads, 1.0);
      ones.stiffness.assign(ones.beads, 1.0);
      ones.thresholds.assign(ones.beads, ones.threshold);
      cb::Integrator sim(ones, cb::make_forcing(sc.drive), pc.options);
      CHECK(!sim.coefficients().per_bead);
      CHECK(state_bytes(run(ones, sc.drive, pc.options, sc.steps)) == state_bytes(uniform));
    }
}

TEST_CASE("RK4 of an unequal chain against the exact solution, on every path", "[unequal]") {
  // ../shared/reference/I0_unequal_N12_gamma0.json (tests/data): phi_j(tau) of the exact
  // modal solution in 40-digit arithmetic, ramp f = 0.05 tau, N = 12, gamma = 0.
  const nlohmann::json ref = load_test_data("I0_unequal_N12_gamma0.json");
  cb::ChainParams chain;
  chain.beads = 12;
  chain.mass = ref["masses"].get<std::vector<double>>();
  chain.stiffness = ref["stiffness"].get<std::vector<double>>();
  cb::DriveDesc drive;
  drive.beta = ref["beta"].get<double>();
  const auto taus = ref["tau"].get<std::vector<double>>();
  const auto phis = ref["phi"].get<std::vector<std::vector<double>>>();
  const double dt = 0.01;
  std::vector<unsigned char> tiled;
  double worst = 0.0;
  for (const PathCase& pc : path_cases(dt, false)) {
    INFO(pc.name);
    cb::Integrator sim(chain, cb::make_forcing(drive), pc.options);
    REQUIRE(sim.coefficients().per_bead);
    for (std::size_t k = 0; k < taus.size(); ++k) {
      REQUIRE(sim.advance_to(std::llround(taus[k] / dt)));
      for (int j = 1; j <= 12; ++j) {
        const double want = phis[k][j - 1];
        const double err = std::abs(cb::extension(sim.state(), j) - want);
        worst = std::max(worst, err / std::max(1.0, std::abs(want)));
        // RK4's global error at dt = 0.01 over tau <= 60 (measured ~5e-10 at most).
        CHECK(err <= 1e-7 * std::max(1.0, std::abs(want)));
      }
    }
    // And the same bits on every path.
    if (tiled.empty())
      tiled = state_bytes(sim.state());
    else
      CHECK(state_bytes(sim.state()) == tiled);
  }
  WARN("largest relative error against the exact solution: " << worst);
}

TEST_CASE("an unequal chain with per-spring thresholds: every path gives the tiled bits",
          "[unequal]") {
  struct Case {
    const char* name;
    cb::ChainParams chain;
    cb::DriveDesc drive;
    double dt;
    std::int64_t steps;
    bool threads;
  };
  std::vector<Case> cases;
  Case small{"N=30 ramp", unequal_chain(30, 0.0, cb::BreakMode::Abs), {}, 0.01, 8000, false};
  small.drive.beta = 0.05;
  cases.push_back(small);
  Case mid{"N=2053 sine, friction",
           unequal_chain(2053, 0.03, cb::BreakMode::Abs),
           {},
           0.02,
           2000,
           false};
  mid.drive.type = cb::DriveType::Sine;
  mid.drive.amplitude = 0.5;
  mid.drive.period = 5.3;
  cases.push_back(mid);
  Case kicks{"N=61 kicks, stretch",
             unequal_chain(61, 0.01, cb::BreakMode::Stretch),
             {},
             0.01,
             5000,
             false};
  kicks.drive.type = cb::DriveType::Impulses;
  kicks.drive.times = {0.0, 12.345, 25.0};
  kicks.drive.strengths = {1.1, -0.8, 1.6};
  cases.push_back(kicks);
  Case big{"N=70001 step, stretch",
           unequal_chain(70001, 0.0, cb::BreakMode::Stretch),
           {},
           0.05,
           240,
           true};
  big.drive.type = cb::DriveType::Step;
  big.drive.amplitude = 0.9;
  cases.push_back(big);
  for (const Case& c : cases) {
    cb::IntegratorOptions tiled_options{c.dt, 1, cb::SimdPath::Sse2};
    tiled_options.tiled_only = true;
    tiled_options.block_steps = 1;
    const cb::ChainState want = run(c.chain, c.drive, tiled_options, c.steps);
    INFO(c.name);
    // Breaks, and steps on with a broken spring (the PerBead policy's general stencil).
    REQUIRE(!want.breaks.empty());
    CHECK(want.breaks.front().step < c.steps - 50);
    for (const PathCase& pc : path_cases(c.dt, c.threads)) {
      INFO(pc.name);
      const cb::ChainState got = run(c.chain, c.drive, pc.options, c.steps);
      CHECK(got.breaks.size() == want.breaks.size());
      CHECK(state_bytes(got) == state_bytes(want));
    }
  }
}

TEST_CASE("an unequal chain's energy books balance", "[unequal][energy]") {
  // Kinetic sum m_j v_j^2 / 2 + potential sum K_j phi_j^2 / 2 = work - friction - broken springs'
  // energy, with kicks (s / m_N on bead N) and breaks; dt = 0.01 (RK4's energy error ~1e-10).
  for (double gamma : {0.0, 0.04}) {
    INFO("gamma " << gamma);
    cb::ChainParams chain = unequal_chain(40, gamma, cb::BreakMode::Abs);
    chain.mass.back() = 2.5;  // a kick moves bead N by s / 2.5
    cb::DriveDesc drive;
    drive.type = cb::DriveType::Impulses;
    drive.times = {0.0, 7.5, 19.0};
    drive.strengths = {1.2, 0.9, -1.4};
    cb::Integrator sim(chain, cb::make_forcing(drive), {0.01, 1});
    REQUIRE(sim.advance_to(6000));
    const cb::ChainState& s = sim.state();
    CHECK(!s.breaks.empty());
    CHECK(s.break_loss > 0.0);
    if (gamma > 0.0) CHECK(s.dissipated > 0.0);
    CHECK(cb::energy_balance_error(s, chain) < 1e-8);
    // The uniform books of the same state do not balance: the masses and stiffnesses count.
    CHECK(cb::energy_balance_error(s) > 1e-3);
  }
}

TEST_CASE("a threshold array's first break against DOP853", "[unequal]") {
  // tests/data/unequal_first_break.json: tests/physics_oracle/unequal_first_break.py (scipy
  // DOP853 at rtol = atol = 1e-12 with terminal events; its tau is good to ~1e-10).
  const nlohmann::json ref = load_test_data("unequal_first_break.json");
  for (const auto& c : ref["cases"]) {
    INFO(c["name"].get<std::string>());
    cb::ChainParams chain;
    chain.beads = 12;
    chain.mass = ref["masses"].get<std::vector<double>>();
    chain.stiffness = ref["stiffness"].get<std::vector<double>>();
    chain.thresholds = c["thresholds"].get<std::vector<double>>();
    chain.threshold = 1.0;  // the pull string's; no pull string here
    chain.gamma = c["gamma"].get<double>();
    chain.break_on = c["break_on"] == "stretch" ? cb::BreakMode::Stretch : cb::BreakMode::Abs;
    cb::DriveDesc drive;
    drive.beta = c["beta"].get<double>();
    for (const PathCase& pc : path_cases(0.01, false)) {
      INFO(pc.name);
      cb::Integrator sim(chain, cb::make_forcing(drive), pc.options);
      REQUIRE(cb::run_until(sim, {40000, std::nullopt, true, nullptr}) != cb::RunEnd::Failed);
      REQUIRE(!sim.state().breaks.empty());
      const cb::BreakEvent first = sim.state().breaks.front();
      CHECK(first.spring == c["spring"].get<int>());
      // RK4 at dt = 0.01 and the Hermite location, O(dt^4): measured ~1e-9.
      CHECK(first.tau == Approx(c["tau"].get<double>()).margin(1e-7).epsilon(0));
    }
  }
}

TEST_CASE("lanes: an unequal-chain sweep's first breaks are Integrator's, bit for bit",
          "[unequal][lanes]") {
  // Unequal chains (masses, stiffnesses, thresholds), uniform ones and uniform dynamics with a
  // weak link, mixed in one sweep so that uniform lanes share PerBead kernel calls.
  struct Value {
    cb::ChainParams chain;
    cb::DriveDesc drive;
  };
  std::vector<Value> values;
  for (int i = 0; i < 14; ++i) {
    Value v;
    v.chain = unequal_chain(30, i % 3 == 0 ? 0.0 : 0.02 * i,
                            i % 4 == 1 ? cb::BreakMode::Stretch : cb::BreakMode::Abs);
    if (i % 5 == 2) {  // uniform dynamics, a weak link
      v.chain.mass.clear();
      v.chain.stiffness.clear();
    }
    if (i % 5 == 4) {  // the paper's chain
      v.chain.mass.clear();
      v.chain.stiffness.clear();
      v.chain.thresholds.clear();
    }
    v.drive.beta = 0.01 * std::pow(80.0, i / 13.0);
    if (i == 6) {
      v.drive.type = cb::DriveType::Impulses;
      v.drive.times = {0.0, 3.3};
      v.drive.strengths = {1.5, 1.5};
    }
    values.push_back(v);
  }
  const double dt = 0.01;
  const std::int64_t last = 40000;
  for (cb::SimdPath path : supported_paths()) {
    INFO(cb::simd_name(path));
    std::size_t next = 0;
    std::map<std::size_t, cb::LaneEnd> ends;
    auto take = [&]() -> std::optional<cb::LaneJob> {
      if (next == values.size()) return std::nullopt;
      const Value& v = values[next];
      return cb::LaneJob{next++, v.chain, cb::make_forcing(v.drive), dt, last};
    };
    auto done = [&](std::size_t id, const cb::LaneEnd& e) { ends[id] = e; };
    REQUIRE(cb::run_first_breaks_in_lanes(30, take, done, path));
    REQUIRE(ends.size() == values.size());
    for (std::size_t i = 0; i < values.size(); ++i) {
      INFO("value " << i);
      cb::Integrator sim(values[i].chain, cb::make_forcing(values[i].drive), {dt, 1, path});
      REQUIRE(cb::run_until(sim, {last, std::nullopt, true, nullptr}) == cb::RunEnd::Reached);
      REQUIRE(!sim.state().breaks.empty());
      const cb::BreakEvent want = sim.state().breaks.front();
      REQUIRE(ends[i].kind == cb::LaneEnd::Kind::Broke);
      CHECK(ends[i].first.spring == want.spring);
      CHECK(std::memcmp(&ends[i].first.tau, &want.tau, sizeof want.tau) == 0);
      CHECK(ends[i].first.step == want.step);
    }
  }
}

TEST_CASE("RK4's stability limit of an unequal chain", "[unequal]") {
  // The uniform chain keeps its answer; arrays of ones are the uniform chain.
  cb::ChainParams uniform;
  uniform.beads = 30;
  uniform.gamma = 0.02;
  CHECK(cb::rk4_stability_limit(uniform) == cb::rk4_stability_limit(30, 0.02));
  cb::ChainParams ones = uniform;
  ones.mass.assign(30, 1.0);
  CHECK(cb::rk4_stability_limit(ones) == cb::rk4_stability_limit(30, 0.02));
  // Every mass 1/4: every frequency doubles, so without friction the limit halves (RK4's
  // imaginary-axis bound 2 sqrt(2) over the highest frequency: both sides bind there).
  cb::ChainParams light;
  light.beads = 30;
  light.mass.assign(30, 0.25);
  CHECK(cb::rk4_stability_limit(light) ==
        Approx(0.5 * cb::rk4_stability_limit(30, 0.0)).epsilon(1e-6));
  // The I0 chain's highest frequency from its eigenvalue (numpy.linalg.eigvalsh of
  // M^-1/2 K M^-1/2: lambda_max = 17.29090920583246), so the limit is 2 sqrt(2) / sqrt(lambda).
  cb::ChainParams i0;
  i0.beads = 12;
  i0.mass = {1, 1, 1, 1, 4, 4, 1, 1, 0.5, 0.5, 1, 1};
  i0.stiffness = {1, 1, 2, 2, 2, 0.5, 0.5, 1, 1, 3, 3, 1};
  const double limit = cb::rk4_stability_limit(i0);
  CHECK(limit == Approx(2.0 * std::sqrt(2.0) / std::sqrt(17.29090920583246)).epsilon(1e-6));
  CHECK(limit <= 2.0 * std::sqrt(2.0) / std::sqrt(17.29090920583246));  // on the safe side
  // And the integrator agrees: a kicked chain stays bounded just below it and blows up above.
  cb::DriveDesc kick;
  kick.type = cb::DriveType::Impulses;
  kick.times = {0.0};
  auto energy_after = [&](double dt) {
    cb::Integrator sim(i0, cb::make_forcing(kick), {dt, 1});
    sim.advance_to(20000);
    return sim.error().empty() ? cb::energy(sim.state(), i0).total() : HUGE_VAL;
  };
  CHECK(energy_after(0.98 * limit) < 1.0);     // the kick's energy 1 / (2 m_N) = 0.5
  CHECK(energy_after(1.05 * limit) > 1000.0);  // the highest mode grows
}
