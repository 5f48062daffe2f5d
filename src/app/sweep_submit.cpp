// `chainbreak sweep ... --submit slurm`: the grid as a Slurm job array of --tasks shards.
// Writes the sbatch script next to the CSV, submits only the shards that are not complete
// (a rerun resumes), and with --wait follows the array and merges.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <thread>

#include "app/commands.h"
#include "app/sweep_setup.h"
#include "cluster/merge.h"
#include "cluster/process.h"
#include "cluster/shard.h"
#include "cluster/slurm.h"
#include "output/output_file.h"

namespace cb {

namespace fs = std::filesystem;

namespace {

// A shard is complete when its CSV and record are there and the record is of this sweep.
bool shard_complete(const std::string& csv, const ShardRecord& expected, Shard shard) {
  if (!fs::exists(csv) || !fs::exists(record_path(csv))) return false;
  try {
    const ShardFile f = read_shard_file(csv);
    return record_mismatch(expected, f.record).empty() && f.record.shard.index == shard.index &&
           f.record.shard.count == shard.count;
  } catch (const MergeError&) {
    return false;  // damaged or of another sweep: compute it again
  }
}

// The array tasks of `job_id` still in the queue, by state ("PENDING", "RUNNING", ...):
// empty once the whole array has left the queue. False when squeue failed for another reason
// than an unknown (finished and purged) job, e.g. a controller too busy to answer: ask again.
bool queued_states(const std::string& job_id, std::vector<std::string>& states) {
  const auto r =
      run_process({"squeue", "--noheader", "--array", "--jobs", job_id, "--format", "%T"});
  states.clear();
  if (r.status != 0) return r.err.find("Invalid job id") != std::string::npos;
  std::size_t start = 0;
  for (std::size_t end; (end = r.out.find('\n', start)) != std::string::npos; start = end + 1)
    if (end > start) states.push_back(r.out.substr(start, end - start));
  return true;
}

std::size_t count_of(const std::vector<std::string>& v, const std::string& what) {
  return static_cast<std::size_t>(std::count(v.begin(), v.end(), what));
}

}  // namespace

int submit_sweep(const SweepOptions& o, const Grid& grid) {
  if (o.submit != "slurm")
    throw GridError("--submit " + o.submit + ": the only scheduler is slurm (--submit slurm)");
  const std::size_t n = grid.size();
  if (o.tasks < 1 || static_cast<std::size_t>(o.tasks) > n)
    throw GridError("--tasks " + std::to_string(o.tasks) +
                    ": --submit slurm needs --tasks S with " + "1 <= S <= " + std::to_string(n) +
                    " (the grid's points), e.g. --tasks " +
                    std::to_string(std::min<std::size_t>(n, 8)));
  if (o.shard != "1/1")
    throw GridError("--shard " + o.shard +
                    " with --submit: the array chooses each task's shard; "
                    "drop --shard");
  const auto S = static_cast<std::size_t>(o.tasks);
  if (!on_path("sbatch"))
    throw GridError(
        "--submit slurm: sbatch is not on PATH, so this machine cannot submit to Slurm. Run it "
        "on a Slurm login node (or install Slurm's client, Debian package slurm-client, with "
        "SLURM_CONF pointing at the cluster's slurm.conf), or run the shards without Slurm: "
        "chainbreak sweep ... --shard I/" +
        std::to_string(S) + " for I = 1.." + std::to_string(S) +
        " (e.g. with GNU parallel), then chainbreak merge");
  if (o.wait && !on_path("squeue"))
    throw GridError(
        "--wait: squeue is not on PATH, so the array cannot be followed; submit "
        "without --wait and run chainbreak merge when the job is done");

  std::vector<std::size_t> all;
  for (std::size_t i = 1; i <= S; ++i) all.push_back(i);
  std::size_t throttle = o.max_running > 0 ? static_cast<std::size_t>(o.max_running) : 0;
  std::vector<std::string> sbatch_lines;
  for (const auto& a : o.sbatch_args) {
    if (const std::size_t k = throttle_from_array_arg(a, array_spec(all, 0)); k > 0) {
      throttle = k;
      continue;
    }
    if (a.rfind("--array", 0) != 0) sbatch_lines.push_back(a);
  }
  // Task ids run 0..S-1 and Slurm refuses ids >= MaxArraySize: name the limit rather than
  // let sbatch fail with "Invalid job array specification".
  if (on_path("scontrol")) {
    const auto config = run_process({"scontrol", "show", "config"});
    const std::size_t limit = config.status == 0 ? max_array_size(config.out) : 1001;
    if (S > limit)
      throw GridError("--tasks " + std::to_string(S) + ": this cluster's MaxArraySize is " +
                      std::to_string(limit) + " (scontrol show config), so an array has at " +
                      "most " + std::to_string(limit) + " tasks; use --tasks " +
                      std::to_string(limit) + " or fewer (each task then computes more points)");
  }

  check_output_path(o.csv, "map.csv");
  const fs::path csv = fs::absolute(o.csv);
  const fs::path dir = csv.string() + ".shards";
  const fs::path script = fs::path(csv).replace_extension(".sbatch");
  // Every point's scene is checked here, before anything is queued.
  sweep_points(o, grid, {0, n});
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec)
    throw OutputError(dir.string() + ": cannot create the shards' folder (" + ec.message() +
                      "); choose a --csv in a writable folder");

