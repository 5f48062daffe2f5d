// The flag long work polls to end early: set by a signal handler (src/interrupt) or a GUI;
// a caller that cannot be interrupted passes none (nullptr). Relaxed order is enough: the flag
// carries no data, and the work that sees it late by a few steps only ends a few steps later.
#pragma once

#include <atomic>

namespace cb {

inline bool stop_requested(const std::atomic<bool>* flag) {
  return flag && flag->load(std::memory_order_relaxed);
}

}  // namespace cb
