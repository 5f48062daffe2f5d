#include "cluster/slurm.h"

#include <charconv>
#include <cstdio>
#include <sstream>

#include "cluster/grid.h"
#include "cluster/shard.h"
#include "cluster/shard_record.h"

namespace cb {

std::string array_spec(const std::vector<std::size_t>& shards, std::size_t max_running) {
  std::string spec;
  for (std::size_t i = 0; i < shards.size();) {
    std::size_t j = i;
    while (j + 1 < shards.size() && shards[j + 1] == shards[j] + 1) ++j;
    spec += (spec.empty() ? "" : ",") + std::to_string(shards[i] - 1);
    if (j > i) spec += "-" + std::to_string(shards[j] - 1);
    i = j + 1;
  }
  if (max_running > 0) spec += "%" + std::to_string(max_running);
  return spec;
}

std::string sbatch_script(const SbatchJob& job) {
  std::vector<std::size_t> all;
  for (std::size_t i = 1; i <= job.shards; ++i) all.push_back(i);
  const std::string s = std::to_string(job.shards);
  char count[16];
  std::snprintf(count, sizeof count, "%04zu", job.shards);
  std::ostringstream o;
  o << "#!/bin/bash\n"
    << "# A chainbreak sweep as a Slurm job array, written by `chainbreak sweep ... --submit "
       "slurm`.\n"
    << "# Array task k computes shard k+1 of " << s << " (a contiguous block of the grid) into\n"
    << "#   " << job.shards_dir << "/shard-<k+1>-of-" << count << ".csv\n"
    << "# with a record of what made it beside it (.json, written last: a shard is complete\n"
    << "# when its record is there).\n"
    << "#\n"
    << "# Submit by hand: sbatch THIS_FILE (every shard); only some shards, e.g. the 2nd and\n"
    << "# 5th: sbatch --array=1,4 THIS_FILE (task ids are shard numbers minus one). Rerunning the\n"
    << "# same `chainbreak sweep ... --submit slurm` does that for the shards that are not\n"
    << "# complete. When all are done, merge them:\n"
    << "#   " << job.merge_command << "\n"
    << "#SBATCH --job-name=" << job.job_name << "\n"
    << "#SBATCH --array=" << array_spec(all, job.max_running) << "\n"
    << "#SBATCH --output=" << job.shards_dir << "/slurm-%A_%a.out\n";
  for (const auto& a : job.sbatch_args) o << "#SBATCH " << a << "\n";
  o << "set -euo pipefail\n"
    << "shard=$((SLURM_ARRAY_TASK_ID + 1))\n"
    << "printf -v name 'shard-%04d-of-" << count << ".csv' \"$shard\"\n"
    << "# One thread per CPU Slurm gave the task (1 unless --cpus-per-task).\n"
    << "exec " << shell_command(job.sweep) << " \\\n"
    << "  --shard \"$shard/" << s << "\" --csv " << shell_quote(job.shards_dir)
    << "/\"$name\" --jobs \"${SLURM_CPUS_PER_TASK:-1}\" --quiet\n";
  return o.str();
}

std::size_t max_array_size(const std::string& show_config) {
  std::istringstream in(show_config);
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("MaxArraySize", 0) != 0) continue;
    const auto eq = line.find('=');
    if (eq == std::string::npos) continue;
    std::size_t pos = line.find_first_not_of(' ', eq + 1);
    std::size_t v = 0;
    if (pos == std::string::npos) continue;
    const auto r = std::from_chars(line.data() + pos, line.data() + line.size(), v);
    if (r.ec == std::errc()) return v;
  }
  return 1001;
}

std::string parsable_job_id(const std::string& out) {
  const auto end = out.find_first_of(";\n");
  const std::string id = out.substr(0, end);
  if (id.empty() || id.find_first_not_of("0123456789") != std::string::npos) return {};
  return id;
}

std::size_t throttle_from_array_arg(const std::string& arg, const std::string& expected) {
  const std::string prefix = "--array=";
  if (arg.rfind(prefix, 0) != 0) return 0;
  const std::string spec = arg.substr(prefix.size());
  const auto pct = spec.find('%');
  const std::string indices = spec.substr(0, pct);
  if (!indices.empty() && indices != expected)
    throw GridError("--sbatch-arg=" + arg + ": chainbreak chooses the array's task ids (" +
                    expected + ", one per shard of --tasks); give only a throttle, " +
                    "--sbatch-arg=--array=" + expected + "%K or --max-running K");
  if (pct == std::string::npos) return 0;
  std::size_t k = 0;
  const std::string t = spec.substr(pct + 1);
  const auto r = std::from_chars(t.data(), t.data() + t.size(), k);
  if (r.ec != std::errc() || r.ptr != t.data() + t.size() || k == 0)
    throw GridError("--sbatch-arg=" + arg +
                    ": the throttle after % must be a whole number "
                    "above zero, e.g. --array=" +
                    expected + "%4");
  return k;
}

}  // namespace cb
