// What `sweep`, `sweep --submit` and `merge` share: the grid built from the command line (its
// axes in the order given), each point's scene, checked before any work, and the record that
// describes a sweep's output (cluster/shard_record.h).
#pragma once

#include <string>
#include <vector>

#include "app/commands.h"
#include "app/sweep_points.h"
#include "cluster/grid.h"
#include "cluster/shard_record.h"
#include "resources/resources.h"

namespace cb {

// The grid of --vary / --values; GridError for a bad spec. Every key is checked against the
// scene (an unknown key or a value the scene refuses is a SceneError naming the option).
Grid sweep_grid(const SweepOptions& o);
// The points [range) and their scenes: every value validated before any work.
SweepPoints sweep_points(const SweepOptions& o, const Grid& grid, PointRange range);
// What the sweep of points [range) will hold at once (resources.h): the points' scenes, one
// run per job (RK4 arrays; the exact solver's N x N tables too), the first breaks and the CSV
// text between writes. Sized by the largest chain any point runs.
MemoryEstimate sweep_memory(const SweepOptions& o, const Grid& grid, PointRange range);
// Bytes of a sweep's CSV text held between writes.
inline constexpr std::size_t kSweepCsvChunk = std::size_t{1} << 16;
// The record of this sweep without shard, timing or host: scene, hash, solver, header, grid
// and the command that recomputes it.
ShardRecord sweep_record(const SweepOptions& o, const Grid& grid);
// This program's absolute path, for commands printed or written into scripts.
std::string chainbreak_exe();
// Merges the shard CSVs into `csv` (and its .json), or reports missing and duplicated points
// with the commands that recompute just those shards: status 0 or 1 (MergeError for shards
// that do not belong together).
int merge_shards(const std::string& csv, const std::vector<std::string>& shard_csvs, bool quiet);

}  // namespace cb
