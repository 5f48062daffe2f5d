// The kernel's instruction sets (physics/simd.h): every path the CPU supports gives the same
// bytes as the SSE2 baseline, and CHAINBREAK_SIMD values are checked.
#include <catch2/catch.hpp>
#include <cstring>
#include <filesystem>
#include <limits>
#include <nlohmann/json.hpp>

#include "drive/drive.h"
#include "physics/integrator.h"
#include "physics/run_loop.h"
#include "physics/simd.h"
#include "support/chain_test_support.h"
#include "test_support.h"

namespace {

using cb::test::chain_of;
using cb::test::state_bytes;
using cb::test::state_hash;

struct Scene {
  const char* name;
  cb::ChainParams chain;
  cb::DriveDesc drive;
  double dt;
  std::int64_t steps;
  int threads;
};

std::vector<Scene> scenes() {
  std::vector<Scene> out;
  // The paper's N = 30 ramp with breaking: several springs go, so broken springs, the wall
  // and bead N all take the general stencil in the kernel.
  using cb::BreakMode;
  out.push_back({"ramp N=30 breaking", chain_of(30, 0.0, 1.0, BreakMode::Abs, false),
                 cb::test::ramp_drive(0.05), 0.01, 20000, 1});
  // Friction, a sine drive and a length that is no multiple of any vector width or tile.
  Scene sine{
      "sine N=2053 gamma", chain_of(2053, 0.05, 0.9, BreakMode::Abs, false), {}, 0.02, 3000, 1};
  sine.drive.type = cb::DriveType::Sine;
  sine.drive.amplitude = 0.3;
  sine.drive.period = 4.7;
  out.push_back(sine);
  // Two workers (N >= 20000 per thread), breaking in the stretch-only mode.
  Scene big{"step N=50001 2 threads",
            chain_of(50001, 0.0, 0.6, BreakMode::Stretch, false),
            {},
            0.05,
            400,
            2};
  big.drive.type = cb::DriveType::Step;
  big.drive.amplitude = 0.8;
  out.push_back(big);
  return out;
}

}  // namespace

TEST_CASE("every SIMD path the CPU supports gives the same bytes as SSE2", "[simd]") {
  for (const Scene& sc : scenes()) {
    SECTION(sc.name) {
      auto run = [&](cb::SimdPath path) {
        cb::IntegratorOptions o{sc.dt, sc.threads, path};
        cb::Integrator sim(sc.chain, cb::make_forcing(sc.drive), o);
        REQUIRE(sim.simd() == path);
        REQUIRE(cb::run_until(sim, {sc.steps, std::nullopt, false, nullptr}) ==
                cb::RunEnd::Reached);
        return sim.state();
      };
      const cb::ChainState base = run(cb::SimdPath::Sse2);
      CHECK(base.step == sc.steps);
      for (cb::SimdPath p : {cb::SimdPath::Avx2, cb::SimdPath::Avx512}) {
        if (!cb::simd_supported(p)) {
          WARN("this CPU has no " << cb::simd_name(p) << ": path not checked");
          continue;
        }
        INFO(cb::simd_name(p));
        const cb::ChainState s = run(p);
        CHECK(s.breaks.size() == base.breaks.size());
        CHECK(state_bytes(s) == state_bytes(base));
      }
    }
  }
}

TEST_CASE("CHAINBREAK_SIMD values: auto is the widest, a missing ISA or a typo is an error",
          "[simd]") {
  CHECK(cb::simd_from_setting(nullptr) == cb::widest_simd());
  CHECK(cb::simd_from_setting("auto") == cb::widest_simd());
  CHECK(cb::simd_from_setting("sse2") == cb::SimdPath::Sse2);
  CHECK_THROWS_WITH(cb::simd_from_setting("avx3"),
                    Catch::Contains("CHAINBREAK_SIMD=avx3") && Catch::Contains("avx512"));
  for (cb::SimdPath p : {cb::SimdPath::Avx2, cb::SimdPath::Avx512}) {
    if (cb::simd_supported(p))
      CHECK(cb::simd_from_setting(cb::simd_name(p)) == p);
    else
      CHECK_THROWS_AS(cb::simd_from_setting(cb::simd_name(p)), cb::SimdChoiceError);
  }
}

