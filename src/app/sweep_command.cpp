// `chainbreak sweep`: which spring breaks first as one scene key varies.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <mutex>
#include <thread>

#include "app/commands.h"
#include "app/csv.h"
#include "app/option_parsers.h"
#include "app/progress.h"
#include "exact/first_break.h"
#include "figures/break_maps.h"
#include "output/output_file.h"
#include "physics/integrator.h"

namespace cb {

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

}  // namespace

int sweep_command(const SweepOptions& o) {
  if (o.solver != "rk4" && o.solver != "exact")
    throw SceneError("--solver " + o.solver + ": sweep supports rk4 or exact");
  const Vary vary = parse_vary(o.vary);
  const auto [first, last] = parse_shard(o.shard, vary.count);
  // Validate the scene and every value before any work: a bad value fails now, not at row 300.
  std::vector<SceneDesc> scenes;
  for (int i = first; i < last; ++i) {
    auto overrides = o.overrides;
    overrides.push_back({vary.key, number_text(vary.value(i))});
    scenes.push_back(load_scene(o.scene, overrides));
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
    Progress progress("sweep " + vary.key, static_cast<double>(scenes.size()), o.quiet);
    std::vector<std::thread> pool;
    for (int t = 1; t < std::min<int>(jobs, static_cast<int>(scenes.size())); ++t)
      pool.emplace_back(worker);
    std::thread watcher;
    if (!o.quiet)
      watcher = std::thread([&] {
        while (done < scenes.size() && !g_interrupted && !failed) {
          progress.update(static_cast<double>(done));
          std::this_thread::sleep_for(std::chrono::milliseconds(100));
        }
      });
    worker();
    for (auto& t : pool) t.join();
    if (watcher.joinable()) watcher.join();
  }
  if (g_interrupted) {
    std::fprintf(stderr, "chainbreak: interrupted; no CSV written\n");
    return 130;
  }
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
