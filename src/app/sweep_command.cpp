// `chainbreak sweep`: which spring breaks first over a grid of scene keys (one or more
// --vary / --values), the whole grid or one shard of it; with --submit, as a Slurm array
// (sweep_submit.cpp).
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <mutex>
#include <thread>

#include "app/commands.h"
#include "app/csv.h"
#include "app/progress.h"
#include "app/sweep_setup.h"
#include "cluster/shard.h"
#include "exact/first_break.h"
#include "figures/break_maps.h"
#include "output/output_file.h"
#include "physics/integrator.h"
#include "resources/resources.h"

namespace cb {

int submit_sweep(const SweepOptions& o, const Grid& grid);  // sweep_submit.cpp

namespace {

// The first break of one scene by RK4 (stopping at it) or by the exact solution.
FirstBreak first_break_of(const SceneDesc& scene, const std::string& solver) {
  if (solver == "exact") return exact_first_break(scene.chain, scene.drive, scene.integrator.t_end);
  try {
    return simulated_first_break(scene.chain, scene.drive, scene.integrator.t_end,
                                 scene.integrator.dt, &g_interrupted);
  } catch (const std::runtime_error& e) {
    throw std::runtime_error(scene.name + ": " + e.what());
  }
}

// One CSV row: the point's values, then the spring that broke first and when (both empty
// when nothing broke by t_end).
void append_row(std::string& text, const std::vector<double>& values, const FirstBreak& b) {
  for (double v : values) {
    append_number(text, v);
    text += ',';
  }
  if (b.broke) {
    text += std::to_string(b.spring) + ",";
    append_number(text, b.tau);
  } else {
    text += ',';
  }
  text += '\n';
}

Shard sweep_shard(const std::string& text) {
  if (text == "slurm") return shard_from_slurm([](const char* name) { return std::getenv(name); });
  return parse_shard(text);
}

std::string host_name() {
  char buf[256] = {};
  return ::gethostname(buf, sizeof buf - 1) == 0 ? buf : "";
}

long peak_memory_kib() {
  rusage u{};
  return ::getrusage(RUSAGE_SELF, &u) == 0 ? u.ru_maxrss : 0;
}

}  // namespace

int sweep_command(const SweepOptions& o) {
  if (o.solver != "rk4" && o.solver != "exact")
    throw SceneError("--solver " + o.solver + ": sweep supports rk4 or exact");
  if (record_path(o.csv) == o.csv)
    throw SceneError("--csv " + o.csv + ": the sweep's record goes to " + o.csv +
                     " (the CSV's name with .json); name the CSV .csv");
  const auto start = std::chrono::steady_clock::now();
  const Grid grid = sweep_grid(o);
  if (!o.submit.empty()) return submit_sweep(o, grid);
  if (o.tasks > 0 || o.wait || !o.sbatch_args.empty() || o.max_running > 0)
    throw GridError(
        "--tasks, --wait, --sbatch-arg and --max-running go with --submit slurm; "
        "add --submit slurm, or drop them for a sweep on this machine");
  const Shard shard = sweep_shard(o.shard);
  const PointRange range = shard_points(grid.size(), shard);
  // Validate the scene and every value before any work: a bad value fails now, not at row 300.
  const std::vector<SceneDesc> scenes = point_scenes(o, grid, range);
  OutputFile out(o.csv);
  OutputFile out_record(record_path(o.csv));
  std::vector<FirstBreak> results(scenes.size());
  const int jobs = o.jobs > 0 ? o.jobs : std::max(1u, std::thread::hardware_concurrency());
  std::atomic<std::size_t> next{0};
  std::atomic<std::size_t> done{0};
  std::string failure;
  std::mutex failure_mutex;
  std::atomic<bool> failed{false};  // what the watcher reads: `failure` is the workers'
  auto worker = [&] {
    for (std::size_t i; (i = next++) < scenes.size() && !g_interrupted;) {
      try {
        results[i] = first_break_of(scenes[i], o.solver);
      } catch (const std::exception& e) {
        std::lock_guard lock(failure_mutex);
        if (failure.empty()) failure = e.what();
        failed = true;
        next = scenes.size();
      }
      ++done;
    }
  };
  {
    Progress progress("sweep", static_cast<double>(scenes.size()), o.quiet);
    std::vector<std::thread> pool;
    for (int t = 1; t < std::min<int>(jobs, static_cast<int>(scenes.size())); ++t)
      pool.emplace_back(worker);
    std::thread watcher;
    if (!o.quiet)
      watcher = std::thread([&] {
        // Reads the atomic flag, never `failure` (the workers write it under the mutex).
        while (done < scenes.size() && !g_interrupted && !failed) {
          progress.update(static_cast<double>(done));
          std::this_thread::sleep_for(std::chrono::milliseconds(100));
        }
      });
    worker();
    for (auto& t : pool) t.join();
    if (watcher.joinable()) watcher.join();
  }
  if (g_interrupted) return interrupted_status("no CSV written");
  if (!failure.empty()) {
    std::fprintf(stderr, "chainbreak: %s\n", failure.c_str());
    return 1;
  }
  std::string text = grid.csv_header() + "\n";
  for (std::size_t i = 0; i < results.size(); ++i)
    append_row(text, grid.point(range.first + i), results[i]);
  out.write(text);
  out.commit();
  // The record last: its presence says the CSV is complete (resubmission and merge rely on it).
  ShardRecord record = sweep_record(o, grid);
  record.shard = shard;
  record.points = range;
  record.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  record.peak_memory_kib = peak_memory_kib();
  record.host = host_name();
  out_record.write(record_json(record));
  out_record.commit();
  if (!o.quiet)
    std::fprintf(stderr, "sweep: %zu points written to %s\n", results.size(), o.csv.c_str());
  return 0;
}

}  // namespace cb
