#include "figures/break_maps.h"

#include <algorithm>
#include <atomic>
#include <cassert>
#include <cmath>
#include <exception>
#include <mutex>
#include <stdexcept>
#include <thread>

#include "physics/integrator.h"
#include "physics/run_loop.h"
#include "physics/stop_flag.h"
#include "threads/parked_threads.h"

namespace cb {

FirstBreak simulated_first_break(const ChainParams& chain, const DriveDesc& drive, double t_end,
                                 double dt, const std::atomic<bool>* stop) {
  Integrator sim(chain, make_forcing(drive), {dt, 1});
  const StopRule rule{std::llround(t_end / dt), std::nullopt, true, stop};
  if (run_until(sim, rule) == RunEnd::Failed) throw std::runtime_error(sim.error());
  FirstBreak fb;
  if (!sim.state().breaks.empty()) {
    fb.broke = true;
    fb.spring = sim.state().breaks.front().spring;
    fb.tau = sim.state().breaks.front().tau;
  }
  return fb;
}

std::vector<FirstBreak> parallel_first_breaks(int count, int jobs,
                                              const std::function<FirstBreak(int)>& fn) {
  std::vector<FirstBreak> out(static_cast<std::size_t>(std::max(count, 0)));
  jobs = threads_for(jobs);
  std::atomic<int> next{0};
  std::exception_ptr failure;
  std::mutex failure_mutex;
  auto worker = [&] {
    for (int i; (i = next++) < count;) {
      try {
        out[static_cast<std::size_t>(i)] = fn(i);
      } catch (...) {
        std::lock_guard lock(failure_mutex);
        if (!failure) failure = std::current_exception();
        next = count;
      }
    }
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < std::min(jobs, count); ++t) pool.emplace_back(worker);
  worker();
  for (auto& t : pool) t.join();
  if (failure) std::rethrow_exception(failure);
  return out;
}

FirstBreak ramp_first_break(int beads, double gamma, double zeta_c) {
  ChainParams chain;
  chain.beads = beads;
  chain.gamma = gamma;
  chain.threshold = zeta_c;
  DriveDesc ramp;
  ramp.type = DriveType::Ramp;
  ramp.beta = 1.0;
  return exact_first_break(chain, ramp, 4.0 * zeta_c + 8.0 * beads);
}

std::vector<MapBoundary> spring_n_boundaries(int beads, double gamma, double zeta_lo,
                                             double zeta_hi, int samples, double tolerance,
                                             const std::atomic<bool>* stop) {
  assert(samples >= 2 && zeta_hi > zeta_lo);
  const auto is_n = [&](const FirstBreak& b) { return b.broke && b.spring == beads; };
  std::vector<MapBoundary> out;
  double prev_zeta = zeta_lo;
  FirstBreak prev = ramp_first_break(beads, gamma, zeta_lo);
  for (int i = 1; i < samples && !stop_requested(stop); ++i) {
    const double zeta = zeta_lo + (zeta_hi - zeta_lo) * i / (samples - 1);
    const FirstBreak here = ramp_first_break(beads, gamma, zeta);
    if (is_n(here) != is_n(prev)) {
      // Bisection keeps one end on each side of the switch.
      double lo = prev_zeta, hi = zeta;
      FirstBreak at_lo = prev, at_hi = here;
      while (hi - lo > tolerance && !stop_requested(stop)) {
        const double mid = 0.5 * (lo + hi);
        const FirstBreak m = ramp_first_break(beads, gamma, mid);
        (is_n(m) == is_n(at_lo) ? lo : hi) = mid;
        (is_n(m) == is_n(at_lo) ? at_lo : at_hi) = m;
      }
      out.push_back({0.5 * (lo + hi), at_lo.spring, at_hi.spring});
    }
    prev_zeta = zeta;
    prev = here;
  }
  return out;
}

ContinuumBreak continuum_ramp_break(int beads, double zeta_c) {
  const double n = beads;
  const double m = std::floor(zeta_c / (4.0 * n));  // zeta_c in [4m N, (4m + 4) N)
  if (zeta_c - 4.0 * m * n < 2.0 * n) return {true, 0.0};
  return {false, (2.0 * m + 2.0) * n - 0.5 * zeta_c};
}

}  // namespace cb
