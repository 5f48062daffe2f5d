// `chainbreak merge`: shards of a sweep into one table, checked (cluster/merge.h), written
// atomically with a record of the scene, the grid and every shard's cost.
#include <cstdio>
#include <filesystem>

#include "app/commands.h"
#include "app/sweep_setup.h"
#include "cluster/merge.h"
#include "cluster/slurm.h"
#include "output/output_file.h"
#include "output/output_lock.h"
#include "version.h"  // CHAINBREAK_VERSION (src/cmake/version.cmake)

namespace cb {

namespace fs = std::filesystem;

namespace {

// What to run to recompute just `shards` (1-based, of S) of the sweep `record` describes,
// their CSVs going into `dir`: one `chainbreak sweep --shard I/S` line each, and the sbatch
// line when the sweep's script is beside the merged table.
std::string recompute_hint(const ShardRecord& record, const std::vector<std::size_t>& shards,
                           const fs::path& dir, const std::string& merged_csv) {
  std::string hint = "Recompute just those shards with:\n";
  for (std::size_t i : shards) {
    std::vector<std::string> words = {chainbreak_exe()};
    words.insert(words.end(), record.command.begin(), record.command.end());
    const Shard s{i, record.shard.count};
    words.insert(words.end(), {"--shard", std::to_string(i) + "/" + std::to_string(s.count),
                               "--csv", (dir / (shard_stem(s) + ".csv")).string()});
    hint += "  " + shell_command(words) + "\n";
  }
  const fs::path script = fs::path(merged_csv).replace_extension(".sbatch");
  if (fs::exists(script))
    hint +=
        "or on Slurm (the array of just those shards):\n  sbatch --array=" + array_spec(shards, 0) +
        " " + shell_quote(fs::absolute(script).string()) +
        "\n(rerunning the same `chainbreak sweep ... --submit slurm` does this too)\n";
  return hint + "then merge again.\n";
}

}  // namespace

int merge_shards(const std::string& csv, const std::vector<std::string>& shard_csvs, bool quiet) {
  check_output_path(csv, "merged.csv");
  // The merged CSV and its record are one set, like a sweep's (output_lock.h).
  const OutputLock lock(csv);
  std::vector<ShardFile> shards;
  for (const auto& path : shard_csvs) shards.push_back(read_shard_file(path));
  const Coverage c = check_coverage(shards);
  const ShardRecord& first = shards.front().record;
  if (!c.complete()) {
    const std::size_t n = first.grid.size();
    std::string msg = "chainbreak merge: " + csv + " not written: ";
    if (!c.missing.empty())
      msg += std::to_string(c.missing.size()) + " of " + std::to_string(n) +
             " grid points missing: " + index_ranges(c.missing) + "\n";
    for (const auto& [p, files] : c.duplicated) {
      msg += "grid point " + std::to_string(p) + " is in more than one shard:";
      for (const auto& f : files) msg += " " + f;
      msg += "; merge only one of them\n";
    }
    if (!c.missing.empty()) {
      const auto todo = shards_holding(n, first.shard.count, c.missing);
      msg += recompute_hint(first, todo, fs::absolute(shards.front().csv_path).parent_path(), csv);
    }
    std::fputs(msg.c_str(), stderr);
    return 1;
  }
  OutputFile out(csv);
  OutputFile out_record(record_path(csv));
  out.write(merged_csv(shards));
  out_record.write(merged_json(shards, CHAINBREAK_VERSION));
  out.commit();
  out_record.commit();
  if (!quiet)
    std::fprintf(stderr, "merge: %zu shards, %zu grid points written to %s (record %s)\n",
                 shards.size(), first.grid.size(), csv.c_str(), record_path(csv).c_str());
  return 0;
}

int merge_command(const MergeOptions& o) {
  std::vector<std::string> files;
  for (const auto& in : o.inputs) {
    if (fs::is_directory(in)) {
      const auto found = shard_csvs_in(in);
      if (found.empty())
        throw MergeError(in +
                         ": no shard CSVs with their .json records in this folder; "
                         "name the shard files or the folder `sweep --submit` wrote");
      files.insert(files.end(), found.begin(), found.end());
    } else {
      files.push_back(in);
    }
  }
  if (record_path(o.csv) == o.csv)
    throw MergeError("--csv " + o.csv + ": the merged table's record goes to " + o.csv +
                     "; name the table .csv");
  return merge_shards(o.csv, files, o.quiet);
}

}  // namespace cb