  const ShardRecord expected = sweep_record(o, grid);
  std::vector<std::string> shard_csvs;
  std::vector<std::size_t> todo;
  for (std::size_t i : all) {
    const Shard s{i, S};
    shard_csvs.push_back((dir / (shard_stem(s) + ".csv")).string());
    if (!shard_complete(shard_csvs.back(), expected, s)) todo.push_back(i);
  }
  if (todo.empty()) {
    std::printf("all %zu shards in %s are complete; merging\n", S, dir.c_str());
    std::fflush(stdout);
    return merge_shards(o.csv, shard_csvs, o.quiet);
  }

  SbatchJob job;
  job.job_name = "chainbreak-" + csv.stem().string();
  job.shards = S;
  job.sweep = {chainbreak_exe()};
  job.sweep.insert(job.sweep.end(), expected.command.begin(), expected.command.end());
  job.shards_dir = dir.string();
  job.merge_command =
      shell_command({chainbreak_exe(), "merge", "--csv", csv.string(), dir.string()});
  job.sbatch_args = sbatch_lines;
  job.max_running = throttle;
  OutputFile script_file(script.string());
  script_file.write(sbatch_script(job));
  script_file.commit();
  fs::permissions(script, fs::perms::owner_exec, fs::perm_options::add, ec);

  std::vector<std::string> sbatch = {"sbatch", "--parsable"};
  if (todo.size() < S || throttle > 0) sbatch.push_back("--array=" + array_spec(todo, throttle));
  sbatch.push_back(script.string());
  const auto r = run_process(sbatch);
  const std::string job_id = parsable_job_id(r.out);
  if (r.status != 0 || job_id.empty()) {
    std::fprintf(stderr,
                 "chainbreak: sbatch failed (status %d): %s\nThe script is %s; fix the cause "
                 "(options, SLURM_CONF, the cluster) and rerun, or submit it by hand.\n",
                 r.status, (r.err + r.out).c_str(), script.c_str());
    return 1;
  }
  std::printf("Slurm job %s: %zu of %zu shards (array %s)%s\n", job_id.c_str(), todo.size(), S,
              array_spec(todo, throttle).c_str(),
              todo.size() < S ? ", the others are complete" : "");
  std::printf("shards: %s%s\n", shard_csvs[todo.front() - 1].c_str(),
              todo.size() > 1
                  ? (" ... " + fs::path(shard_csvs[todo.back() - 1]).filename().string()).c_str()
                  : "");
  std::printf("script: %s\nmerge:  %s\n", script.c_str(), job.merge_command.c_str());
  std::fflush(stdout);
  if (!o.wait) return 0;

  // Follow the array: poll squeue (each call is cheap for the controller at this rate) and
  // count finished shards by their records.
  const auto start = std::chrono::steady_clock::now();
  std::string last_line;
  for (int polls = 0;; ++polls) {
    if (g_interrupted) {
      std::fprintf(stderr,
                   "chainbreak: stopped waiting; job %s keeps running (scancel %s stops it). "
                   "Merge later with: %s\n",
                   job_id.c_str(), job_id.c_str(), job.merge_command.c_str());
      return 130;
    }
    std::vector<std::string> states;
    const bool answered = queued_states(job_id, states);
    std::size_t done = 0;
    for (const auto& f : shard_csvs) done += fs::exists(record_path(f)) ? 1 : 0;
    char line[160];
    std::snprintf(line, sizeof line, "slurm job %s: %zu/%zu shards done, %zu running, %zu pending",
                  job_id.c_str(), done, S, count_of(states, "RUNNING"),
                  count_of(states, "PENDING"));
    if (!o.quiet && line != last_line) {  // a line when something changed, with the time
      const double t =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      std::fprintf(stderr, "%s (%.0f s)\n", line, t);
      last_line = line;
    }
    if (answered && states.empty()) break;
    // Quick polls while a short array finishes, then every 10 s to spare the controller.
    std::this_thread::sleep_for(std::chrono::milliseconds(polls < 60 ? 500 : 10000));
  }
  std::vector<std::string> present;
  for (const auto& f : shard_csvs)
    if (fs::exists(record_path(f))) present.push_back(f);
  if (present.empty()) {
    std::fprintf(stderr,
                 "chainbreak: job %s left the queue and no shard is complete; see the logs "
                 "%s/slurm-%s_*.out, fix the cause and rerun the same command\n",
                 job_id.c_str(), dir.c_str(), job_id.c_str());
    return 1;
  }
  if (present.size() < S)
    std::fprintf(
        stderr, "chainbreak: %zu of %zu shards did not complete; Slurm's logs: %s/slurm-%s_*.out\n",
        S - present.size(), S, dir.c_str(), job_id.c_str());
  return merge_shards(o.csv, present, o.quiet);
}

}  // namespace cb
