#include "app/sweep_values.h"

#include <algorithm>
#include <chrono>
#include <mutex>
#include <stdexcept>
#include <thread>

#include "figures/break_maps.h"

namespace cb {

void check_sweep_scene(const SceneDesc& scene, const std::string& solver) {
  if (solver != "rk4" && solver != "exact")
    throw SceneError("--solver " + solver + ": sweep supports rk4 or exact");
  if (solver == "exact" && scene.drive.type == DriveType::Expr)
    throw SceneError(scene.path +
                     ": the exact first break has no closed form for an expr drive; use "
                     "--solver rk4");
}

FirstBreak sweep_first_break(const SceneDesc& scene, const std::string& solver,
                             const std::atomic<bool>* stop) {
  if (solver == "exact") return exact_first_break(scene.chain, scene.drive, scene.integrator.t_end);
  try {
    return simulated_first_break(scene.chain, scene.drive, scene.integrator.t_end,
                                 scene.integrator.dt, stop);
  } catch (const std::runtime_error& e) {
    throw std::runtime_error(scene.name + ": " + e.what());
  }
}

std::vector<FirstBreak> sweep_first_breaks(const std::vector<SceneDesc>& scenes,
                                           const std::string& solver, int jobs,
                                           const std::atomic<bool>* stop,
                                           const std::function<void(std::size_t)>& on_progress) {
  std::vector<FirstBreak> results(scenes.size());
  if (jobs <= 0) jobs = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  auto stopped = [stop] { return stop && stop->load(); };
  std::atomic<std::size_t> next{0};
  std::atomic<std::size_t> done{0};
  std::string failure;
  std::mutex failure_mutex;
  std::atomic<bool> failed{false};
  auto worker = [&] {
    for (std::size_t i; (i = next++) < scenes.size() && !stopped();) {
      try {
        results[i] = sweep_first_break(scenes[i], solver, stop);
      } catch (const std::exception& e) {
        std::lock_guard lock(failure_mutex);
        if (failure.empty()) failure = e.what();
        failed = true;
        next = scenes.size();
      }
      ++done;
    }
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < std::min<int>(jobs, static_cast<int>(scenes.size())); ++t)
    pool.emplace_back(worker);
  std::thread watcher;
  if (on_progress)
    watcher = std::thread([&] {
      while (done < scenes.size() && !stopped() && !failed) {
        on_progress(done);
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
      }
    });
  worker();
  for (auto& t : pool) t.join();
  if (watcher.joinable()) watcher.join();
  if (!failure.empty()) throw std::runtime_error(failure);
  return results;
}

}  // namespace cb
