// What bench_rk4.cpp and bench_rk4_native.cpp share: the workload, the textbook RK4 baseline
// and the benchmark settings. Included into each file's anonymous namespace on purpose: the
// native file compiles the same baseline with -march=native, and the two copies must not be
// one symbol.
#pragma once

#include <benchmark/benchmark.h>

#include <cfloat>
#include <cmath>
#include <cstdint>
#include <vector>

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

// Args: {beads}. One thread.
void run_plain_rk4(benchmark::State& state) {
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

}  // namespace
