// Temporal blocking (physics/temporal_block.h): a run with blocks gives the same bytes as
// the same run stepped one step at a time -- psi, vel, broken springs, break times, energy
// books -- on every SIMD path the CPU has, with 1 and 2 threads, with friction, a ramp that
// stops, kicks, breaking inside what would be a block, and the pull string.
#include <algorithm>
#include <array>
#include <atomic>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstring>
#include <limits>

#include "physics/crossing.h"
#include "physics/integrator.h"
#include "physics/run_loop.h"
#include "physics/simd.h"
#include "physics/temporal_block.h"

namespace {

struct Scene {
  const char* name;
  cb::ChainParams chain;
  cb::Forcing forcing;
  double dt = 0.01;
  std::int64_t steps = 0;
  int threads = 1;
  std::int64_t observe_every = 0;  // an observer every this many steps; 0: none
  bool at_first_break = false;
};

// f = beta tau up to t_stop, then constant: a kink at t_stop, which falls inside a step
// (the step is split there) unless t_stop is on the grid.
cb::Forcing ramp(double beta, double t_stop, std::vector<cb::Kick> kicks = {}) {
  cb::Forcing f;
  f.f = [beta, t_stop](double tau) { return beta * std::min(tau, t_stop); };
  f.breakpoints = {t_stop};
  f.kicks = std::move(kicks);
  return f;
}

std::vector<Scene> scenes() {
  std::vector<Scene> out;
  {
    // Several tiles on one thread: friction, a ramp whose kink splits a step, kicks inside a
    // step and on the grid, an observer every 5 steps (blocks shorter than block_steps).
    Scene s{"N=5000 friction ramp kicks", {}, ramp(0.02, 0.8355, {{0.3333, 0.5}, {0.6, -0.25}})};
    s.chain.beads = 5000;
    s.chain.gamma = 0.05;
    s.chain.threshold = 2.0;
    s.steps = 400;
    s.observe_every = 5;
    out.push_back(s);
  }
  {
    // Two workers (the Integrator takes 1 + N / 20000 at most), ~80 tiles, a kick in the
    // middle of the run and friction. N is kept this small for the sanitizer jobs, where
    // every bead-step costs ~40 x the Release build's.
    Scene s{"N=40003 2 threads friction kick", {}, ramp(0.05, 1.5, {{1.004, 1.0}})};
    s.chain.beads = 40003;
    s.chain.gamma = 0.1;
    s.chain.threshold = 5.0;
    s.steps = 300;
    s.threads = 2;
    out.push_back(s);
  }
  {
    // Springs near bead N break (several of them, at times no block boundary knows of);
    // the steps around each break go one at a time, the rest in blocks.
    Scene s{"N=5000 breaking", {}, ramp(0.4, 1e9)};
    s.chain.beads = 5000;
    s.chain.gamma = 0.02;
    s.chain.threshold = 0.5;
    s.steps = 600;
    out.push_back(s);
  }
  {
    // The same with two threads at ~4e4 beads, stopping at the first break as break maps do.
    Scene s{"N=40003 2 threads first break", {}, ramp(0.4, 1e9)};
    s.chain.beads = 40003;
    s.chain.gamma = 0.02;
    s.chain.threshold = 0.5;
    s.chain.break_on = cb::BreakMode::Stretch;
    s.steps = 2000;
    s.threads = 2;
    s.at_first_break = true;
    out.push_back(s);
  }
  {
    // The pull string breaks when f reaches phi_c: a step the block must not take.
    Scene s{"N=5000 pull string", {}, ramp(0.1, 1e9)};
    s.chain.beads = 5000;
    s.chain.threshold = 0.6543;
    s.chain.pull_string = true;
    s.steps = 1000;
    out.push_back(s);
  }
  return out;
}

struct Run {
  cb::ChainState state;
  std::vector<std::int64_t> observed;  // steps the observer saw
  std::int64_t blocked_steps = 0;      // steps taken inside blocks (by counting step_up_to)
};

// tiled_only: the tiled kernel everywhere (else the window kernel in blocks on AVX2 and
// AVX-512, and the one-chain kernel for small chains stepped one at a time).
Run run(const Scene& sc, cb::SimdPath path, int block, bool tiled_only) {
  cb::IntegratorOptions o{sc.dt, sc.threads, path, block, tiled_only};
  cb::Integrator sim(sc.chain, sc.forcing, o);
  REQUIRE(sim.block_steps() == std::max(1, block));
  // Not vacuous: the window kernel is there where it should be.
  REQUIRE(sim.block_window_kernel() == (!tiled_only && path != cb::SimdPath::Sse2));
  Run r;
  std::vector<cb::Observer> observers;
  if (sc.observe_every > 0)
    observers.push_back({sc.observe_every, true,
                         [&](const cb::Integrator& s) { r.observed.push_back(s.state().step); }});
  // Through the one run loop, as every command steps; the block count from a second
  // integrator stepped by hand the same way.
  REQUIRE(cb::run_until(sim, {sc.steps, std::nullopt, sc.at_first_break, nullptr}, observers) ==
          cb::RunEnd::Reached);
  r.state = sim.state();
  if (block > 1 && !sc.at_first_break) {
    cb::Integrator by_hand(sc.chain, sc.forcing, o);
    while (by_hand.state().step < sc.steps) {
      const std::int64_t step = by_hand.state().step;
      std::int64_t room = sc.steps - step;
      if (sc.observe_every > 0) room = std::min(room, sc.observe_every - step % sc.observe_every);
      const int taken = by_hand.step_up_to(room);
      REQUIRE(taken > 0);
      if (taken > 1) r.blocked_steps += taken;
    }
  }
  return r;
}

bool same_doubles(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}
bool same_double(double a, double b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

}  // namespace

TEST_CASE("temporal blocking gives the bytes of one step at a time on every SIMD path",
          "[blocking]") {
  for (const Scene& sc : scenes()) {
    SECTION(sc.name) {
      for (cb::SimdPath path : {cb::SimdPath::Sse2, cb::SimdPath::Avx2, cb::SimdPath::Avx512}) {
        if (!cb::simd_supported(path)) {
          WARN("this CPU has no " << cb::simd_name(path) << ": path not checked");
          continue;
        }
        INFO(cb::simd_name(path));
        // Blocked with the window kernel (AVX2, AVX-512; the tiled kernel on SSE2) against
        // unblocked on the tiled kernel; blocked on the tiled kernel below.
        const Run off = run(sc, path, 1, true);
        const Run on = run(sc, path, 8, false);
        if (!sc.at_first_break) {
          // Not vacuous: most steps went through blocks.
          CHECK(on.blocked_steps > sc.steps / 2);
        }
        {
          const Run tiled = run(sc, path, 8, true);
          CHECK(same_doubles(tiled.state.psi, on.state.psi));
          CHECK(same_doubles(tiled.state.vel, on.state.vel));
          CHECK(same_double(tiled.state.dissipated, on.state.dissipated));
          CHECK(same_double(tiled.state.work, on.state.work));
          CHECK(tiled.state.broken == on.state.broken);
        }
        CHECK(on.state.step == off.state.step);
        CHECK(on.observed == off.observed);
        CHECK(same_doubles(on.state.psi, off.state.psi));
        CHECK(same_doubles(on.state.vel, off.state.vel));
        CHECK(on.state.broken == off.state.broken);
        CHECK(on.state.string_broken == off.state.string_broken);
        CHECK(same_double(on.state.tau, off.state.tau));
        CHECK(same_double(on.state.dissipated, off.state.dissipated));
        CHECK(same_double(on.state.work, off.state.work));
        CHECK(same_double(on.state.break_loss, off.state.break_loss));
        REQUIRE(on.state.breaks.size() == off.state.breaks.size());
        for (std::size_t i = 0; i < on.state.breaks.size(); ++i) {
          CHECK(on.state.breaks[i].spring == off.state.breaks[i].spring);
          CHECK(same_double(on.state.breaks[i].tau, off.state.breaks[i].tau));
          CHECK(on.state.breaks[i].step == off.state.breaks[i].step);
        }
        // Two threads blocked give the bytes of one thread blocked (as they do unblocked).
        if (sc.threads > 1) {
          Scene one = sc;
          one.threads = 1;
          const Run single = run(one, path, 8, false);
          CHECK(same_doubles(single.state.psi, on.state.psi));
          CHECK(same_doubles(single.state.vel, on.state.vel));
          CHECK(same_double(single.state.dissipated, on.state.dissipated));
          CHECK(same_double(single.state.work, on.state.work));
          CHECK(single.state.breaks.size() == on.state.breaks.size());
        }
        // The scenes that are about breaking must break (else they test nothing new).
        if (sc.chain.threshold < 1.0) CHECK(!off.state.breaks.empty());
        if (sc.chain.gamma > 0.0) CHECK(off.state.dissipated > 0.0);
      }
    }
  }
}

TEST_CASE("blocking is on by default only for long chains, and 0 or 1 turns it off", "[blocking]") {
  cb::ChainParams small, large;
  small.beads = cb::kBlockMinBeads - 1;
  large.beads = cb::kBlockMinBeads;
  CHECK(cb::Integrator(small, {}, {0.01, 1}).block_steps() == 1);
  CHECK(cb::Integrator(large, {}, {0.01, 1}).block_steps() == cb::kDefaultBlockSteps);
  CHECK(cb::Integrator(large, {}, {0.01, 1, std::nullopt, 0}).block_steps() == 1);
  CHECK(cb::Integrator(large, {}, {0.01, 1, std::nullopt, 1}).block_steps() == 1);
}

// The window kernel's calls, counted so that the test knows it ran (through `window_under_test`).
namespace {
cb::detail::Rk4Window window_under_test = nullptr;
int window_calls = 0;
// The same for the segments kernel (rk4_segments.h).
cb::detail::Rk4Segments segments_under_test = nullptr;
int segments_calls = 0;
void counting_segments(const cb::detail::SegmentStep& in, cb::detail::SegmentBooks& out) {
  ++segments_calls;
  segments_under_test(in, out);
}
void counting_window(const cb::detail::StepInput& in, int first, int last, int own_first,
                     int own_last, cb::detail::StepOutput& out) {
  ++window_calls;
  window_under_test(in, first, last, own_first, own_last, out);
}
}  // namespace

// The driver at the kernel's interface, on a state in motion everywhere (a chain from rest
// moves only near bead N for any run a test can afford, so most tiles' friction sums would be
// zero and their order would not show): random psi and vel on 20000 beads split between two
// workers, broken springs inside, at and across tile and block edges, friction, bead N.
// 18437 beads: bead N 5 beads into the last block, so the block before reaches it with its
// halo (the free end in a window whose books stop short of it), close enough for an error
// there to reach the block's own beads (a new state depends on beads up to 2 away); N % 8 = 5
// (masked lanes, the tail of the friction sums).
TEST_CASE("a block's states and per-step sums equal the one-step kernel's on a moving chain",
          "[blocking]") {
  for (const int kBeads : {20000, 18437}) {
    const std::pair<int, int> ranges[2] = {{0, 10240}, {10240, kBeads}};
    // Broken springs at tile, block and worker edges (most blocks then take the tiled kernel);
    // one near bead N only; none (every block on the window kernel where there is one: the
    // wall, bead N, the halo reaching the chain's ends, every tile's friction sums).
    for (const std::vector<int>& broken :
         {std::vector<int>{17, 512, 513, 4096, 4097, 4101, 10240, 10241, 12000, kBeads},
          std::vector<int>{kBeads - 3}, std::vector<int>{}}) {
      std::vector<double> psi(kBeads), vel(kBeads);
      std::uint64_t seed = 12345;
      auto uniform = [&] {  // splitmix64 -> [-0.3, 0.3)
        seed += 0x9E3779B97F4A7C15ull;
        std::uint64_t z = seed;
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return 0.6 * static_cast<double>((z ^ (z >> 31)) >> 11) * 0x1.0p-53 - 0.3;
      };
      for (int i = 0; i < kBeads; ++i) {
        psi[i] = uniform();
        vel[i] = uniform();
      }
      // Unequal beads and springs (the PerBead policy: every array read where it belongs) on the
      // longer chain with none or one spring broken.
      for (int variant = 0; variant < 6; ++variant) {
        const int count = std::array{2, 3, 8}[variant % 3];
        const bool unequal = variant >= 3;
        if (unequal && (kBeads != 20000 || broken.size() >= 10)) continue;
        std::vector<cb::detail::PlainStep> steps(count);
        for (int k = 0; k < count; ++k) {
          steps[k].h = 0.05;
          for (int i = 0; i < 3; ++i) steps[k].force[i] = 0.1 * k + 0.03 * i;
        }
        for (cb::SimdPath path : {cb::SimdPath::Sse2, cb::SimdPath::Avx2, cb::SimdPath::Avx512}) {
          if (!cb::simd_supported(path)) continue;
          // 0: the tiled kernel; 1: the window kernel; 2, 3: with the segments kernel, its
          // lanes 512 and 1024 beads long (the Integrator's are longer: the runs above use them).
          for (int use : {0, 1, 2, 3}) {
            const bool use_window = use > 0;
            // The reference below is always the tiled kernel, one step at a time.
            window_under_test = cb::detail::rk4_window_kernel(path);
            if (use_window && !window_under_test) continue;  // SSE2: tiled only
            const cb::detail::Rk4Window window = use_window ? counting_window : nullptr;
            cb::detail::SegmentsKernel segments = cb::detail::rk4_segments_kernel(path);
            segments_under_test = segments.step;
            segments.step = use >= 2 ? counting_segments : nullptr;
            segments.segment = segments.segment_per_bead = use == 2 ? 512 : 1024;
            window_calls = segments_calls = 0;
            INFO(cb::simd_name(path)
                 << ", " << count << " steps, " << kBeads << " beads, "
                 << (unequal ? "unequal, " : "") << broken.size() << " broken, kernels " << use);
            const cb::detail::Rk4Beads kernel = cb::detail::rk4_kernel(path);
            cb::detail::StepInput in;
            in.beads = kBeads;
            in.gamma = 0.07;
            in.broken = &broken;
            cb::ChainParams unbreakable;
            unbreakable.beads = kBeads;
            if (unequal) {
              unbreakable.mass.resize(kBeads);
              unbreakable.stiffness.resize(kBeads);
              for (int j = 1; j <= kBeads; ++j) {
                unbreakable.mass[j - 1] = 1.0 + 0.5 * std::sin(0.37 * j);
                unbreakable.stiffness[j - 1] = 1.0 + 0.4 * std::cos(0.11 * j);
              }
            }
            cb::ChainCoefficients coef = cb::chain_coefficients(unbreakable);
            REQUIRE(coef.per_bead == unequal);
            in.coef = &coef;
            // One step at a time, the reference: each worker's StepOutput per step.
            std::vector<double> x = psi, v = vel, xn(kBeads), vn(kBeads);
            std::vector<cb::detail::StepOutput> want(2 * count);
            cb::detail::TileScratch scratch;
            // Step k of the one-step path: from x, v into xn, vn.
            auto step_input = [&](int k) {
              in.psi = x.data();
              in.vel = v.data();
              in.psi_out = xn.data();
              in.vel_out = vn.data();
              in.h = steps[k].h;
              std::copy(steps[k].force, steps[k].force + 3, in.force);
            };
            for (int k = 0; k < count; ++k) {
              step_input(k);
              for (int w = 0; w < 2; ++w)
                kernel(in, ranges[w].first, ranges[w].second, scratch, want[2 * k + w]);
              x.swap(xn);
              v.swap(vn);
            }
            // The same steps as blocks.
            std::vector<double> bx(kBeads), bv(kBeads);
            in.psi = psi.data();
            in.vel = vel.data();
            in.psi_out = bx.data();
            in.vel_out = bv.data();
            cb::detail::BlockScratch blocks[2];
            std::atomic<bool> abort{false};
            for (int w = 0; w < 2; ++w)
              REQUIRE(cb::detail::rk4_blocked(kernel, window, segments, in, steps, ranges[w].first,
                                              ranges[w].second, scratch, blocks[w], abort) == -1);
            CHECK(same_doubles(bx, x));
            CHECK(same_doubles(bv, v));
            // Not vacuous (with the ten broken springs every block of the shorter chain is near
            // one).
            if (use_window && broken.size() < 10)
              CHECK(window_calls >= (broken.empty() && use == 1 ? 5 * count : 1));
            // Not vacuous: the segments kernel ran (each step of a group is one call); on
            // AVX-512 eight 1024-bead lanes fit only the longer chain.
            if (broken.size() < 10 && (use == 2 || (use == 3 && kBeads == 20000)))
              CHECK(segments_calls >= count);
            for (int k = 0; k < count; ++k)
              for (int w = 0; w < 2; ++w)
                for (int s = 0; s < 4; ++s) {
                  INFO("step " << k << " worker " << w << " stage " << s);
                  CHECK(same_double(blocks[w].steps[k].dissipation_rate[s],
                                    want[2 * k + w].dissipation_rate[s]));
                  CHECK(same_double(blocks[w].steps[k].end_velocity[s],
                                    want[2 * k + w].end_velocity[s]));
                  CHECK(want[2 * k + w].dissipation_rate[s] > 0.0);
                }
            // A crossing: the same chain with a threshold its springs reach within the block. The
            // block names a step in which the one-step path finds a crossing in worker 0's range
            // (the Hermite test of Integrator::advance_interval on the kernel's candidates).
            coef.threshold = 0.62;
            if (unequal) {
              std::fill(coef.upper.begin(), coef.upper.end(), 0.62);
              std::fill(coef.lower.begin(), coef.lower.end(), -0.62);
            }
            coef.checks = true;
            std::vector<bool> crossing(count, false);
            x = psi;
            v = vel;
            for (int k = 0; k < count; ++k) {
              step_input(k);
              for (int w = 0; w < 2; ++w) {
                cb::detail::StepOutput out;
                kernel(in, ranges[w].first, ranges[w].second, scratch, out);
                if (w == 0)
                  for (const auto& c : out.candidates)
                    crossing[k] =
                        crossing[k] || cb::detail::hermite_first_crossing(c.p0, c.p1, c.m0, c.m1,
                                                                          in.h, 0.62, -0.62) >= 0.0;
              }
              x.swap(xn);
              v.swap(vn);
            }
            in.psi = psi.data();
            in.vel = vel.data();
            in.psi_out = bx.data();
            in.vel_out = bv.data();
            abort = false;
            const int failed =
                cb::detail::rk4_blocked(kernel, window, segments, in, steps, ranges[0].first,
                                        ranges[0].second, scratch, blocks[0], abort);
            REQUIRE(failed >= 0);
            REQUIRE(failed < count);
            CHECK(crossing[failed]);
            CHECK(abort.load());
            coef.checks = false;
            const int calls_before_bad = segments_calls;
            // A value that is not finite fails the block too: at its first step on the window
            // and tiled kernels, at the last on the segments kernel, which tests only the last
            // step's values (an inf or NaN stays at its bead; rk4_segments.h).
            std::vector<double> bad = psi;
            bad[ranges[1].first + 700] = std::numeric_limits<double>::infinity();
            in.psi = bad.data();
            abort = false;
            const int bad_step =
                cb::detail::rk4_blocked(kernel, window, segments, in, steps, ranges[1].first,
                                        ranges[1].second, scratch, blocks[1], abort);
            CHECK(bad_step == (segments_calls > calls_before_bad ? count - 1 : 0));
            CHECK(abort.load());
          }
        }
      }
    }
  }
}

TEST_CASE("CHAINBREAK_BLOCK_STEPS values: auto, 0 to 64, anything else an error", "[blocking]") {
  CHECK(!cb::block_steps_from_setting(nullptr));
  CHECK(!cb::block_steps_from_setting("auto"));
  CHECK(cb::block_steps_from_setting("0") == 0);
  CHECK(cb::block_steps_from_setting("16") == 16);
  for (const char* bad : {"-1", "65", "8x", "eight", " 8"})
    CHECK_THROWS_WITH(cb::block_steps_from_setting(bad),
                      Catch::Contains("CHAINBREAK_BLOCK_STEPS=") && Catch::Contains("0 (no"));
}

TEST_CASE("a coarse observer (progress) sees the run after each block, an exact one each step",
          "[blocking]") {
  cb::ChainParams chain;
  chain.beads = 5000;
  cb::Integrator sim(chain, ramp(0.1, 1e9), {0.01, 1, std::nullopt, 8});
  std::vector<std::int64_t> coarse, exact;
  std::vector<cb::Observer> observers = {
      {1, false, [&](const cb::Integrator& s) { coarse.push_back(s.state().step); }, true},
      {12, false, [&](const cb::Integrator& s) { exact.push_back(s.state().step); }}};
  REQUIRE(cb::run_until(sim, {40, std::nullopt, false, nullptr}, observers) == cb::RunEnd::Reached);
  // Blocks of 8 cut at the exact observer's steps 12, 24 and 36 and at the end (40).
  CHECK(coarse == std::vector<std::int64_t>{8, 12, 20, 24, 32, 36, 40});
  CHECK(exact == std::vector<std::int64_t>{12, 24, 36});
}
