// What the benchmark programs share: Google Benchmark set up with repetitions interleaved
// at random (so a drift of this VM's speed, PLATFORM-NOTES.md, spreads over every benchmark
// instead of biasing a ratio), and the median the summaries print.
#pragma once

#include <benchmark/benchmark.h>

#include <algorithm>
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

}  // namespace cb::bench
