// What the benchmark programs share: Google Benchmark set up with repetitions interleaved
// at random (so a drift of this VM's speed, PLATFORM-NOTES.md, spreads over every benchmark
// instead of biasing a ratio), and the median the summaries print.
#pragma once

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <utility>
#include <vector>

namespace cb::bench {

// benchmark::Initialize with --benchmark_enable_random_interleaving=true in front of the
// command line's flags (a flag given later wins). False after an unrecognised argument.
inline bool initialize(int argc, char** argv) {
  std::vector<char*> args(argv, argv + argc);
  static char interleave[] = "--benchmark_enable_random_interleaving=true";
  args.insert(args.begin() + 1, interleave);
  int count = static_cast<int>(args.size());
  benchmark::Initialize(&count, args.data());
  return !benchmark::ReportUnrecognizedArguments(count, args.data());
}

inline double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// Paired measurements. This VM's speed drifts by up to 30 % within minutes, and not alike for
// everything (PLATFORM-NOTES.md): two benchmarks of one run can catch different halves of a
// drift, so a ratio of two of them moves by as much. time_paired times both workloads in each
// benchmark iteration, one after the other (their order alternating), and the ratio is taken
// iteration by iteration: both halves of every ratio come from the same second. Reported
// (report_ratios): the median ratio `ratio` and its quartiles `ratio_q1`, `ratio_q3`.
inline double quantile(std::vector<double> v, double at) {
  if (v.empty()) return 0.0;
  const auto k = static_cast<std::ptrdiff_t>(at * static_cast<double>(v.size() - 1) + 0.5);
  std::nth_element(v.begin(), v.begin() + k, v.end());
  return v[static_cast<std::size_t>(k)];
}

// Seconds of `a` and of `b` in each iteration (the benchmark's time: their sum, UseManualTime).
template <class A, class B>
std::vector<std::pair<double, double>> time_paired(benchmark::State& state, A&& a, B&& b) {
  const auto seconds = [](auto&& work) {
    const auto t0 = std::chrono::steady_clock::now();
    work();
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  };
  std::vector<std::pair<double, double>> times;
  for (auto _ : state) {
    double ta, tb;
    if (times.size() % 2 == 0) {
      ta = seconds(a);
      tb = seconds(b);
    } else {
      tb = seconds(b);
      ta = seconds(a);
    }
    state.SetIterationTime(ta + tb);
    times.emplace_back(ta, tb);
  }
  return times;
}

inline void report_ratios(benchmark::State& state, const std::vector<double>& ratios) {
  state.counters["ratio"] = quantile(ratios, 0.5);
  state.counters["ratio_q1"] = quantile(ratios, 0.25);
  state.counters["ratio_q3"] = quantile(ratios, 0.75);
}

}  // namespace cb::bench
