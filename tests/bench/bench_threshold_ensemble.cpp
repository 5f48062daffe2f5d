// Issue #23's goal: 10^4 flawed chains (Weibull thresholds by seed, N = 30, one beta) from one
// RK4 run (physics/threshold_ensemble.h) in under 2 x the time of one run of that chain. The
// ensemble runs until its last member breaks, so "one run" is measured twice: seed 1 alone
// (to its first break, as `run` stops a sweep's value) and the seed that breaks last alone (the
// same span of steps as the ensemble). Thresholds are drawn beforehand (not timed).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>

#include "drive/drive.h"
#include "physics/integrator.h"
#include "physics/run_loop.h"
#include "physics/threshold_draw.h"
#include "physics/threshold_ensemble.h"

namespace {

constexpr int kBeads = 30, kSeeds = 10000;
constexpr double kDt = 0.01, kTEnd = 20000.0;

cb::ChainParams chain_of(int seed) {
  cb::ChainParams p;
  p.beads = kBeads;
  p.gamma = 0.05;
  p.thresholds = cb::draw_thresholds(cb::ThresholdDist::Weibull, 1.0, 6.0,
                                     static_cast<std::uint64_t>(seed), kBeads);
  p.threshold = *std::min_element(p.thresholds.begin(), p.thresholds.end());
  return p;
}

cb::DriveDesc drive_of(double beta) {
  cb::DriveDesc d;
  d.type = cb::DriveType::Ramp;
  d.beta = beta;
  return d;
}

cb::ThresholdEnsemble ensemble_of(double beta) {
  cb::ThresholdEnsemble e;
  e.chain = chain_of(1);
  e.forcing = cb::make_forcing(drive_of(beta));
  e.dt = kDt;
  e.last_step = std::llround(kTEnd / kDt);
  for (int s = 1; s <= kSeeds; ++s) {
    const cb::ChainParams p = chain_of(s);
    e.thresholds.insert(e.thresholds.end(), p.thresholds.begin(), p.thresholds.end());
  }
  return e;
}

double one_run(const cb::ChainParams& p, double beta) {
  cb::Integrator sim(p, cb::make_forcing(drive_of(beta)), {kDt, 1});
  cb::run_until(sim, {std::llround(kTEnd / kDt), std::nullopt, true, nullptr});
  return sim.state().breaks.empty() ? -1.0 : sim.state().breaks.front().tau;
}

void BM_Ensemble10k(benchmark::State& state) {
  const double beta = state.range(0) / 1000.0;
  const cb::ThresholdEnsemble e = ensemble_of(beta);
  for (auto _ : state) benchmark::DoNotOptimize(cb::ensemble_first_breaks(e));
}

void BM_OneRunSeed1(benchmark::State& state) {
  const double beta = state.range(0) / 1000.0;
  const cb::ChainParams p = chain_of(1);
  for (auto _ : state) benchmark::DoNotOptimize(one_run(p, beta));
}

// The seed of the ensemble that breaks last, alone.
void BM_OneRunLastSeed(benchmark::State& state) {
  const double beta = state.range(0) / 1000.0;
  const auto ends = cb::ensemble_first_breaks(ensemble_of(beta));
  std::size_t last = 0;
  for (std::size_t i = 0; i < ends.size(); ++i)
    if (ends[i].first.tau > ends[last].first.tau) last = i;
  const cb::ChainParams p = chain_of(static_cast<int>(last) + 1);
  state.counters["tau_last"] = ends[last].first.tau;
  for (auto _ : state) benchmark::DoNotOptimize(one_run(p, beta));
}

}  // namespace

// beta = 0.001 (slow), 0.02 (the scene flawed_chain.toml), 0.1 and 1 (in thousandths).
BENCHMARK(BM_Ensemble10k)->Arg(1)->Arg(20)->Arg(100)->Arg(1000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_OneRunSeed1)->Arg(1)->Arg(20)->Arg(100)->Arg(1000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_OneRunLastSeed)->Arg(1)->Arg(20)->Arg(100)->Arg(1000)->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();
