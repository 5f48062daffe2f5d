// First breaks of many chains at once: an ensemble of same-length chains (a sweep over beta,
// gamma, phi_c, amplitude, ...) integrated side by side in SIMD lanes, each lane stopping at
// its own first break.
//
// Design note: a sweep of the paper's N = 30 chain spends its time on steps of 30 beads, too
// few to fill a vector or to hide the per-step bookkeeping; eight chains interleaved bead by
// bead fill one. Every lane keeps its own clock (step count, split points, kicks), so a lane
// whose chain broke takes the next value at once instead of idling until the slowest lane
// finishes. A lane does, operation for operation, what Integrator does for that chain alone
// (rk4_tile_kernel.inc, Integrator::step and advance_interval) up to its first break, so the
// spring, tau and step are bit-identical to `run` on that value (tests/test_lanes.cpp).
#pragma once

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>

#include "physics/chain.h"
#include "physics/forcing.h"
#include "physics/simd.h"

namespace cb {

// One value of the ensemble: what Integrator(params, forcing, {dt}) would run, stopping at the
// first break or after step last_step (t_end on the step grid).
struct LaneJob {
  std::size_t id = 0;  // the caller's index, handed back with the result
  ChainParams params;
  Forcing forcing;
  double dt = 0.01;
  std::int64_t last_step = 0;
};

struct LaneEnd {
  enum class Kind {
    Broke,    // the first break: spring, tau, step as Integrator's state().breaks.front()
    Reached,  // no break by last_step
    Failed,   // the state stopped being finite: rerun the value with Integrator for the message
  };
  Kind kind = Kind::Reached;
  BreakEvent first;
};

// Chains longer than this are run one by one: eight interleaved copies would leave the caches.
inline constexpr int kMaxLaneBeads = 4096;

// Runs every job that `next` hands out (std::nullopt: no more), all of `beads` beads (at most
// kMaxLaneBeads), calling `done` with each job's id and end, in the order they end. Returns
// false when *cancel became true (jobs still running are dropped without a `done`).
bool run_first_breaks_in_lanes(int beads, const std::function<std::optional<LaneJob>()>& next,
                               const std::function<void(std::size_t, const LaneEnd&)>& done,
                               SimdPath simd, const std::atomic<bool>* cancel = nullptr);

}  // namespace cb
