// Shards: the I-th of S contiguous, balanced blocks of a grid's points, so that the shards'
// rows in order are the whole table. Where I and S come from (the command line or a Slurm
// array task's environment) and what a shard's files are called.
#pragma once

#include <cstddef>
#include <functional>
#include <string>

namespace cb {

struct Shard {
  std::size_t index = 1, count = 1;  // I of S, 1 <= I <= S
};

struct PointRange {
  std::size_t first = 0, last = 0;  // points [first, last)
  std::size_t size() const { return last - first; }
};

// Points of shard I/S among n: [n(I-1)/S, nI/S). Block sizes differ by at most one.
PointRange shard_points(std::size_t n, Shard shard);
// The shard holding point `p` (the inverse of shard_points).
std::size_t shard_of_point(std::size_t n, std::size_t shards, std::size_t p);

// "I/S". Throws GridError with a usage hint.
Shard parse_shard(const std::string& text);

// `--shard slurm`: I = SLURM_ARRAY_TASK_ID - SLURM_ARRAY_TASK_MIN + 1 and
// S = SLURM_ARRAY_TASK_COUNT, read through `env` (std::getenv in the program, a map in tests).
// Throws GridError naming the missing or malformed variable.
Shard shard_from_slurm(const std::function<const char*(const char*)>& env);

// "shard-0003-of-0008": a name that sorts in shard order (at least four digits).
std::string shard_stem(Shard shard);

}  // namespace cb
