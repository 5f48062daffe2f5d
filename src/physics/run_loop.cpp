#include "physics/run_loop.h"

#include <algorithm>
#include <cmath>

#include "physics/stop_flag.h"

namespace cb {

std::int64_t after_break_step(double break_tau, double after_break, double dt) {
  return static_cast<std::int64_t>(std::ceil((break_tau + after_break) / dt - 1e-9));
}

RunEnd run_until(Integrator& sim, const StopRule& stop, const std::vector<Observer>& observers) {
  // `from`: the step before the last advance (a coarse observer sees the run if a multiple
  // of its `every` lies in (from, step]).
  auto observe = [&](bool start, std::int64_t from) {
    const std::int64_t step = sim.steps_done();
    for (const Observer& o : observers) {
      if (start ? o.at_start && step % o.every == 0
                : (o.coarse ? step / o.every > from / o.every : step % o.every == 0))
        o.see(sim);
    }
  };
  std::int64_t last = stop.last_step;
  // A run resumed after its first break (the viewer, advance_to) applies the rule at once.
  bool break_seen = false;
  auto on_break = [&] {
    if (break_seen || sim.breaks().empty()) return false;
    break_seen = true;
    if (stop.after_break)
      last =
          std::min(last, after_break_step(sim.breaks().front().tau, *stop.after_break, sim.dt()));
    return stop.at_first_break;
  };
  if (on_break()) return RunEnd::Reached;
  observe(true, 0);
  while (sim.steps_done() < last) {
    if (stop_requested(stop.cancel)) return RunEnd::Cancelled;
    // The steps up to the next observation or stop are plain as far as this loop is
    // concerned: the integrator may take them as one temporal block or a run of a small
    // chain's steps (never across a break), and this loop's tests are paid once for all.
    const std::int64_t step = sim.steps_done();
    std::int64_t room = last - step;
    for (const Observer& o : observers)
      if (!o.coarse) room = std::min(room, o.every - step % o.every);
    if (sim.step_up_to(room) == 0) return RunEnd::Failed;
    observe(false, step);
    if (on_break()) return RunEnd::Reached;
  }
  return RunEnd::Reached;
}

}  // namespace cb
