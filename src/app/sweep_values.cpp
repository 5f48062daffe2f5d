#include "app/sweep_values.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <chrono>
#include <mutex>
#include <stdexcept>
#include <thread>

#include "drive/drive.h"
#include "figures/break_maps.h"
#include "physics/lanes.h"

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

namespace {

// The sweep's values that RK4 runs side by side in lanes (physics/lanes.h): those of one chain
// length up to kMaxLaneBeads, in groups by length. The others run one by one.
struct LaneGroups {
  std::vector<std::vector<std::size_t>> groups;  // scene indices of one length each
  std::vector<std::size_t> singles;
};

LaneGroups lane_groups(const std::vector<SceneDesc>& scenes, const std::string& solver) {
  LaneGroups g;
  std::vector<int> lengths;
  for (std::size_t i = 0; i < scenes.size(); ++i) {
    const int n = scenes[i].chain.beads;
    // The lanes kernel has the harmonic stencil only: anharmonic chains run one by one.
    if (solver != "rk4" || n > kMaxLaneBeads || scenes[i].chain.anharmonic()) {
      g.singles.push_back(i);
      continue;
    }
    const auto at = std::find(lengths.begin(), lengths.end(), n);
    if (at == lengths.end()) {
      lengths.push_back(n);
      g.groups.push_back({i});
    } else {
      g.groups[static_cast<std::size_t>(at - lengths.begin())].push_back(i);
    }
  }
  return g;
}

}  // namespace

std::vector<FirstBreak> sweep_first_breaks(const std::vector<SceneDesc>& scenes,
                                           const std::string& solver, int jobs,
                                           const std::atomic<bool>* stop,
                                           const std::function<void(std::size_t)>& on_progress) {
  std::vector<FirstBreak> results(scenes.size());
  if (jobs <= 0) jobs = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  auto stopped = [stop] { return stop && stop->load(); };
  const LaneGroups plan = lane_groups(scenes, solver);
  // Every worker takes values from the lane groups first (a lane that ends takes the next value
  // of its group), then the values run one by one.
  std::vector<std::atomic<std::size_t>> next_in_group(plan.groups.size());
  std::atomic<std::size_t> next{0};
  std::atomic<std::size_t> done{0};
  std::string failure;
  std::mutex failure_mutex;
  std::atomic<bool> failed{false};
  auto fail = [&](const std::exception& e) {
    std::lock_guard lock(failure_mutex);
    if (failure.empty()) failure = e.what();
    failed = true;
  };
  const SimdPath simd = active_simd();
  auto lanes = [&](std::size_t g) {
    const auto& group = plan.groups[g];
    auto take = [&]() -> std::optional<LaneJob> {
      const std::size_t k = next_in_group[g]++;
      if (k >= group.size() || failed || stopped()) return std::nullopt;
      const SceneDesc& scene = scenes[group[k]];
      LaneJob job;
      job.id = group[k];
      job.params = scene.chain;
      try {
        job.forcing = make_forcing(scene.drive);
      } catch (const std::runtime_error& e) {  // as sweep_first_break names it
        throw std::runtime_error(scene.name + ": " + e.what());
      }
      job.dt = scene.integrator.dt;
      job.last_step = std::llround(scene.integrator.t_end / scene.integrator.dt);
      return job;
    };
    auto end = [&](std::size_t i, const LaneEnd& e) {
      // A value whose state stopped being finite runs again alone, for Integrator's message.
      if (e.kind == LaneEnd::Kind::Failed) results[i] = sweep_first_break(scenes[i], solver, stop);
      if (e.kind == LaneEnd::Kind::Broke) results[i] = {true, e.first.spring, e.first.tau};
      ++done;
    };
    run_first_breaks_in_lanes(scenes[group.front()].chain.beads, take, end, simd, stop);
  };
  auto worker = [&] {
    for (std::size_t g = 0; g < plan.groups.size() && !failed && !stopped(); ++g) {
      try {
        lanes(g);
      } catch (const std::exception& e) {
        fail(e);
      }
    }
    for (std::size_t k; (k = next++) < plan.singles.size() && !failed && !stopped();) {
      const std::size_t i = plan.singles[k];
      try {
        results[i] = sweep_first_break(scenes[i], solver, stop);
      } catch (const std::exception& e) {
        fail(e);
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
