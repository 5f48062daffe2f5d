#include "cluster/shard.h"

#include <charconv>
#include <cstdio>

#include "cluster/grid.h"

namespace cb {

namespace {

bool parse_count(std::string_view text, std::size_t& out) {
  const auto r = std::from_chars(text.data(), text.data() + text.size(), out);
  return r.ec == std::errc() && r.ptr == text.data() + text.size() && !text.empty();
}

}  // namespace

PointRange shard_points(std::size_t n, Shard s) {
  // n * I fits: grids are limited far below 2^64 / S (check_grid_size).
  return {n * (s.index - 1) / s.count, n * s.index / s.count};
}

std::size_t shard_of_point(std::size_t n, std::size_t shards, std::size_t p) {
  // The first I whose block ends after p: n*I/S > p  <=>  I > ((p+1)*S - 1) / n.
  return ((p + 1) * shards - 1) / n + 1;
}

Shard parse_shard(const std::string& text) {
  const auto slash = text.find('/');
  Shard s;
  if (slash == std::string::npos ||
      !parse_count(std::string_view(text).substr(0, slash), s.index) ||
      !parse_count(std::string_view(text).substr(slash + 1), s.count) || s.count < 1 ||
      s.index < 1 || s.index > s.count)
    throw GridError("--shard " + text +
                    ": expected I/S with 1 <= I <= S, e.g. --shard 2/8, or --shard slurm inside a "
                    "Slurm array job");
  return s;
}

Shard shard_from_slurm(const std::function<const char*(const char*)>& env) {
  auto read = [&](const char* name) {
    const char* v = env(name);
    std::size_t out = 0;
    if (!v)
      throw GridError(std::string("--shard slurm: ") + name +
                      " is not set; --shard slurm works inside a Slurm array job (sbatch "
                      "--array=...); elsewhere give the shard as --shard I/S");
    if (!parse_count(v, out))
      throw GridError(std::string("--shard slurm: ") + name + "=" + v +
                      " is not a whole number; give the shard as --shard I/S instead");
    return out;
  };
  const std::size_t id = read("SLURM_ARRAY_TASK_ID"), min = read("SLURM_ARRAY_TASK_MIN"),
                    count = read("SLURM_ARRAY_TASK_COUNT");
  // Indices min .. min+count-1 map to shards 1..count: this needs a contiguous array
  // (--array=0-7 or 1-8, not 1,4); a stepped or listed array would leave gaps.
  if (id < min || id - min >= count)
    throw GridError("--shard slurm: SLURM_ARRAY_TASK_ID=" + std::to_string(id) +
                    " is outside SLURM_ARRAY_TASK_MIN=" + std::to_string(min) +
                    " + SLURM_ARRAY_TASK_COUNT=" + std::to_string(count) +
                    "; --shard slurm needs a contiguous array (e.g. --array=1-8); for another "
                    "array give --shard $SLURM_ARRAY_TASK_ID/S");
  return {id - min + 1, count};
}

std::string shard_stem(Shard s) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "shard-%04zu-of-%04zu", s.index, s.count);
  return buf;
}

}  // namespace cb
