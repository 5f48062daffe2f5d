// RK4 throughput of the fused, tiled integrator against the baselines it is judged by.
//
// Design note: three kinds of benchmark run side by side in one binary, because memory
// bandwidth on the VMs we run on drifts by 2-3x within an hour (PLATFORM-NOTES.md) and
// only numbers from the same run can be divided by each other:
//   BM_FusedRK4  cb::Integrator (its own threading) on an N-bead chain, ramp drive;
//   BM_PlainRK4  the textbook RK4 of the same equations -- k1..k4 arrays for x and v,
//                one temporary stage state, one derivative function -- on one thread;
//   BM_Triad     a[i] = b[i] + s c[i], the STREAM triad, as the memory-bandwidth ceiling.
// Both RK4s start from rest with the same dt, gamma and ramp, so they do the same work.
// Throughput is reported in bead-steps per second (beads x steps); bytes_per_second is
// nominal traffic counted without write-allocate: triad 24 B/element, fused RK4 32 B per
// bead-step (read psi, vel; write psi_next, vel_next), plain RK4 368 B per bead-step.
// A chain started from rest has, ahead of the wave front, a band of ~10-15 beads whose
// values are subnormal; on x86 every operation on them costs a microcode assist (~100
// cycles), which at N = 1e3 slows both RK4s by up to ~30% for as long as the band is
// inside the chain. Small chains (N <= 1e4) are therefore warmed up until every bead is
// in motion with normal numbers; for N >= 1e6 the band is < 1e-4 of the chain and is
// left in. The counter `subnormal` reports the beads in that band at the end.
// Before the benchmarks run, main() checks that the plain RK4 and the Integrator agree,
// so the baseline is known to solve the same equations.
#include <benchmark/benchmark.h>
#include <xmmintrin.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "bench_support.h"
#include "drive/drive.h"
#include "physics/integrator.h"
#include "physics/lanes.h"
#include "physics/simd.h"
#include "physics/worker_pool.h"
#include "rk4_workload.h"