// The hashes were made by the integrator as it was before the SIMD paths, the run loop and the
// small-chain changes (commit f8ecf44, compiled with the project's flags, same scenes): every
// path must still give exactly those bytes. A change that moves one bit of one bead fails here;
// if a change of the numerics is intended, regenerate them and say why in the commit.
TEST_CASE("every SIMD path reproduces the bytes of the integrator before the SIMD work",
          "[simd][determinism]") {
  struct Case {
    const char* name;
    int beads;
    double gamma, threshold;
    cb::BreakMode mode;
    bool pull_string;
    cb::DriveType drive;
    double amplitude, beta, dt;
    std::int64_t steps;
    int threads;
    std::uint64_t hash;
  };
  using cb::BreakMode;
  using cb::DriveType;
  const Case cases[] = {
      {"anomalous N=30", 30, 0.0, 3.0, BreakMode::Abs, false, DriveType::Ramp, 1, 0.02, 0.01, 40000,
       1, 0xec756ac9285742f7ull},
      {"ramp N=30, 6 breaks", 30, 0.0, 1.0, BreakMode::Abs, false, DriveType::Ramp, 1, 0.05, 0.01,
       20000, 1, 0x1b729f94dd153ac8ull},
      {"N=1000 friction", 1000, 0.1, 1e300, BreakMode::Abs, false, DriveType::Ramp, 1, 0.01, 0.01,
       30000, 1, 0x1865b77b65d9fad8ull},
      {"N=50001 step, 2 threads", 50001, 0.0, 0.6, BreakMode::Stretch, false, DriveType::Step, 0.8,
       1, 0.05, 600, 2, 0x6fcf3bfe5ac1e747ull},
      {"one body, pull string", 1, 0.0, 1.0, BreakMode::Abs, true, DriveType::Ramp, 1, 0.3, 0.01,
       2000, 1, 0x0f34d36321c218bfull},
      {"N=40 kicks", 40, 0.02, 0.8, BreakMode::Abs, false, DriveType::Impulses, 1, 1, 0.01, 8000, 1,
       0xe07e5919c14e7606ull},
  };
  for (const Case& c : cases) {
    const cb::ChainParams p = chain_of(c.beads, c.gamma, c.threshold, c.mode, c.pull_string);
    cb::DriveDesc d;
    d.type = c.drive;
    d.amplitude = c.amplitude;
    d.beta = c.beta;
    if (c.drive == DriveType::Impulses) {
      d.times = {0.5, 3.25, 7.125};
      d.strengths = {0.7, -0.4, 0.9};
    }
    for (cb::SimdPath path : {cb::SimdPath::Sse2, cb::SimdPath::Avx2, cb::SimdPath::Avx512}) {
      if (!cb::simd_supported(path)) continue;
      INFO(c.name << ", " << cb::simd_name(path));
      cb::Integrator sim(p, cb::make_forcing(d), {c.dt, c.threads, path});
      REQUIRE(sim.advance_to(c.steps));
      CHECK(state_hash(sim.state()) == c.hash);
    }
  }
}

TEST_CASE("run names the path in its JSON, same numbers on each, a bad CHAINBREAK_SIMD exits 2",
          "[simd][cli]") {
  const std::string scene = std::string(CHAINBREAK_SCENES) + "/anomalous_breaking.toml";
  const std::string exe = CHAINBREAK_EXE;
  nlohmann::json first;
  for (cb::SimdPath path : {cb::SimdPath::Sse2, cb::SimdPath::Avx2, cb::SimdPath::Avx512}) {
    if (!cb::simd_supported(path)) continue;
    const auto r = cb::test::run_shell(std::string("CHAINBREAK_SIMD=") + cb::simd_name(path) + " " +
                                       exe + " run " + scene + " --quiet");
    INFO(r.err);
    REQUIRE(r.status == 0);
    auto summary = nlohmann::json::parse(r.out);
    CHECK(summary["simd"] == cb::simd_name(path));
    summary.erase("simd");
    if (first.is_null()) first = summary;
    CHECK(summary == first);  // breaks, tau to the last digit printed, energy books
  }
  REQUIRE_FALSE(first.is_null());
  CHECK(first["breaks"].size() >= 1);

  const auto csv = std::filesystem::temp_directory_path() / "chainbreak_simd_refused.csv";
  std::filesystem::remove(csv);
  const auto bad = cb::test::run_shell("CHAINBREAK_SIMD=avx3 " + exe + " run " + scene +
                                       " --quiet --csv " + csv.string());
  CHECK(bad.status == 2);
  CHECK_THAT(bad.err, Catch::Contains("CHAINBREAK_SIMD=avx3") &&
                          Catch::Contains("expected auto, sse2, avx2 or avx512"));
  CHECK_FALSE(std::filesystem::exists(csv));
}

