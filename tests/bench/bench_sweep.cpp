// The 420-value sweep of issue 13 (`sweep scenes/anomalous_breaking.toml --vary
// drive.beta=0.005:1:420:log --jobs 2`) with --solver rk4 and --solver exact, in one run.
//
// Design note: the sweep's per-value work is timed in process (sweep_first_breaks, the code the
// command and the Python module call), on the same 420 scenes the command builds, so the ratio
// is not drowned by the program's start-up (~0.1-0.15 s CPU to load its shared libraries, the
// same for both solvers; tests/bench/sweep_bench.py times the whole command). Scene loading is
// timed on its own (BM_SweepScenes). CPU time of the process is the measure (both jobs' threads
// summed): on this shared 2-vCPU machine wall-clock mostly measures the other processes.
// BM_SweepRk4Single runs the values one by one through Integrator, as before ensemble lanes.
#include <benchmark/benchmark.h>

#include <cmath>
#include <string>
#include <vector>

#include "app/csv.h"
#include "app/sweep_values.h"
#include "bench_support.h"
#include "cluster/grid.h"
#include "figures/break_maps.h"
#include "scene/scene.h"

namespace {

const std::string kScene = std::string(CHAINBREAK_SCENES) + "/anomalous_breaking.toml";

// The scenes `sweep --vary drive.beta=0.005:1:420:log` builds (sweep_setup.cpp: one
// load_scene with the value as an override).
std::vector<cb::SceneDesc> sweep_scenes() {
  const cb::GridAxis axis = cb::parse_vary("drive.beta=0.005:1:420:log");
  std::vector<cb::SceneDesc> scenes;
  for (double v : axis.values)
    scenes.push_back(cb::load_scene(kScene, {{axis.key, cb::number_text(v)}}));
  return scenes;
}

void BM_SweepScenes(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(sweep_scenes());
}

// Args: {jobs}.
void sweep(benchmark::State& state, const std::string& solver_name) {
  const cb::Solver solver = cb::parse_solver(solver_name);
  const auto scenes = sweep_scenes();
  const cb::SweepPoints points = cb::points_of(scenes);
  const int jobs = static_cast<int>(state.range(0));
  int broke = 0;
  for (auto _ : state) {
    const auto results = cb::sweep_first_breaks(points, solver, jobs, nullptr, {});
    broke = 0;
    for (const auto& r : results) broke += r.broke;
  }
  state.counters["values"] = static_cast<double>(scenes.size());
  state.counters["broke"] = broke;
}
void BM_SweepRk4(benchmark::State& state) {
  sweep(state, "rk4");
}
void BM_SweepExact(benchmark::State& state) {
  sweep(state, "exact");
}

// The values one by one through Integrator (what the rk4 sweep did before lanes).
void BM_SweepRk4Single(benchmark::State& state) {
  const auto scenes = sweep_scenes();
  const cb::SweepPoints points = cb::points_of(scenes);
  const int jobs = static_cast<int>(state.range(0));
  for (auto _ : state) {
    const auto results =
        cb::parallel_first_breaks(static_cast<int>(scenes.size()), jobs, [&](int i) {
          return cb::sweep_first_break(scenes[static_cast<std::size_t>(i)], cb::Solver::Rk4,
                                       nullptr);
        });
    benchmark::DoNotOptimize(results.data());
  }
}

// Issue #23's sweep before its ensemble: `sweep scenes/flawed_chain.toml --vary
// chain.seed=1:10000:10000`'s points (sweep_points: 3 x 10^5 Weibull thresholds drawn, each seed's
// scene set and checked), the part of a seed sweep its one RK4 run does not cover.
void BM_SeedPoints(benchmark::State& state) {
  const cb::SceneVariations variations(std::string(CHAINBREAK_SCENES) + "/flawed_chain.toml", {});
  cb::Grid grid;
  cb::add_axis(grid, cb::parse_vary("chain.seed=1:10000:10000"));
  const auto origin = [](const cb::GridAxis& a, double v) { return a.key + cb::number_text(v); };
  for (auto _ : state)
    benchmark::DoNotOptimize(cb::sweep_points(variations, grid, {0, grid.size()}, cb::Solver::Rk4,
                                              static_cast<int>(state.range(0)), origin));
}

void common(benchmark::internal::Benchmark* b) {
  b->ArgName("jobs")->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime();
  b->Repetitions(5)->ReportAggregatesOnly(false);
}

}  // namespace

BENCHMARK(BM_SweepScenes)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime()->Repetitions(5);
BENCHMARK(BM_SweepRk4)->Apply(common);
BENCHMARK(BM_SweepExact)->Apply(common);
BENCHMARK(BM_SweepRk4Single)->Apply(common);
BENCHMARK(BM_SeedPoints)->Apply(common);

int main(int argc, char** argv) {
  if (!cb::bench::initialize(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
