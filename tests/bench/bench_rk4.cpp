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

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <vector>

#include "bench_support.h"
#include "drive/drive.h"
#include "physics/integrator.h"

namespace {

// The common workload: Eq. (dimless) with friction, pulled by a ramp f = beta tau.
constexpr double kDt = 0.01;
constexpr double kGamma = 0.1;
constexpr double kBeta = 0.01;

double ramp(double tau) {
  return kBeta * tau;
}

// Steps per benchmark iteration: ~1e6-1e7 bead-steps, so one iteration is long enough
// to time and short enough that the whole binary runs in about a minute.
int steps_per_iteration(std::int64_t beads) {
  if (beads <= 100) return 32768;
  if (beads <= 10000) return 1024;
  if (beads <= 1000000) return 2;
  return 1;
}

// Beads still at rest or in the subnormal band ahead of the wave front.
std::int64_t beads_below_normal(const std::vector<double>& psi, const std::vector<double>& vel) {
  std::int64_t count = 0;
  for (std::size_t i = 0; i < psi.size(); ++i)
    count += std::abs(psi[i]) < DBL_MIN || std::abs(vel[i]) < DBL_MIN;
  return count;
}

std::int64_t beads_subnormal(const std::vector<double>& psi, const std::vector<double>& vel) {
  std::int64_t count = 0;
  for (std::size_t i = 0; i < psi.size(); ++i)
    count += std::fpclassify(psi[i]) == FP_SUBNORMAL || std::fpclassify(vel[i]) == FP_SUBNORMAL;
  return count;
}

// Warm-up of small chains (see the design note): advance until the wave front has left
// the chain, in chunks of 1000 steps. At N = 1e3, dt = 0.01 this takes ~60000 steps.
constexpr std::int64_t kWarmUpMaxBeads = 10000;

template <class Sim>
void warm_up(Sim& sim) {
  if (static_cast<std::int64_t>(sim.psi().size()) > kWarmUpMaxBeads) return;
  for (int chunk = 0; chunk < 1000 && beads_below_normal(sim.psi(), sim.vel()) > 0; ++chunk)
    sim.advance(1000);
}

void set_counters(benchmark::State& state, std::int64_t beads, std::int64_t steps,
                  std::int64_t bytes_per_bead_step) {
  const std::int64_t bead_steps = beads * steps * static_cast<std::int64_t>(state.iterations());
  state.counters["bead_steps"] =
      benchmark::Counter(static_cast<double>(bead_steps), benchmark::Counter::kIsRate);
  state.SetItemsProcessed(bead_steps);
  state.SetBytesProcessed(bead_steps * bytes_per_bead_step);
}

// ---------------------------------------------------------------------------------------
// The baseline: classical RK4 as a textbook writes it, with a k array per stage.
// Same equations as the Integrator: psi_j'' = psi_{j-1} - 2 psi_j + psi_{j+1}
// - 2 gamma psi_j' + f delta_jN, with psi_0 = 0 (wall) and psi_{N+1} = psi_N (free end).
class PlainRk4 {
 public:
  PlainRk4(int beads, double gamma, double dt)
      : n_(beads),
        gamma_(gamma),
        dt_(dt),
        x_(beads),
        v_(beads),
        k1x_(beads),
        k1v_(beads),
        k2x_(beads),
        k2v_(beads),
        k3x_(beads),
        k3v_(beads),
        k4x_(beads),
        k4v_(beads),
        xs_(beads),
        vs_(beads) {}

  void step() {
    const double t = static_cast<double>(steps_) * dt_;
    const double h = dt_, h2 = 0.5 * dt_, h6 = dt_ / 6.0;
    derivatives(x_.data(), v_.data(), ramp(t), k1x_.data(), k1v_.data());
    stage(h2, k1x_.data(), k1v_.data());
    derivatives(xs_.data(), vs_.data(), ramp(t + h2), k2x_.data(), k2v_.data());
    stage(h2, k2x_.data(), k2v_.data());
    derivatives(xs_.data(), vs_.data(), ramp(t + h2), k3x_.data(), k3v_.data());
    stage(h, k3x_.data(), k3v_.data());
    derivatives(xs_.data(), vs_.data(), ramp(t + h), k4x_.data(), k4v_.data());
    for (int i = 0; i < n_; ++i) {
      x_[i] += h6 * (k1x_[i] + 2.0 * k2x_[i] + 2.0 * k3x_[i] + k4x_[i]);
      v_[i] += h6 * (k1v_[i] + 2.0 * k2v_[i] + 2.0 * k3v_[i] + k4v_[i]);
    }
    ++steps_;
  }

