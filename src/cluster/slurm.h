// The Slurm side of a sweep: the sbatch array script (plain text a user can read, edit and
// resubmit), the --array spec, and reading what sbatch, scontrol and squeue print.
// Array task k computes shard k+1 (0-based task ids, so S shards fit under MaxArraySize = S),
// and takes its shard from its own task id, so an array of some indices (a resubmission of
// the shards that failed) computes exactly those shards.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace cb {

struct SbatchJob {
  std::string job_name;
  std::size_t shards = 1;          // S
  std::vector<std::string> sweep;  // chainbreak (absolute) sweep SCENE ... without --shard/--csv
  std::string shards_dir;          // absolute; CSVs, records and Slurm's logs go here
  std::string merge_command;       // printed in the comments: how to merge by hand
  std::vector<std::string> sbatch_args;  // extra #SBATCH lines, as the user gave them
  std::size_t max_running = 0;           // the array's %K throttle; 0: none
};

// "0-7%2", "1,4": array task ids (shard - 1) for shards (1-based, sorted), with a throttle.
std::string array_spec(const std::vector<std::size_t>& shards, std::size_t max_running);
std::string sbatch_script(const SbatchJob& job);

// MaxArraySize from `scontrol show config` (Slurm's default, 1001, when it is not listed).
// The largest array task id is MaxArraySize - 1.
std::size_t max_array_size(const std::string& show_config);
// The job id from `sbatch --parsable` ("1234" or "1234;cluster"); empty when there is none.
std::string parsable_job_id(const std::string& sbatch_out);

// A `--sbatch-arg=--array=SPEC` the user gave: only a throttle "%K" is taken from it (the
// tasks are chainbreak's to choose). Returns K, 0 when none; throws GridError when SPEC
// lists other indices than `expected` (the full array).
std::size_t throttle_from_array_arg(const std::string& arg, const std::string& expected);

}  // namespace cb
