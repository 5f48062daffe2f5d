// The command-line options that carry a small language of their own (--vary, --shard, --at,
// --size): parsed here, apart from the commands, so the fuzzer (tests/fuzz) calls the same
// functions the commands do. Each throws SceneError with the option, what is wrong and an
// example (exit status 2).
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace cb {

// --vary KEY=LO:HI:COUNT[:log]: COUNT values from LO to HI, evenly or log-spaced.
struct Vary {
  std::string key;
  double lo = 0, hi = 0;
  int count = 0;
  bool log = false;
  double value(int i) const;
};
// The most values one sweep takes: a sweep row is a whole run, and COUNT becomes an int.
constexpr int kMaxSweepValues = 1'000'000;
Vary parse_vary(const std::string& text);

// --shard I/S (I in 1..S) of `count` values: the half-open range [first, last) of a
// contiguous block, so concatenating the shards' rows in order gives the full table.
std::pair<int, int> parse_shard(const std::string& text, int count);

// --at T1,T2,...: times tau >= 0, sorted, duplicates removed.
std::vector<double> parse_times(const std::string& text);

// --size WIDTHxHEIGHT in pixels, each 16..16384.
std::pair<int, int> parse_size(const std::string& text);

}  // namespace cb
