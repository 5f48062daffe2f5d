// The one loop that advances an Integrator: every command (run, sweep, render, snapshot,
// the figures, the viewer) says when to stop and what to watch, and this loop does the
// stepping.
//
// Design note: in the spirit of MuJoCo's single mj_step, the stop rules and the observers
// are plain values, so a new caller (an ensemble lane, a signal handler, a GUI stop button)
// adds a value instead of a sixth hand-written loop, and the after_break rule exists once.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "physics/integrator.h"

namespace cb {

// When a run ends: whichever of these comes first.
struct StopRule {
  std::int64_t last_step = 0;  // t_end on the step grid (tau = step * dt)
  // Stop this long (in tau) after the first break, rounded up to the step grid.
  std::optional<double> after_break;
  bool at_first_break = false;  // stop at the end of the step in which the first break fell
  // Polled before every step, every temporal block of steps (IntegratorOptions::
  // block_steps) or every run of a small chain's steps (at most kSmallRunSteps): a signal
  // handler or a GUI sets it to cancel the run.
  const std::atomic<bool>* cancel = nullptr;
};

// The last step of a run that stops `after_break` past a first break at `break_tau`: the
// first grid step at or past that time (within 1e-9 of a step counts as on it).
std::int64_t after_break_step(double break_tau, double after_break, double dt);

// Something that watches the run: called with the integrator after every `every`-th step
// (the step count a multiple of `every`), and on the starting state if `at_start`.
struct Observer {
  std::int64_t every = 1;
  bool at_start = false;
  std::function<void(const Integrator&)> see;
  // A progress report: it may be called once after a temporal block of steps
  // (IntegratorOptions::block_steps) that passed a multiple of `every`, instead of at that
  // step, so it does not cut the run into single steps.
  bool coarse = false;
};

enum class RunEnd {
  Reached,    // a stop rule other than the cancel flag ended it
  Cancelled,  // *cancel was set
  Failed,     // the state stopped being finite: Integrator::error() says why
};

// Steps `sim` until a stop rule holds. A run already past last_step takes no step.
RunEnd run_until(Integrator& sim, const StopRule& stop,
                 const std::vector<Observer>& observers = {});

}  // namespace cb