  void advance(int steps) {
    for (int s = 0; s < steps; ++s) step();
  }
  const std::vector<double>& psi() const { return x_; }
  const std::vector<double>& vel() const { return v_; }

 private:
  void derivatives(const double* x, const double* v, double f, double* kx, double* kv) const {
    const double g2 = 2.0 * gamma_;
    const int n = n_;
    kx[0] = v[0];
    kv[0] = -2.0 * x[0] + x[1] - g2 * v[0];
    for (int i = 1; i < n - 1; ++i) {
      kx[i] = v[i];
      kv[i] = x[i - 1] - 2.0 * x[i] + x[i + 1] - g2 * v[i];
    }
    kx[n - 1] = v[n - 1];
    kv[n - 1] = x[n - 2] - x[n - 1] - g2 * v[n - 1] + f;
  }

  void stage(double c, const double* kx, const double* kv) {
    for (int i = 0; i < n_; ++i) {
      xs_[i] = x_[i] + c * kx[i];
      vs_[i] = v_[i] + c * kv[i];
    }
  }

  int n_;
  double gamma_, dt_;
  std::int64_t steps_ = 0;
  std::vector<double> x_, v_, k1x_, k1v_, k2x_, k2v_, k3x_, k3v_, k4x_, k4v_, xs_, vs_;
};

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

// ---------------------------------------------------------------------------------------
// Args: {beads, threads, breakable}. Breakable uses a finite threshold no spring can
// reach, so the result is the same but every step pays for the crossing checks.
void BM_FusedRK4(benchmark::State& state) {
  cb::ChainParams p;
  p.beads = static_cast<int>(state.range(0));
  p.gamma = kGamma;
  if (state.range(2) != 0) p.threshold = 1e300;
  cb::Integrator sim(p, ramp_forcing(), {kDt, static_cast<int>(state.range(1))});
  FusedSim fused{sim};
  warm_up(fused);
  const int steps = steps_per_iteration(p.beads);
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

// Args: {beads}. One thread.
void BM_PlainRK4(benchmark::State& state) {
  const int beads = static_cast<int>(state.range(0));
  PlainRk4 sim(beads, kGamma, kDt);
  warm_up(sim);
  const int steps = steps_per_iteration(beads);
  for (auto _ : state) {
    sim.advance(steps);
    benchmark::ClobberMemory();
  }
  benchmark::DoNotOptimize(sim.psi().back());
  set_counters(state, beads, steps, 368);
  state.counters["subnormal"] = static_cast<double>(beads_subnormal(sim.psi(), sim.vel()));
}

// Args: {elements}. bytes_per_second counts 24 B per element (read b, c; write a),
// without the write-allocate read of a (which would make it 32).
void BM_Triad(benchmark::State& state) {
  const std::size_t n = static_cast<std::size_t>(state.range(0));
  std::vector<double> a(n, 0.0), b(n, 1.0), c(n, 2.0);
  const double s = 3.0;
  for (auto _ : state) {
    double* pa = a.data();
    const double* pb = b.data();
    const double* pc = c.data();
    for (std::size_t i = 0; i < n; ++i) pa[i] = pb[i] + s * pc[i];
    benchmark::ClobberMemory();
  }
  benchmark::DoNotOptimize(a[n / 2]);
  state.counters["elements"] =
      benchmark::Counter(static_cast<double>(n * state.iterations()), benchmark::Counter::kIsRate);
  state.SetBytesProcessed(static_cast<std::int64_t>(24 * n * state.iterations()));
}

constexpr int kRepetitions = 5;
constexpr double kMinTime = 0.2;  // seconds per repetition

// Wall-clock time: the Integrator's second thread is not the benchmark's thread, so CPU
// time would hide it. Medians over repetitions, which main() interleaves at random.
void common(benchmark::internal::Benchmark* b) {
  b->Unit(benchmark::kMillisecond)
      ->MinTime(kMinTime)
      ->UseRealTime()
      ->Repetitions(kRepetitions)
      ->ReportAggregatesOnly(true);
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
BENCHMARK(BM_FusedRK4)
    ->ArgNames({"N", "threads", "breakable"})
    ->ArgsProduct({{30, 1'000, 1'000'000, 10'000'000}, {1, 2}, {0}})
    ->Args({1'000'000, 1, 1})
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

}  // namespace

int main(int argc, char** argv) {
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
