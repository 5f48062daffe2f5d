// `chainbreak sweep`: which spring breaks first over a grid of scene keys (one or more
// --vary / --values), the whole grid or one shard of it; with --submit, as a Slurm array
// (sweep_submit.cpp).
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <mutex>

#include "app/commands.h"
#include "app/csv.h"
#include "app/h5_sweep_file.h"
#include "app/progress.h"
#include "app/sweep_setup.h"
#include "app/sweep_values.h"
#include "cluster/shard.h"
#include "exact/first_break.h"
#include "figures/break_maps.h"
#include "output/output_file.h"
#include "output/output_lock.h"
#include "physics/integrator.h"
#include "resources/resources.h"
#include "threads/parked_threads.h"

namespace cb {

int submit_sweep(const SweepOptions& o, const Grid& grid);  // sweep_submit.cpp

namespace {

// Appends an integer's digits (std::to_string builds a string a number: a 10^4-seed CSV's
// rows took ~0.1 us each).
template <class Int>
void append_integer(std::string& text, Int value) {
  char buf[24];
  text.append(buf, std::to_chars(buf, buf + sizeof buf, value).ptr);
}

// One CSV row: the point's values, then the spring that broke first and when (both empty
// when nothing broke by t_end). Whole-number keys (chain.seed: whole[k] set) as integers:
// 100000, not the shortest form 1e+05.
void append_row(std::string& text, const std::vector<char>& whole,
                const std::vector<double>& values, const FirstBreak& b) {
  for (std::size_t k = 0; k < values.size(); ++k) {
    if (whole[k] && std::abs(values[k]) < 9.0e15)
      append_integer(text, static_cast<long long>(values[k]));
    else
      append_number(text, values[k]);
    text += ',';
  }
  if (b.broke) {
    append_integer(text, b.spring);
    text += ',';
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
  // The sweep's threads, started now and parked, so that its first parallel phase, a few ms
  // from here, finds them running (parked_threads.h: a VM can start a thread ms late).
  prestart_threads(threads_for(o.jobs) - 1);
  check_sweep_solver(o.solver);
  if (record_path(o.csv) == o.csv)
    throw SceneError("--csv " + o.csv + ": the sweep's record goes to " + o.csv +
                     " (the CSV's name with .json); name the CSV .csv");
  const auto start = std::chrono::steady_clock::now();
  const Grid grid = sweep_grid(o);
  if (!o.submit.empty() && !o.h5.empty())
    throw GridError("--h5 " + o.h5 +
                    ": an array's shards are merged as CSV; write HDF5 from a sweep on this "
                    "machine (drop --submit) or drop --h5");
  if (!o.submit.empty()) return submit_sweep(o, grid);
  if (o.tasks > 0 || o.wait || !o.sbatch_args.empty() || o.max_running > 0)
    throw GridError(
        "--tasks, --wait, --sbatch-arg and --max-running go with --submit slurm; "
        "add --submit slurm, or drop them for a sweep on this machine");
  const Shard shard = sweep_shard(o.shard);
  const PointRange range = shard_points(grid.size(), shard);
  // The memory it will take, before building any point (issue #12: a sweep of a 10^8-bead
  // chain used to die in the exact solver's first allocation, or later, at the kernel's hand).
  require_memory(sweep_memory(o, grid, range), machine_memory(), "sweep " + o.scene,
                 "use fewer beads (chain.beads), fewer --jobs, or a shard of the grid (--shard)");
  // Validate the scene and every value before any work: a bad value fails now, not at row 300.
  const SweepPoints points = sweep_points(o, grid, range);
  // The CSV and its record are one set: a second sweep or a merge to the same name is refused
  // while this one runs (output_lock.h), so the pair never comes from two runs.
  if (!o.h5.empty()) check_output_path(o.h5, "out.h5");
  const OutputLock lock(o.csv);
  OutputFile out(o.csv);
  OutputFile out_record(record_path(o.csv));
  // The per-value work is sweep_values.h's, shared with the Python module: one pool of
  // `jobs` threads, a watcher that reads only atomics (issue #12, row 13), first failure wins.
  std::vector<FirstBreak> results;
  try {
    Progress progress("sweep", static_cast<double>(points.size()), o.quiet);
    std::function<void(std::size_t)> on_progress;
    if (!o.quiet)
      on_progress = [&](std::size_t done) { progress.update(static_cast<double>(done)); };
    results = sweep_first_breaks(points, o.solver, o.jobs, &g_interrupted, on_progress);
  } catch (const std::runtime_error& e) {
    std::fprintf(stderr, "chainbreak: %s\n", e.what());
    return 1;
  }
  if (g_interrupted) return interrupted_status("no CSV written");
  // The record (its JSON lists the grid's values: ~1 ms for 10^4 seeds) is written on a parked
  // thread while this one writes the CSV; its wall time is the sweep's up to its results.
  ShardRecord record = sweep_record(o, grid);
  record.shard = shard;
  record.points = range;
  record.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  record.peak_memory_kib = peak_memory_kib();
  record.host = host_name();
  std::exception_ptr record_error;
  ParkedThread recorder([&] {
    try {
      out_record.write(record_json(record));
    } catch (...) {
      record_error = std::current_exception();
    }
  });
  // Written kSweepCsvChunk bytes at a time: a 2 x 10^5-point grid's 7 MB of text built whole
  // grew by copies into fresh pages (a tenth of that sweep's time, page faults included).
  std::string text = grid.csv_header() + "\n";
  std::vector<double> values;
  std::vector<char> whole;
  for (const GridAxis& axis : grid.axes) whole.push_back(whole_number_key(axis.key));
  for (std::size_t i = 0; i < results.size(); ++i) {
    grid.point_into(range.first + i, values);
    append_row(text, whole, values, results[i]);
    if (text.size() >= kSweepCsvChunk) {
      out.write(text);
      text.clear();
    }
  }
  out.write(text);
  recorder.join();
  if (record_error) std::rethrow_exception(record_error);
  // Both made durable at once, then published in order: the CSV, the HDF5 table, and the record
  // last: its presence says the sweep's files are complete (resubmission and merge rely on it).
  flush_together({&out, &out_record});
  out.publish();
  if (!o.h5.empty()) write_h5_sweep(o.h5, grid, range, results, record);
  out_record.publish();
  if (!o.quiet)
    std::fprintf(stderr, "sweep: %zu points written to %s\n", results.size(), o.csv.c_str());
  return 0;
}

}  // namespace cb
