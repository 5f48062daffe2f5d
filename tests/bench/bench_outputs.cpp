// A run's files (app/run_outputs.h) at N = 10^5, 100 rows, every value a full double (a chain
// in motion everywhere, as after the wave has crossed it): the CSV against the HDF5 file, plain
// and compressed, with --psi's three matrices. The output's share of `run --csv` / `run --h5`
// (issue #26: --h5 at most 0.5x the CSV). Results in README.md.
#include <benchmark/benchmark.h>

#include <cmath>
#include <filesystem>
#include <random>

#include "app/h5_run_file.h"
#include "app/run_outputs.h"

namespace {

constexpr int kBeads = 100000;
constexpr int kRows = 100;

struct Rows {
  std::vector<double> phi, psi, vel;
  Rows() : phi(kBeads), psi(kBeads), vel(kBeads) {
    std::mt19937_64 random(26);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (int j = 0; j < kBeads; ++j) phi[j] = u(random), psi[j] = u(random), vel[j] = u(random);
  }
};

void write(benchmark::State& state, bool h5, int deflate) {
  const bool psi = state.range(0) != 0;
  static const Rows rows;
  const std::string path =
      (std::filesystem::temp_directory_path() / (h5 ? "bench_outputs.h5" : "bench_outputs.csv"))
          .string();
  cb::RunDescription d;
  d.scene = "bench";
  d.beads = kBeads;
  d.psi = psi;
  d.every = 100;
  for (auto _ : state) {
    auto file = h5 ? cb::h5_run_file(path, d, deflate) : cb::csv_run_file(path, kBeads, psi);
    file->begin(kBeads, psi, kRows);
    cb::RunRow row;
    row.phi = &rows.phi;
    if (psi) row.psi = &rows.psi, row.vel = &rows.vel;
    for (int k = 0; k < kRows; ++k) {
      row.tau = k;
      row.f = 0.01 * k;
      row.energy = row.kinetic = row.potential = 1.0 / (k + 1);
      file->row(row);
    }
    file->end(cb::RunOutcome{});
    file->commit();
  }
  state.counters["MB"] = static_cast<double>(std::filesystem::file_size(path)) / 1e6;
  std::filesystem::remove(path);
}

void BM_Csv(benchmark::State& s) {
  write(s, false, 0);
}
void BM_H5(benchmark::State& s) {
  write(s, true, 0);
}
void BM_H5Deflate1(benchmark::State& s) {
  write(s, true, 1);
}

}  // namespace

BENCHMARK(BM_Csv)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);
BENCHMARK(BM_H5)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);
BENCHMARK(BM_H5Deflate1)
    ->Arg(0)
    ->Arg(1)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(3);
BENCHMARK_MAIN();
