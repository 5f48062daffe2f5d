// `chainbreak sweep`: which spring breaks first as one scene key varies.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <mutex>
#include <thread>

#include "app/commands.h"
#include "app/csv.h"
#include "app/progress.h"
#include "exact/first_break.h"
#include "figures/break_maps.h"
#include "output/output_file.h"
#include "physics/integrator.h"
#include "resources/resources.h"

namespace cb {

namespace {

struct Vary {
  std::string key;
  double lo = 0, hi = 0;
  int count = 0;
  bool log = false;
  double value(int i) const {
    if (count == 1) return lo;
    const double w = static_cast<double>(i) / (count - 1);
    return log ? std::exp(std::log(lo) + w * (std::log(hi) - std::log(lo))) : lo + w * (hi - lo);
  }
};

bool parse_double(std::string_view text, double& out) {
  const auto r = std::from_chars(text.data(), text.data() + text.size(), out);
  return r.ec == std::errc() && r.ptr == text.data() + text.size();
}

std::vector<std::string_view> split(std::string_view text, char sep) {
  std::vector<std::string_view> parts;
  for (std::size_t start = 0;;) {
    const auto end = text.find(sep, start);
    parts.push_back(text.substr(start, end - start));
    if (end == std::string_view::npos) return parts;
    start = end + 1;
  }
}

Vary parse_vary(const std::string& text) {
  const std::string usage =
      "--vary " + text + ": expected KEY=LO:HI:COUNT[:log], e.g. --vary chain.threshold=1:300:420";
  const auto eq = text.find('=');
  if (eq == std::string::npos || eq == 0) throw SceneError(usage);
  Vary v;
  v.key = text.substr(0, eq);
  const auto parts = split(std::string_view(text).substr(eq + 1), ':');
  double count = 0;
  if (parts.size() < 3 || parts.size() > 4 || !parse_double(parts[0], v.lo) ||
      !parse_double(parts[1], v.hi) || !parse_double(parts[2], count) || count < 1 ||
      count != std::floor(count) || (parts.size() == 4 && parts[3] != "log"))
    throw SceneError(usage);
  // Checked as a double, before it becomes an int (1e12 would not fit).
  if (count > kMaxSweepValues)
    throw SceneError("--vary " + text + ": COUNT = " + std::string(parts[2]) +
                     " values is more than the limit of " + std::to_string(kMaxSweepValues) +
                     "; use fewer values, or split the range over several sweeps (--shard)");
  v.count = static_cast<int>(count);
  v.log = parts.size() == 4;
  if (v.log && (v.lo <= 0 || v.hi <= 0))
    throw SceneError("--vary " + text + ": a log sweep needs LO and HI above zero");
  return v;
}

// Shard "I/S" (I in 1..S) of `count` values: a contiguous block, so concatenating the
// shards' rows in order gives the full table.
std::pair<int, int> parse_shard(const std::string& text, int count) {
  const auto parts = split(text, '/');
  double i = 0, s = 0;
  if (parts.size() != 2 || !parse_double(parts[0], i) || !parse_double(parts[1], s) || s < 1 ||
      i < 1 || i > s || i != std::floor(i) || s != std::floor(s))
    throw SceneError("--shard " + text + ": expected I/S with 1 <= I <= S, e.g. --shard 2/8");
  const long n = count, si = static_cast<long>(s), ii = static_cast<long>(i) - 1;
  return {static_cast<int>(n * ii / si), static_cast<int>(n * (ii + 1) / si)};
}

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

}  // namespace

int sweep_command(const SweepOptions& o) {
  if (o.solver != "rk4" && o.solver != "exact")
    throw SceneError("--solver " + o.solver + ": sweep supports rk4 or exact");
  const Vary vary = parse_vary(o.vary);
  const auto [first, last] = parse_shard(o.shard, vary.count);
  // Validate the scene and every value before any work: a bad value fails now, not at row 300.
  // The file is read once; each value is set in memory and checked by validate().
  const SceneVariations variations(o.scene, o.overrides);
  std::vector<SceneDesc> scenes;
  for (int i = first; i < last; ++i) {
    if (g_interrupted) return interrupted_status("no CSV written");
    scenes.push_back(
        variations.with(vary.key, vary.value(i),
                        "--vary " + o.vary + " (value " + number_text(vary.value(i)) + ")"));
    if (o.solver == "exact" && scenes.back().drive.type == DriveType::Expr)
      throw SceneError(
          o.scene +
          ": the exact first break has no closed form for an expr drive; use --solver rk4");
  }
  OutputFile out(o.csv);
  std::vector<FirstBreak> results(scenes.size());
  const int jobs = o.jobs > 0 ? o.jobs : std::max(1u, std::thread::hardware_concurrency());
  std::atomic<std::size_t> next{0};
  std::atomic<std::size_t> done{0};
  std::string failure;
  std::mutex failure_mutex;
  auto worker = [&] {
    for (std::size_t i; (i = next++) < scenes.size() && !g_interrupted;) {
      try {
        results[i] = first_break_of(scenes[i], o.solver);
      } catch (const std::exception& e) {
        std::lock_guard lock(failure_mutex);
        if (failure.empty()) failure = e.what();
        next = scenes.size();
      }
      ++done;
    }
  };
  {
    Progress progress("sweep " + vary.key, static_cast<double>(scenes.size()), o.quiet);
    std::vector<std::thread> pool;
    for (int t = 1; t < std::min<int>(jobs, static_cast<int>(scenes.size())); ++t)
      pool.emplace_back(worker);
    std::thread watcher;
    if (!o.quiet)
      watcher = std::thread([&] {
        while (done < scenes.size() && !g_interrupted && failure.empty()) {
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
  std::string text = "value,spring,tau\n";
  for (std::size_t i = 0; i < results.size(); ++i) {
    append_number(text, vary.value(first + static_cast<int>(i)));
    text += ',';
    if (results[i].broke) {
      text += std::to_string(results[i].spring) + ",";
      append_number(text, results[i].tau);
    } else {
      text += ',';
    }
    text += '\n';
  }
  out.write(text);
  out.commit();
  if (!o.quiet)
    std::fprintf(stderr, "sweep: %zu values of %s written to %s\n", results.size(),
                 vary.key.c_str(), o.csv.c_str());
  return 0;
}

}  // namespace cb