namespace {

// Skips a benchmark whose instruction set this CPU lacks, saying so; true when skipped.
bool skip_without(benchmark::State& state, cb::SimdPath simd) {
  if (cb::simd_supported(simd)) return false;
  state.SkipWithError((std::string("no ") + cb::simd_name(simd) + " on this CPU").c_str());
  return true;
}

// The same interface over cb::Integrator, for warm_up().
struct FusedSim {
  cb::Integrator& sim;
  bool advance(int steps) { return sim.advance_to(sim.state().step + steps); }
  const std::vector<double>& psi() const { return sim.state().psi; }
  const std::vector<double>& vel() const { return sim.state().vel; }
};

cb::Forcing ramp_forcing() {
  cb::DriveDesc d;
  d.type = cb::DriveType::Ramp;
  d.beta = kBeta;
  return cb::make_forcing(d);
}

// BM_UnequalRK4's chains: the homogeneous one, and one with m_j = 1 + 0.5 sin(0.37 j), K_j = 1 +
// 0.4 cos(0.11 j); both with friction, unbreakable.
cb::ChainParams uniform_chain(int beads) {
  cb::ChainParams p;
  p.beads = beads;
  p.gamma = kGamma;
  return p;
}
cb::ChainParams unequal_chain(int beads) {
  cb::ChainParams p = uniform_chain(beads);
  p.mass.resize(beads);
  p.stiffness.resize(beads);
  for (int j = 1; j <= beads; ++j) {
    p.mass[j - 1] = 1.0 + 0.5 * std::sin(0.37 * j);
    p.stiffness[j - 1] = 1.0 + 0.4 * std::cos(0.11 * j);
  }
  return p;
}

// ---------------------------------------------------------------------------------------
// cb::Integrator on the chain p from rest, warmed up; a path the CPU lacks is skipped. At
// N >= 1e6 an iteration is 16 steps (two blocks of the default 8), blocked or not.
void time_integrator(benchmark::State& state, const cb::ChainParams& p,
                     const cb::IntegratorOptions& options) {
  if (options.simd && skip_without(state, *options.simd)) return;
  cb::Integrator sim(p, ramp_forcing(), options);
  FusedSim fused{sim};
  warm_up(fused);
  const int steps = p.beads >= 1'000'000 ? 16 : steps_per_iteration(p.beads);
  for (auto _ : state) {
    if (!sim.advance_to(sim.state().step + steps)) {
      state.SkipWithError(sim.error().c_str());
      break;
    }
  }
  benchmark::DoNotOptimize(sim.state().psi.back());
  set_counters(state, p.beads, steps, 32);
  state.counters["subnormal"] = static_cast<double>(beads_subnormal(fused.psi(), fused.vel()));
}

// time_integrator on the homogeneous chain. Breakable uses a finite threshold no spring can
// reach, so the result is the same but every step pays for the crossing checks. block: steps
// per temporal block (IntegratorOptions::block_steps; 1 off, -1 the Integrator's default).
void run_fused_rk4(benchmark::State& state, int beads, int threads, bool breakable,
                   cb::SimdPath simd, bool tiled_only, int block, double fput_alpha = 0.0,
                   double fput_beta = 0.0) {
  cb::ChainParams p = uniform_chain(beads);
  p.fput_alpha = fput_alpha;  // anharmonic springs (issue #24); 0: the harmonic chain
  p.fput_beta = fput_beta;
  if (breakable) p.threshold = 1e300;
  cb::IntegratorOptions options{kDt, threads, simd};
  options.tiled_only = tiled_only;
  if (block >= 0) options.block_steps = block;
  time_integrator(state, p, options);
}

// Args: {beads, threads, breakable, simd, block}; simd: 0 sse2, 1 avx2, 2 avx512
// (cb::SimdPath); block as in run_fused_rk4.
void BM_FusedRK4(benchmark::State& state) {
  run_fused_rk4(state, static_cast<int>(state.range(0)), static_cast<int>(state.range(1)),
                state.range(2) != 0, static_cast<cb::SimdPath>(state.range(3)), false,
                static_cast<int>(state.range(4)));
}

// Args: {beads, simd, unequal}. Issue #21's goal: a chain of unequal masses and stiffnesses
// (the PerBead policy of physics/stencil.inc: 1/m_j, K_j, K_{j+1} read at every bead) against
// the homogeneous chain (unequal 0, the Uniform policy), one thread, the Integrator's own
// choice of kernel and blocking, in the same run (unequal_chain above).
void BM_UnequalRK4(benchmark::State& state) {
  const int beads = static_cast<int>(state.range(0));
  const auto simd = static_cast<cb::SimdPath>(state.range(1));
  time_integrator(state, state.range(2) != 0 ? unequal_chain(beads) : uniform_chain(beads),
                  {kDt, 1, simd});
}

// Paired measurements (bench_support.h: time_paired, report_ratios). A workload for time_paired:
// `steps` more steps of sim (a failure skips the benchmark).
auto stepping(benchmark::State& state, cb::Integrator& sim, int steps) {
  return [&state, &sim, steps] {
    if (!sim.advance_to(sim.state().step + steps)) state.SkipWithError(sim.error().c_str());
  };
}

// Args: {beads, simd}. Issue #21's ratio paired: the two chains of BM_UnequalRK4 (unequal /
// homogeneous bead-steps/s, the same steps each), and each chain's median rate in M
// bead-steps/s.
void BM_UnequalPaired(benchmark::State& state) {
  const int beads = static_cast<int>(state.range(0));
  const auto simd = static_cast<cb::SimdPath>(state.range(1));
  if (skip_without(state, simd)) return;
  cb::Integrator uniform(uniform_chain(beads), ramp_forcing(), {kDt, 1, simd});
  cb::Integrator unequal(unequal_chain(beads), ramp_forcing(), {kDt, 1, simd});
  FusedSim fu{uniform}, fq{unequal};
  warm_up(fu);
  warm_up(fq);
  const int steps = beads >= 1'000'000 ? 16 : steps_per_iteration(beads);
  const auto times = cb::bench::time_paired(state, stepping(state, uniform, steps),
                                            stepping(state, unequal, steps));
  std::vector<double> ratios, rate_u, rate_q;
  const double work = static_cast<double>(beads) * steps;
  for (const auto& [tu, tq] : times) {
    ratios.push_back(tu / tq);
    rate_u.push_back(work / tu / 1e6);
    rate_q.push_back(work / tq / 1e6);
  }
  cb::bench::report_ratios(state, ratios);
  state.counters["uniform_M"] = cb::bench::quantile(rate_u, 0.5);
  state.counters["unequal_M"] = cb::bench::quantile(rate_q, 0.5);
  benchmark::DoNotOptimize(uniform.state().psi.back() + unequal.state().psi.back());
}

// The STREAM triad over arrays of equal length.
void triad_pass(std::vector<double>& a, const std::vector<double>& b, const std::vector<double>& c,
                double s) {
  double* pa = a.data();
  const double* pb = b.data();
  const double* pc = c.data();
  const std::size_t n = a.size();
  for (std::size_t i = 0; i < n; ++i) pa[i] = pb[i] + s * pc[i];
  benchmark::ClobberMemory();
}

// Args: {simd}. Issue #21's AVX2 goal paired: the homogeneous chain at N = 1e7 on one thread
// (the Integrator's default blocking), 16 steps, against 16 passes of the triad over 1e7
// doubles: `ratio` = (32 B x bead-steps/s) / (24 B x triad elements/s), the share of the
// memory ceiling that "Fused bytes/s / triad" reports from two benchmarks.
void BM_CeilingPaired(benchmark::State& state) {
  const auto simd = static_cast<cb::SimdPath>(state.range(0));
  if (skip_without(state, simd)) return;
  constexpr int kBeads = 10'000'000, kSteps = 16, kPasses = 16;
  cb::Integrator sim(uniform_chain(kBeads), ramp_forcing(), {kDt, 1, simd});
  std::vector<double> a(kBeads, 0.0), b(kBeads, 1.0), c(kBeads, 2.0);
  const auto triad = [&] {
    for (int k = 0; k < kPasses; ++k) triad_pass(a, b, c, 3.0);
  };
  std::vector<double> ratios;
  for (const auto& [tc, tt] : cb::bench::time_paired(state, stepping(state, sim, kSteps), triad))
    ratios.push_back((32.0 / tc) / (24.0 * kPasses / (tt * kSteps)));
  cb::bench::report_ratios(state, ratios);
  benchmark::DoNotOptimize(a[kBeads / 2] + sim.state().psi.back());
}

// Args: {beads, simd}. BM_FusedRK4 on one thread with the small-chain kernel turned off
// (IntegratorOptions::tiled_only): the tiled kernel it replaces, measured in the same run.
void BM_FusedTiledRK4(benchmark::State& state) {
  run_fused_rk4(state, static_cast<int>(state.range(0)), 1, false,
                static_cast<cb::SimdPath>(state.range(1)), true, -1);
}

// Args: {beads, simd, anharmonic}. BM_FusedRK4 on one thread (the Integrator's default kernel
// and blocking) with harmonic springs (0) or anharmonic ones, a = 0.3, b = 0.5 (1; issue #24's
// speed goal: >= 0.8 x the harmonic chain's bead-steps/s at N = 1e3 and 1e7). The ramp keeps
// every |phi| far below 1, so the values and their cost are those of a real run.
void BM_FputRK4(benchmark::State& state) {
  const bool anharmonic = state.range(2) != 0;
  run_fused_rk4(state, static_cast<int>(state.range(0)), 1, false,
                static_cast<cb::SimdPath>(state.range(1)), false, -1, anharmonic ? 0.3 : 0.0,
                anharmonic ? 0.5 : 0.0);
}

// Args: {beads, simd}. The ensemble path of `sweep --solver rk4` (physics/lanes.h): eight
// unbreakable chains side by side, each from rest for steps_per_iteration(N) steps (a chain of
// 30 beads leaves the subnormal band within ~3000 of its 32768 steps). bead_steps counts every
// lane's beads, so it compares with one chain's RK4 bead for bead.
void run_lanes_rk4(benchmark::State& state, double gamma) {
  const int beads = static_cast<int>(state.range(0));
  const auto simd = static_cast<cb::SimdPath>(state.range(1));
  if (skip_without(state, simd)) return;
  const int steps = steps_per_iteration(beads);
  constexpr int kValues = 8;
  for (auto _ : state) {
    int given = 0;
    auto next = [&]() -> std::optional<cb::LaneJob> {
      if (given == kValues) return std::nullopt;
      cb::LaneJob job;
      job.id = static_cast<std::size_t>(given++);
      job.params.beads = beads;
      job.params.gamma = gamma;
      job.forcing = ramp_forcing();
      job.dt = kDt;
      job.last_step = steps;
      return job;
    };
    cb::run_first_breaks_in_lanes(
        beads, next, [](std::size_t, const cb::LaneEnd&) {}, simd);
  }
  set_counters(state, std::int64_t{beads} * kValues, steps, 32);
}
void BM_LanesRK4(benchmark::State& state) {
  run_lanes_rk4(state, kGamma);
}
// The same at gamma = 0, the 420-value sweep's chain (bench_sweep): the lanes' frictionless
// kernel (stencil.inc's NoFriction) and their runs of plain steps, without a sweep's other
// costs, for A/B runs of a kernel change (tests/bench/README.md, session 16).
void BM_LanesRK4Frictionless(benchmark::State& state) {
  run_lanes_rk4(state, 0.0);
}

// Args: {beads}. One thread, this file's flags (the physics core's: baseline x86-64).
void BM_PlainRK4(benchmark::State& state) {
  run_plain_rk4(state);
}

// Flush-to-zero and denormals-are-zero (MXCSR) for the calling thread, or IEEE subnormals.
class FlushSubnormals {
 public:
  explicit FlushSubnormals(bool on) : saved_(_mm_getcsr()) {
    constexpr unsigned kFtz = 0x8000, kDaz = 0x0040;
    _mm_setcsr(on ? saved_ | kFtz | kDaz : saved_ & ~(kFtz | kDaz));
  }
  ~FlushSubnormals() { _mm_setcsr(saved_); }
  FlushSubnormals(const FlushSubnormals&) = delete;
  FlushSubnormals& operator=(const FlushSubnormals&) = delete;