// The one-chain kernel (physics/rk4_chain.h) against the tiled one it replaces for small
// chains (AVX2, AVX-512; SSE2 keeps the tiled one): the same bytes on every path the CPU has.
// The lengths sit on the kernel's edges: bead N in most lane positions of a block (1, 2, 3, 7,
// 12, 30), the unrolled copy for up to 32 beads and the general one past it (33), one tile
// (511, 512: the friction sums' tail of four, none), two tiles (513, 1000: the per-tile
// sums). The scenes pass through
// both kernels: the chain kernel until the first spring breaks, the tiled one after; the pull
// string, kicks between grid points, friction on and off, both break rules, and an unbreakable
// chain (no crossing checks). Tolerance: none, the bytes must be equal.
TEST_CASE("the small-chain kernel gives the same bytes as the tiled kernel", "[simd][small]") {
  // dt near RK4's limit (1.39 here), so that the wave crosses the 1000 beads in a few thousand
  // steps: both tiles then carry motion, and a friction sum over the whole chain instead of
  // per tile would change the energy books' bits.
  struct Variant {
    const char* name;
    double gamma, threshold;
    cb::BreakMode mode;
    bool pull_string;
    cb::DriveType drive;
    double beta, dt;
    std::int64_t steps;
  };
  constexpr double kNever = std::numeric_limits<double>::infinity();
  const Variant variants[] = {
      // A slow ramp: the string or a spring goes near f = 1 (tau ~ 1000), the wave is everywhere.
      {"friction, pull string, ramp, kicks", 0.05, 1.0, cb::BreakMode::Abs, true,
       cb::DriveType::Ramp, 0.001, 0.25, 6000},
      // Springs break from step ~40 (N = 7) to ~2700 (N = 512); none at N = 1000.
      {"no friction, stretch, sine", 0.0, 0.7, cb::BreakMode::Stretch, false, cb::DriveType::Sine,
       0.0, 0.2, 4000},
      {"unbreakable, friction, ramp", 0.01, kNever, cb::BreakMode::Abs, false, cb::DriveType::Ramp,
       0.001, 0.25, 6000},
  };
  for (int beads : {1, 2, 3, 7, 12, 30, 33, 511, 512, 513, 1000}) {
    for (const Variant& v : variants) {
      const cb::ChainParams p = chain_of(beads, v.gamma, v.threshold, v.mode, v.pull_string);
      cb::DriveDesc d;
      d.type = v.drive;
      d.beta = v.beta;
      d.amplitude = 0.4;
      d.period = 31.0;
      cb::Forcing forcing = cb::make_forcing(d);
      // Inside steps (not on the grid): each splits its step and jumps bead N's velocity.
      forcing.kicks = {{0.505, 0.7}, {3.2551, -0.4}};
      auto run = [&](cb::SimdPath path, bool tiled_only) {
        cb::IntegratorOptions o{v.dt, 1, path};
        o.tiled_only = tiled_only;
        cb::Integrator sim(p, forcing, o);
        // The comparison means something only if the new path runs where it should.
        REQUIRE(sim.small_chain_kernel() == (!tiled_only && path != cb::SimdPath::Sse2));
        REQUIRE(sim.advance_to(v.steps));
        return sim.state();
      };
      INFO("N = " << beads << ", " << v.name);
      // SSE2 keeps the tiled kernel even when allowed the chain one (run's REQUIRE): this is
      // the base, and the AVX paths are held to it with the chain kernel and without.
      const cb::ChainState base = run(cb::SimdPath::Sse2, false);
      // The chain kernel ran a good part of the run before a first break sent the rest to
      // the tiled one.
      if (v.pull_string && beads >= 7) REQUIRE_FALSE(base.breaks.empty());
      if (!base.breaks.empty() && beads >= 7) CHECK(base.breaks.front().step > 40);
      for (cb::SimdPath path : {cb::SimdPath::Avx2, cb::SimdPath::Avx512}) {
        if (!cb::simd_supported(path)) {
          WARN("this CPU has no " << cb::simd_name(path) << ": path not checked");
          continue;
        }
        INFO(cb::simd_name(path));
        CHECK(state_bytes(run(path, false)) == state_bytes(base));
        CHECK(state_bytes(run(path, true)) == state_bytes(base));
      }
    }
  }
}

