// The per-value work of `chainbreak sweep`, shared with the Python module (src/python):
// the first break of each of a list of scenes (one per swept value), on a few threads.
// Parsing --vary, sharding and the CSV stay in the command.
#pragma once

#include <atomic>
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "exact/first_break.h"
#include "scene/scene.h"

namespace cb {

// Throws SceneError when `solver` cannot serve the scene (not rk4/exact; exact + expr).
void check_sweep_scene(const SceneDesc& scene, const std::string& solver);

// The first break of one scene by RK4 (stopping at it) or by the exact solution.
FirstBreak sweep_first_break(const SceneDesc& scene, const std::string& solver,
                             const std::atomic<bool>* stop);

// sweep_first_break of every scene on `jobs` threads (0: all cores), results in order.
// Throws std::runtime_error with the first failure. When `stop` is set the remaining values
// are skipped (their results stay default: the caller checks `stop`). `on_progress`, when
// given, is called with the number of finished values from a watcher thread every 100 ms.
std::vector<FirstBreak> sweep_first_breaks(const std::vector<SceneDesc>& scenes,
                                           const std::string& solver, int jobs,
                                           const std::atomic<bool>* stop,
                                           const std::function<void(std::size_t)>& on_progress);

}  // namespace cb
