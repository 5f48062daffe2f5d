// How a sweep's values are shared out between threads: those that can run side by side in SIMD
// lanes (physics/lanes.h: one chain length up to kMaxLaneBeads, RK4) go in groups by length,
// each group's values handed to lanes as lanes free up; the others run one by one. One pool
// of threads, first failure wins, a watcher that reads only atomics reports progress.
//
// Design note: this lived in the app layer (app/sweep_values.cpp), beside the CSV; it belongs
// beside the lanes, whose limits (kMaxLaneBeads) and call shape decide it. What a value is
// (a scene, a forcing) stays the caller's: it hands LaneJobs and single runs in by callback.
#pragma once

#include <atomic>
#include <cstddef>
#include <functional>
#include <vector>

#include "physics/lanes.h"

namespace cb {

// The values' indices split into lane groups (one chain length each, in order of first
// appearance) and singles (too long for lanes, or `lanes` false).
struct LaneSchedule {
  std::vector<std::vector<std::size_t>> groups;
  std::vector<std::size_t> singles;
};
LaneSchedule schedule_lanes(const std::vector<int>& beads, bool lanes);

struct ScheduledRuns {
  std::size_t count = 0;   // values 0..count-1
  std::vector<int> beads;  // each value's chain length
  bool lanes = true;       // false: every value runs alone (the exact solver)
  // The lane job of value i (throws to fail the whole schedule).
  std::function<LaneJob(std::size_t i)> job;
  // What a lane reported for value i (Failed included: the caller reruns it alone).
  std::function<void(std::size_t i, const LaneEnd& end)> lane_end;
  // Runs value i alone (throws to fail the whole schedule).
  std::function<void(std::size_t i)> single;
};

// Runs every value on `jobs` threads (0: all cores). Throws std::runtime_error with the first
// failure's message. When *stop becomes true the remaining values are skipped. `on_progress`,
// when given, is called with the number of finished values from a watcher thread every 100 ms.
void run_scheduled(const ScheduledRuns& runs, int jobs, const std::atomic<bool>* stop,
                   const std::function<void(std::size_t)>& on_progress);

}  // namespace cb
