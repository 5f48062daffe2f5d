// Merging shards: each shard's CSV and record (shard_record.h) are read, checked against
// each other (same scene hash, solver, header, grid) and against the grid (every row's
// values are the grid point it claims), and every grid point must be present exactly once.
// The merged table is the header and the rows in grid order: byte for byte what one
// process writes for the whole grid, because every row is copied as the shard wrote it.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include "cluster/shard_record.h"

namespace cb {

// A shard that cannot be merged with the others (unreadable, no record, another grid):
// the message names the file and what to do. The app exits with 2.
struct MergeError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct ShardFile {
  std::string csv_path;
  ShardRecord record;
  std::vector<std::string> rows;  // data lines without the header, without '\n'
};

// A shard record's largest size: ~25 bytes per axis value, so a grid at sweep's limit of
// points on one axis fits, with room for the command and the scene's name.
inline constexpr double kMaxShardRecordBytes = 64e6;
// A shard CSV's largest size: the header and, per point of the record, a row of at most
// csv_row_bytes (resources.h) per column.
double max_shard_csv_bytes(const ShardRecord& record);

// Reads `csv_path` and its record (each a regular file within its size limit); checks the header
// and that each row is its grid point.
ShardFile read_shard_file(const std::string& csv_path);
// The same from the two texts (the fuzz harness's entry, tests/fuzz/fuzz_merge.cpp).
ShardFile parse_shard_file(const std::string& csv_path, const std::string& record_text,
                           const std::string& csv_text);
// The shard CSVs in a folder (those with a record beside them), sorted by name.
std::vector<std::string> shard_csvs_in(const std::string& dir);

struct Coverage {
  std::vector<std::size_t> missing;  // grid points no shard has
  std::vector<std::pair<std::size_t, std::vector<std::string>>> duplicated;  // point, files
  bool complete() const { return missing.empty() && duplicated.empty(); }
};

// Throws MergeError when the shards disagree on scene, solver, header or grid.
Coverage check_coverage(const std::vector<ShardFile>& shards);
// Header and rows in grid order; `shards` must cover the grid exactly once.
std::string merged_csv(const std::vector<ShardFile>& shards);
// OUT.json: scene and hash, solver, grid, every shard with its wall time and peak memory.
std::string merged_json(const std::vector<ShardFile>& shards, const std::string& version);

// "3-5,9": sorted indices as ranges.
std::string index_ranges(const std::vector<std::size_t>& sorted);
// The shards I (1-based, of `shards`) whose blocks hold any of the `points` of a grid of n.
std::vector<std::size_t> shards_holding(std::size_t n, std::size_t shards,
                                        const std::vector<std::size_t>& points);

}  // namespace cb