 private:
  unsigned saved_;
};

// Args: {beads, ftz}. A chain from rest, as every real run starts: each iteration integrates
// a fresh N = 1000 chain for kFromRestSteps steps (tau = 200), while the subnormal band ahead
// of the wave front is inside the chain, with IEEE subnormals (0) or FTZ/DAZ (1).
constexpr int kFromRestSteps = 20000;
void BM_FusedFromRest(benchmark::State& state) {
  cb::ChainParams p;
  p.beads = static_cast<int>(state.range(0));
  p.gamma = kGamma;
  const FlushSubnormals mode(state.range(1) != 0);
  for (auto _ : state) {
    cb::Integrator sim(p, ramp_forcing(), {kDt, 1});
    sim.advance_to(kFromRestSteps);
    benchmark::DoNotOptimize(sim.state().psi.back());
  }
  set_counters(state, p.beads, kFromRestSteps, 32);
}

// Args: {elements}. bytes_per_second counts 24 B per element (read b, c; write a),
// without the write-allocate read of a (which would make it 32).
void BM_Triad(benchmark::State& state) {
  const std::size_t n = static_cast<std::size_t>(state.range(0));
  std::vector<double> a(n, 0.0), b(n, 1.0), c(n, 2.0);
  for (auto _ : state) triad_pass(a, b, c, 3.0);
  benchmark::DoNotOptimize(a[n / 2]);
  state.counters["elements"] =
      benchmark::Counter(static_cast<double>(n * state.iterations()), benchmark::Counter::kIsRate);
  state.SetBytesProcessed(static_cast<std::int64_t>(24 * n * state.iterations()));
}

// Args: {elements, threads}. The same triad split into `threads` contiguous halves on the
// Integrator's own worker pool: the ceiling of a multi-threaded fused step.
void BM_TriadThreads(benchmark::State& state) {
  const std::size_t n = static_cast<std::size_t>(state.range(0));
  const int threads = static_cast<int>(state.range(1));
  std::vector<double> a(n, 0.0), b(n, 1.0), c(n, 2.0);
  cb::detail::WorkerPool pool(threads);
  const double s = 3.0;
  const std::function<void(int)> part = [&](int w) {
    const std::size_t lo = n * w / threads, hi = n * (w + 1) / threads;
    double* pa = a.data();
    const double* pb = b.data();
    const double* pc = c.data();
    for (std::size_t i = lo; i < hi; ++i) pa[i] = pb[i] + s * pc[i];
  };
  for (auto _ : state) {
    pool.run(part);
    benchmark::ClobberMemory();
  }
  benchmark::DoNotOptimize(a[n / 2]);
  state.SetBytesProcessed(static_cast<std::int64_t>(24 * n * state.iterations()));
}

// The Integrator caps its workers at 1 + N / 20000, so at N = 30 and 1e3 "threads:2"
// runs on one thread: those rows show the noise of the run, not threading.
BENCHMARK(BM_Triad)->Arg(10'000'000)->Apply(common);
BENCHMARK(BM_Triad)->Arg(50'000'000)->Apply(common);  // 3 x 400 MB: beyond any L3
BENCHMARK(BM_PlainRK4)
    ->ArgName("N")
    ->Arg(30)
    ->Arg(1'000)
    ->Arg(1'000'000)
    ->Arg(10'000'000)
    ->Apply(common);
BENCHMARK(BM_LanesRK4)
    ->ArgNames({"N", "simd"})
    ->ArgsProduct({{30, 1'000}, {0, 1, 2}})
    ->Apply(common);
BENCHMARK(BM_LanesRK4Frictionless)
    ->ArgNames({"N", "simd"})
    ->ArgsProduct({{30}, {1, 2}})
    ->Apply(common);
BENCHMARK(BM_FusedFromRest)->ArgNames({"N", "ftz"})->ArgsProduct({{1'000}, {0, 1}})->Apply(common);
BENCHMARK(BM_TriadThreads)->Args({10'000'000, 2})->Apply(common);
// Every instruction set at every N on one thread; two threads only where the Integrator
// uses them (N >= 20000 per extra worker).
// At N >= 1e6, temporal blocking off (block 1) and on (8) side by side; SSE2 unblocked only.
BENCHMARK(BM_FusedRK4)
    ->ArgNames({"N", "threads", "breakable", "simd", "block"})
    ->ArgsProduct({{30, 1'000}, {1}, {0}, {0, 1, 2}, {-1}})
    ->ArgsProduct({{1'000'000, 10'000'000}, {1, 2}, {0}, {0}, {1}})
    ->ArgsProduct({{1'000'000, 10'000'000}, {1, 2}, {0}, {1, 2}, {1, 8}})
    ->ArgsProduct({{10'000'000}, {1}, {0}, {1}, {2, 4, 16}})  // the block length's trade-off
    ->Args({1'000'000, 1, 1, 2, 1})
    ->Args({1'000'000, 1, 1, 2, 8})
    ->Apply(common);
BENCHMARK(BM_UnequalRK4)
    ->ArgNames({"N", "simd", "unequal"})
    ->ArgsProduct({{30, 1'000, 10'000'000}, {1, 2}, {0, 1}})
    ->Apply(common);
// Paired: 2 s of iterations at N = 30 and 1e3; 21 iterations at N = 1e7 (about 20 s each).
BENCHMARK(BM_UnequalPaired)
    ->ArgNames({"N", "simd"})
    ->ArgsProduct({{30, 1'000}, {1, 2}})
    ->Unit(benchmark::kMillisecond)
    ->MinTime(2.0)
    ->UseManualTime();
BENCHMARK(BM_UnequalPaired)
    ->ArgNames({"N", "simd"})
    ->ArgsProduct({{10'000'000}, {1, 2}})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(21)
    ->UseManualTime();
BENCHMARK(BM_CeilingPaired)
    ->ArgName("simd")
    ->Arg(1)
    ->Arg(2)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(21)
    ->UseManualTime();
BENCHMARK(BM_FusedTiledRK4)
    ->ArgNames({"N", "simd"})
    ->ArgsProduct({{30, 1'000}, {0, 1, 2}})
    ->Apply(common);
BENCHMARK(BM_FputRK4)
    ->ArgNames({"N", "simd", "fput"})
    ->ArgsProduct({{1'000, 10'000'000}, {1, 2}, {0, 1}})
    ->Apply(common);

// The baseline must solve the same equations: after 500 steps of dt = 0.01 on 1000
// beads the two differ only by rounding (different operation order), so they must agree
// to 1e-12 relative to the largest |psi|.
bool baseline_agrees() {
  constexpr int kBeads = 1000, kSteps = 500;
  cb::ChainParams p;
  p.beads = kBeads;
  p.gamma = kGamma;
  cb::Integrator fused(p, ramp_forcing(), {kDt, 1});
  PlainRk4 plain(kBeads, kGamma, kDt);
  fused.advance_to(kSteps);
  for (int s = 0; s < kSteps; ++s) plain.step();
  double diff = 0.0, scale = 0.0;
  for (int i = 0; i < kBeads; ++i) {
    diff = std::max(diff, std::abs(fused.state().psi[i] - plain.psi()[i]));
    scale = std::max(scale, std::abs(plain.psi()[i]));
  }
  std::printf(
      "baseline check (N=%d, %d steps): psi_N fused %.15g plain %.15g, max |diff| %.3g "
      "(max |psi| %.3g)\n",
      kBeads, kSteps, fused.state().psi.back(), plain.psi().back(), diff, scale);
  return scale > 0.0 && diff <= 1e-12 * scale;
}

// What flush-to-zero would do to the results: the same from-rest run with and without it.
void report_ftz_effect() {
  cb::ChainParams p;
  p.beads = 1000;
  p.gamma = kGamma;
  auto run = [&](bool ftz) {
    const FlushSubnormals mode(ftz);
    cb::Integrator sim(p, ramp_forcing(), {kDt, 1});
    sim.advance_to(kFromRestSteps);
    return sim.state();
  };
  const cb::ChainState ieee = run(false), flushed = run(true);
  double diff = 0.0, scale = 0.0;
  int differing = 0;
  for (int i = 0; i < p.beads; ++i) {
    const double d = std::abs(ieee.psi[i] - flushed.psi[i]);
    diff = std::max(diff, d);
    differing += ieee.psi[i] != flushed.psi[i];
    scale = std::max(scale, std::abs(ieee.psi[i]));
  }
  std::printf(
      "ftz check (N=%d from rest, %d steps): %d beads differ, max |diff| %.3g (max |psi| %.3g), "
      "work %.17g vs %.17g\n",
      p.beads, kFromRestSteps, differing, diff, scale, ieee.work, flushed.work);
}

}  // namespace

int main(int argc, char** argv) {
  report_ftz_effect();
  if (!baseline_agrees()) {
    std::fprintf(stderr,
                 "bench_rk4: the plain RK4 baseline disagrees with cb::Integrator; "
                 "fix the baseline before trusting any ratio\n");
    return 1;
  }
  // Repetitions run in random order across benchmarks, so a drift of the machine's speed
  // during the run (PLATFORM-NOTES.md) spreads over all of them instead of biasing the
  // ratios. A flag given on the command line comes later and wins.
  if (!cb::bench::initialize(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