// Integrator::step_up_to takes a small chain's plain steps in runs (up to kSmallRunSteps a
// call), calling the chain kernel directly and handing a step that may break a spring, or whose
// state is not finite, to advance_interval's code with the kernel's output. Held here to one
// step() at a time on the same kernel (the per-step path it short-cuts) and on the tiled kernel,
// through the run loop with observers that cut the runs short (every 1, 5 and 64 steps) and
// without: breaks (the hand-over), the pull string, kicks and a drive's jump inside steps (runs
// stop before them), the stretch rule, and a blow-up (the same step, error and bytes).
// Tolerance: none, the bytes must be equal.
TEST_CASE("a small chain's runs of steps give the bytes of one step at a time",
          "[simd][small][run_loop]") {
  struct Variant {
    const char* name;
    int beads;
    double gamma, threshold;
    cb::BreakMode mode;
    bool pull_string;
    cb::DriveDesc drive;
    double dt;
    std::int64_t steps;
    bool kicks;
    bool blows_up;
  };
  constexpr double kNever = std::numeric_limits<double>::infinity();
  auto drive = [](cb::DriveType type, double amplitude, double beta, double t0) {
    cb::DriveDesc d;
    d.type = type;
    d.amplitude = amplitude;
    d.beta = beta;
    d.period = 17.0;
    d.t0 = t0;
    return d;
  };
  using cb::BreakMode;
  using cb::DriveType;
  const Variant variants[] = {
      // The paper's ramp: six springs break, each in a step first taken by a run.
      {"N=30 ramp, breaks", 30, 0.0, 1.0, BreakMode::Abs, false, drive(DriveType::Ramp, 1, 0.05, 0),
       0.01, 20000, false, false},
      {"N=30 friction, pull string, kicks", 30, 0.05, 1.0, BreakMode::Abs, true,
       drive(DriveType::Ramp, 1, 0.004, 0), 0.05, 6000, true, false},
      // A step drive switched on between grid points: that step is split, the others are runs.
      {"N=33 step drive off the grid, stretch", 33, 0.02, 0.7, BreakMode::Stretch, false,
       drive(DriveType::Step, 0.8, 1, 0.1234), 0.01, 8000, true, false},
      {"N=7 sine, unbreakable", 7, 0.1, kNever, BreakMode::Abs, false,
       drive(DriveType::Sine, 0.4, 1, 0), 0.1, 3000, false, false},
      {"N=1000 ramp, friction", 1000, 0.1, 0.9, BreakMode::Abs, false,
       drive(DriveType::Ramp, 1, 0.01, 0), 0.2, 3000, false, false},
      // dt beyond RK4's stability limit (~1.39 for N = 10, gamma = 0): the state blows up.
      {"N=10 blow-up", 10, 0.0, kNever, BreakMode::Abs, false, drive(DriveType::Ramp, 1, 0.01, 0),
       1.6, 5000, false, true},
  };
  for (const Variant& v : variants) {
    const cb::ChainParams p = chain_of(v.beads, v.gamma, v.threshold, v.mode, v.pull_string);
    cb::Forcing forcing = cb::make_forcing(v.drive);
    if (v.kicks) forcing.kicks = {{0.505, 0.7}, {3.2551, -0.4}, {40.0, 0.3}};
    for (cb::SimdPath path : {cb::SimdPath::Avx2, cb::SimdPath::Avx512}) {
      if (!cb::simd_supported(path)) {
        WARN("this CPU has no " << cb::simd_name(path) << ": path not checked");
        continue;
      }
      INFO(v.name << ", " << cb::simd_name(path));
      auto one_at_a_time = [&](bool tiled_only, std::string& error) {
        cb::IntegratorOptions o{v.dt, 1, path, 1};
        o.tiled_only = tiled_only;
        cb::Integrator sim(p, forcing, o);
        REQUIRE(sim.small_chain_kernel() == !tiled_only);
        while (sim.state().step < v.steps && sim.step()) {
        }
        error = sim.error();
        // Not vacuous: a breakable chain broke (a step handed over), a blow-up blew up.
        CHECK(sim.state().breaks.empty() == !p.breakable());
        CHECK(error.empty() == !v.blows_up);
        return state_bytes(sim.state());
      };
      std::string error_steps, error_tiled;
      const auto by_steps = one_at_a_time(false, error_steps);
      CHECK(one_at_a_time(true, error_tiled) == by_steps);
      CHECK(error_tiled == error_steps);
      for (std::int64_t every : {0, 1, 5, 64}) {
        INFO("observer every " << every);
        cb::Integrator sim(p, forcing, {v.dt, 1, path, 1});
        std::vector<cb::Observer> observers;
        if (every > 0) observers.push_back({every, false, [](const cb::Integrator&) {}});
        const cb::RunEnd end =
            cb::run_until(sim, {v.steps, std::nullopt, false, nullptr}, observers);
        CHECK(end == (v.blows_up ? cb::RunEnd::Failed : cb::RunEnd::Reached));
        CHECK(sim.error() == error_steps);
        CHECK(state_bytes(sim.state()) == by_steps);
      }
      // Not vacuous: most steps went in runs (before the first break, or all of them).
      cb::Integrator sim(p, forcing, {v.dt, 1, path, 1});
      std::int64_t in_runs = 0;
      while (sim.state().step < v.steps && sim.state().breaks.empty()) {
        const int taken = sim.step_up_to(v.steps - sim.state().step);
        if (taken == 0) break;
        if (taken > 1) in_runs += taken;
      }
      CHECK(in_runs > sim.state().step / 2);
    }
  }
}
