#include "physics/lane_schedule.h"

#include <algorithm>
#include <chrono>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>

#include "physics/stop_flag.h"
#include "threads/parked_threads.h"

namespace cb {

LaneSchedule schedule_lanes(const std::vector<int>& beads, bool lanes,
                            const std::vector<char>& alone) {
  LaneSchedule s;
  std::vector<int> lengths;
  for (std::size_t i = 0; i < beads.size(); ++i) {
    const int n = beads[i];
    if (!lanes || n > kMaxLaneBeads || (i < alone.size() && alone[i])) {
      s.singles.push_back(i);
      continue;
    }
    const auto at = std::find(lengths.begin(), lengths.end(), n);
    if (at == lengths.end()) {
      lengths.push_back(n);
      s.groups.push_back({i});
    } else {
      s.groups[static_cast<std::size_t>(at - lengths.begin())].push_back(i);
    }
  }
  return s;
}

void run_scheduled(const ScheduledRuns& runs, int jobs, const std::atomic<bool>* stop,
                   const std::function<void(std::size_t)>& on_progress) {
  jobs = threads_for(jobs);
  const LaneSchedule plan = schedule_lanes(runs.beads, runs.lanes, runs.alone);
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
      if (k >= group.size() || failed || stop_requested(stop)) return std::nullopt;
      LaneJob job = runs.job(group[k]);
      job.id = group[k];
      return job;
    };
    auto end = [&](std::size_t i, const LaneEnd& e) {
      runs.lane_end(i, e);
      ++done;
    };
    run_first_breaks_in_lanes(runs.beads[group.front()], take, end, simd, stop);
  };
  auto worker = [&] {
    for (std::size_t g = 0; g < plan.groups.size() && !failed && !stop_requested(stop); ++g) {
      try {
        lanes(g);
      } catch (const std::exception& e) {
        fail(e);
      }
    }
    for (std::size_t k; (k = next++) < plan.singles.size() && !failed && !stop_requested(stop);) {
      try {
        runs.single(plan.singles[k]);
      } catch (const std::exception& e) {
        fail(e);
      }
      ++done;
    }
  };
  std::vector<ParkedThread> pool;
  for (int t = 1; t < std::min<int>(jobs, static_cast<int>(runs.count)); ++t)
    pool.emplace_back(worker);
  ParkedThread watcher;
  if (on_progress)
    watcher = ParkedThread([&] {
      while (done < runs.count && !stop_requested(stop) && !failed) {
        on_progress(done);
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
      }
    });
  worker();
  for (auto& t : pool) t.join();
  if (watcher.joinable()) watcher.join();
  if (!failure.empty()) throw std::runtime_error(failure);
}

}  // namespace cb
