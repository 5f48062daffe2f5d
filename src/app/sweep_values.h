// The per-value work of `chainbreak sweep`, shared with the Python module (src/python):
// the first break of each of a list of scenes (one per swept value), on a few threads
// (physics/lane_schedule.h shares them out). Parsing --vary, sharding and the CSV stay in the
// command.
#pragma once

#include <atomic>
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "app/solver.h"
#include "app/sweep_points.h"
#include "cluster/grid.h"
#include "exact/first_break.h"
#include "scene/scene.h"

namespace cb {

// The one check of a sweep's point, for `sweep`, its shards and the Python module: throws
// SceneError when `solver` cannot serve the scene (continuum; exact + expr).
void check_sweep_scene(const SceneDesc& scene, Solver solver);

// The first break of one scene by RK4 (stopping at it) or by the exact solution.
FirstBreak sweep_first_break(const SceneDesc& scene, Solver solver, const std::atomic<bool>* stop);

// sweep_first_break of every point's scene on `jobs` threads (0: all cores), results in order.
// Points of one group (SweepPoints::group) whose chains differ only in their thresholds run as
// one ensemble, each result still `run`'s on that point's scene bit for bit.
// Throws std::runtime_error with the first failure. When `stop` is set the remaining values
// are skipped (their results stay default: the caller checks `stop`). `on_progress`, when
// given, is called with the number of finished values from a watcher thread every 100 ms.
std::vector<FirstBreak> sweep_first_breaks(const SweepPoints& points, Solver solver, int jobs,
                                           const std::atomic<bool>* stop,
                                           const std::function<void(std::size_t)>& on_progress);

}  // namespace cb
