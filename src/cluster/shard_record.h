// What a sweep's CSV was computed from, written beside it as `<csv stem>.json` after the CSV
// itself is complete: the scene and its hash, the solver, the grid, which points (the shard),
// the wall time and peak memory it took, and the command that recomputes it. `merge` checks
// shards against each other with it, and resubmission treats a shard as done only when its
// record is there and matches. A record is written last, so its presence means the CSV is whole.
#pragma once

#include <string>
#include <vector>

#include "cluster/grid.h"
#include "cluster/shard.h"

namespace cb {

struct ShardRecord {
  std::string version;  // chainbreak's
  std::string scene;    // path as given
  std::string scene_hash;
  std::string solver;
  std::string header;  // the CSV's first line
  Grid grid;
  Shard shard;
  PointRange points;
  double wall_seconds = 0;
  long peak_memory_kib = 0;  // getrusage's ru_maxrss of the process
  std::string host;
  // `chainbreak` arguments that recompute the whole grid (sweep SCENE --set ... --vary ...
  // --solver ...), without --shard, --csv and --jobs: recompute a shard by adding those.
  std::vector<std::string> command;
};

// The record's file for a CSV: the same path with the extension ".json".
std::string record_path(const std::string& csv_path);

std::string record_json(const ShardRecord& r);  // one JSON object, ends with a newline
// Throws std::runtime_error saying what is wrong with the text.
ShardRecord parse_record(const std::string& json_text);

// Same scene, hash, solver, header and grid (keys and values exactly): shards that can be
// merged. Returns an empty string when they match, else what differs.
std::string record_mismatch(const ShardRecord& a, const ShardRecord& b);

// A command line as a user can paste it into a POSIX shell: words single-quoted when needed.
std::string shell_quote(const std::string& word);
std::string shell_command(const std::vector<std::string>& words);

}  // namespace cb
