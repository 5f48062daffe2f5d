// The command-line options that carry a small language of their own (--vary, --shard, --at,
// --size): parsed here, apart from the commands, so the fuzzer (tests/fuzz) calls the same
// functions the commands do. Each throws SceneError with the option, what is wrong and an
// example (exit status 2).
#pragma once

#include "resources/resources.h"  // kMaxSweepValues: one limit for sweep and its parsers

#include <string>
#include <utility>
#include <vector>

namespace cb {

// --vary KEY=LO:HI:COUNT[:log]: COUNT values from LO to HI, evenly or log-spaced.

// --at T1,T2,...: times tau >= 0, sorted, duplicates removed.
std::vector<double> parse_times(const std::string& text);

// --size WIDTHxHEIGHT in pixels, each 16..16384.
std::pair<int, int> parse_size(const std::string& text);

}  // namespace cb
