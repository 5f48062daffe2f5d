#include "physics/lanes.h"

#include <immintrin.h>  // stencil.inc's fmadd

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdint>
#include <limits>
#include <type_traits>
#include <vector>

#include "physics/coefficients.h"
#include "physics/crossing.h"
#include "physics/lane_far.h"
#include "physics/lanes_interval.h"
#include "physics/simd.h"
#include "physics/stop_flag.h"

namespace cb {

namespace detail {
// The crossing rule, as every kernel includes it (here on doubles only).
#include "physics/stencil.inc"
}  // namespace detail

namespace {

using detail::kLanes;

// One lane's clock and drive: Integrator::step's split points and kicks, kept per lane so lanes
// at different steps share one kernel call.
struct Lane {
  bool active = false;
  LaneJob job;
  ChainCoefficients coef;      // the job's constants, built once when the lane takes it
  double nearest_bound = 0.0;  // coef.nearest_bound()
  detail::FarMap far_map;      // proves a run far from the bounds (lane_far.h)
  bool checks = false;         // springs can break (the fused kernel's threshold test)
  bool pull = false;           // the pull string can break
  std::int64_t step = 0;       // steps done
  std::vector<double> cuts;    // the current step's interval ends (empty: between steps)
  std::size_t cut = 0;         // the interval being integrated
  double from = 0.0;           // its start
  bool plain = false;  // the step is one interval, with no kick and no breakpoint at its end
  bool breakpoints_sorted = false;
  std::size_t next_breakpoint = 0;  // the first breakpoint after the current step's start
  std::size_t next_kick = 0;
  DriveCache drive;  // the drive's last value, as Integrator::drive_at keeps it
  std::vector<detail::Candidate> candidates;  // first_crossing's (reused)
  double ta = 0.0, tb = 0.0;
  bool end_is_breakpoint = false;
  double p_max = 0.0, m_max = 0.0;  // max_j |phi_j|, |dphi_j/dtau| now (at rest: 0)
};

// The arrays of lanes_interval, (beads + 2) rows of kLanes doubles each.
struct LaneArrays {
  int rows;
  std::vector<double> x0, v0, xn, vn;
  // The PerBead policy's 1/m_j and K_j per lane (lanes_interval.h); ones for a uniform lane,
  // whose bits the PerBead stencil then reproduces.
  std::vector<double> inv_mass, stiffness;
  explicit LaneArrays(int beads) : rows(beads + 2) {
    for (auto* a : {&x0, &v0, &xn, &vn, &inv_mass, &stiffness})
      a->assign(static_cast<std::size_t>(rows) * kLanes, 0.0);
  }
  // A lane starts from rest, Integrator's initial state.
  void clear_lane(int k) {
    for (int r = 0; r < rows; ++r) x0[r * kLanes + k] = v0[r * kLanes + k] = 0.0;
  }
  // Lane k's coefficients: row j holds bead j's 1/m and spring j's K; row N + 1 K_{N+1} = 0.
  void set_coefficients(int k, const ChainCoefficients& c) {
    for (int r = 1; r < rows - 1; ++r) {
      inv_mass[r * kLanes + k] = c.per_bead ? c.inv_mass[r - 1] : 1.0;
      stiffness[r * kLanes + k] = c.per_bead ? c.stiffness[r - 1] : 1.0;
    }
  }
};

bool on_breakpoint(const Forcing& forcing, double t, double snap) {
  for (double b : forcing.breakpoints)
    if (std::abs(b - t) <= snap) return true;
  return false;
}

// Integrator::step's common step (Forcing::plain_step): no breakpoint near and no kick left
// before t1 - snap, so the step is the one interval [t0, t1], no kick is due at its start and
// its end is no breakpoint. What begin_step, apply_kicks and on_breakpoint would find, without
// their searches (they cost a lane as much as its share of the kernel at N = 30).
bool begin_plain_step(Lane& lane) {
  if (!lane.breakpoints_sorted) return false;
  const double dt = lane.job.dt;
  const double t0 = static_cast<double>(lane.step) * dt;
  const double t1 = static_cast<double>(lane.step + 1) * dt;
  const double snap = 1e-9 * dt;
  if (!lane.job.forcing.plain_step(lane.next_breakpoint, lane.next_kick, t0, t1, snap))
    return false;
  lane.cuts.assign(1, t1);
  lane.cut = 0;
  lane.from = t0;
  lane.plain = true;
  return true;
}

// How many of a lane's next steps (at most `limit`) are plain ones (begin_plain_step's) that
// end before its last step, without changing the lane: a run of them goes to the kernel in one
// go (run_first_breaks_in_lanes). None for a lane with a pull string, whose crossing the
// kernel's bound does not see (first_crossing tests it every step).
int plain_steps_ahead(const Lane& lane, int limit) {
  if (!lane.active || !lane.cuts.empty() || !lane.breakpoints_sorted || lane.pull) return 0;
  const std::int64_t left = lane.job.last_step - lane.step;
  limit = static_cast<int>(std::min<std::int64_t>(limit, left));
  const double dt = lane.job.dt;
  const double snap = 1e-9 * dt;
  const Forcing& forcing = lane.job.forcing;
  // Past the last breakpoint and kick (a ramp after tau = 0) every step is plain.
  if (forcing.plain_from(lane.next_breakpoint, lane.next_kick, static_cast<double>(lane.step) * dt,
                         snap))
    return limit;
  std::size_t next_breakpoint = lane.next_breakpoint;
  for (int s = 0; s < limit; ++s) {
    const double t0 = static_cast<double>(lane.step + s) * dt;
    const double t1 = static_cast<double>(lane.step + s + 1) * dt;
    if (!forcing.plain_step(next_breakpoint, lane.next_kick, t0, t1, snap)) return s;
  }
  return limit;
}

// Integrator::step's split of [t0, t1] at the drive's jumps, kinks and kicks strictly inside.
void begin_step(Lane& lane) {
  const double dt = lane.job.dt;
  const double t0 = static_cast<double>(lane.step) * dt;
  const double t1 = static_cast<double>(lane.step + 1) * dt;
  const double snap = 1e-9 * dt;
  lane.cuts.clear();
  for (double b : lane.job.forcing.breakpoints)
    if (b > t0 + snap && b < t1 - snap) lane.cuts.push_back(b);
  for (const Kick& k : lane.job.forcing.kicks)
    if (k.tau > t0 + snap && k.tau < t1 - snap) lane.cuts.push_back(k.tau);
  std::sort(lane.cuts.begin(), lane.cuts.end());
  lane.cuts.push_back(t1);
  lane.cut = 0;
  lane.from = t0;
  lane.plain = false;
}

// Integrator::apply_kicks: bead N's velocity jumps by each kick up to `up_to` (and the
// largest spring rate is no longer known).
void apply_kicks(Lane& lane, double up_to, double& v_end) {
  const auto& kicks = lane.job.forcing.kicks;
  while (lane.next_kick < kicks.size() && kicks[lane.next_kick].tau <= up_to) {
    // s / m_N (s / 1 == s: the uniform chain's bits), as Integrator::apply_kicks.
    v_end += kicks[lane.next_kick].strength / lane.coef.mass_of(lane.job.params.beads);
    lane.m_max = std::numeric_limits<double>::infinity();
    ++lane.next_kick;
  }
}

// Integrator::advance_interval's search for the earliest crossing in (ta, tb] of a lane whose
// interval was integrated: springs by their Hermite cubic (the fused kernel's bound first), then
// the pull string. Returns the spring (0: the string) and sets `first`, or -1.
int first_crossing(Lane& lane, const LaneArrays& a, int k, bool near, double f_end, double& first) {
  const ChainParams& p = lane.job.params;
  const int n = p.beads;
  const double ta = lane.ta, tb = lane.tb;
  first = tb + 1.0;
  int spring = -1;
  if (lane.checks && near) {
    // The fused kernel's candidates (the same bound, stencil.inc), then Integrator's search.
    const ChainCoefficients& c = lane.coef;
    const double slack = detail::hermite_slack(tb - ta);
    std::vector<detail::Candidate>& candidates = lane.candidates;
    candidates.clear();
    for (int r = 1; r <= n; ++r) {
      const int i = r * kLanes + k, m = i - kLanes;
      const double p0 = a.x0[i] - a.x0[m], p1 = a.xn[i] - a.xn[m];
      const double m0 = a.v0[i] - a.v0[m], m1 = a.vn[i] - a.vn[m];
      const bool trip =
          c.per_bead
              ? detail::may_cross_between(p0, p1, m0, m1, slack, c.upper[r - 1], c.lower[r - 1])
              : detail::may_cross(p0, p1, m0, m1, slack, c.threshold, c.stretch_only);
      if (trip) candidates.push_back({r, p0, p1, m0, m1});
    }
    spring = detail::earliest_crossing(candidates, c, ta, tb, &first);
  }
  if (lane.pull) {
    const Forcing& f = lane.job.forcing;
    const double t = detail::first_time_at_least(
        f.f ? f.f : [](double) { return 0.0; }, f_end, ta, tb, p.threshold);
    if (t >= 0.0 && t <= first) {
      first = t;
      spring = 0;
    }
  }
  return spring;
}

}  // namespace

bool run_first_breaks_in_lanes(int beads, const std::function<std::optional<LaneJob>()>& next,
                               const std::function<void(std::size_t, const LaneEnd&)>& done,
                               SimdPath simd, const std::atomic<bool>* cancel) {
  assert(beads >= 1 && beads <= kMaxLaneBeads);
  const detail::LanesKernel kernel = detail::lanes_kernel(simd);
  LaneArrays a(beads);
  Lane lanes[kLanes];
  constexpr double kInf = std::numeric_limits<double>::infinity();
  alignas(64) double g2[kLanes], h[kLanes], h2[kLanes], h6[kLanes], f0[kLanes], f1[kLanes],
      f2[kLanes], slack[kLanes], threshold[kLanes], p0[kLanes], m0[kLanes], p1[kLanes], m1[kLanes];
  alignas(64) int bad[kLanes], near[kLanes], far[kLanes];
  alignas(64) double p_far[kLanes], m_far[kLanes];

  // Gives lane k the next job, or leaves it idle (at rest, h = 0: it stays at +0).
  bool more = true;
  auto refill = [&](int k) {
    Lane& lane = lanes[k];
    lane.active = false;
    a.clear_lane(k);
    while (more) {
      std::optional<LaneJob> job = next();
      if (!job) {
        more = false;
        break;
      }
      assert(job->params.beads == beads);
      if (job->last_step <= 0) {  // run_until takes no step
        done(job->id, LaneEnd{});
        continue;
      }
      lane = Lane{};
      lane.active = true;
      lane.job = std::move(*job);
      const ChainParams& p = lane.job.params;
      lane.coef = chain_coefficients(p);
      a.set_coefficients(k, lane.coef);
      lane.checks = lane.coef.checks;
      lane.nearest_bound = lane.coef.nearest_bound();
      lane.far_map = detail::FarMap(lane.coef, p.gamma, lane.job.dt);
      lane.pull = p.pull_string && p.breakable();
      lane.breakpoints_sorted =
          std::is_sorted(lane.job.forcing.breakpoints.begin(), lane.job.forcing.breakpoints.end());
      return;
    }
  };
  for (int k = 0; k < kLanes; ++k) refill(k);

  detail::LaneInterval in;
  in.beads = beads;
  in.g2 = g2, in.h = h, in.h2 = h2, in.h6 = h6, in.f0 = f0, in.f1 = f1, in.f2 = f2;
  in.slack = slack, in.threshold = threshold, in.p_start = p0, in.m_start = m0;
  in.bad = bad, in.near = near, in.p_end = p1, in.m_end = m1;
  in.p_far = p_far, in.m_far = m_far;
  const int end_row = beads * kLanes;
  // Lane k's inputs that hold for its whole step: friction, its nearest bound (none: +inf), and
  // the largest |phi|, |dphi/dtau| at the start; an idle lane rests at +0 with no bound.
  auto set_lane_constants = [&](int k) {
    const Lane& lane = lanes[k];
    g2[k] = lane.active ? 2.0 * lane.job.params.gamma : 0.0;
    threshold[k] = lane.active && lane.checks ? lane.nearest_bound : kInf;
    p0[k] = lane.active ? lane.p_max : 0.0;
    m0[k] = lane.active ? lane.m_max : 0.0;
  };
  // The kernel's per-lane inputs that follow from h, in a loop of their own that the compiler
  // vectorises (the divisions were the driver's costliest instructions when each lane did its
  // own); and the kernel called on the lanes' current arrays.
  auto integrate = [&] {
    for (int k = 0; k < kLanes; ++k) {
      h2[k] = 0.5 * h[k];
      h6[k] = h[k] / 6.0;
      slack[k] = detail::hermite_slack(h[k]);
    }
    in.x0 = a.x0.data(), in.v0 = a.v0.data();
    in.xn = a.xn.data(), in.vn = a.vn.data();
    kernel(in);
  };
  // A run of plain steps for every lane (plain_steps_ahead), each one's times and drive values
  // found first, then the kernel called once a step, with no lane's bookkeeping in between: at
  // N = 30 that bookkeeping was a fifth of a sweep's time (tests/bench/README.md, session 15).
  // The run stops after a step in which a lane may cross or may not be finite. The lanes are
  // then left as the one-step path leaves them after the kernel: their last step begun, its
  // interval in ta, tb, f2 and the arrays (x0: its start, xn: its end), every earlier step
  // done. Each step's inputs are those the one-step path gives it, so the bits are the same.
  constexpr int kMaxRun = 16;
  static_assert(kMaxRun - 1 <= detail::kMaxFarSteps);
  alignas(64) double run_h[kMaxRun][kLanes], run_f0[kMaxRun][kLanes], run_f1[kMaxRun][kLanes],
      run_f2[kMaxRun][kLanes];
  auto integrate_run = [&](int run) {
    for (int k = 0; k < kLanes; ++k) {
      Lane& lane = lanes[k];
      set_lane_constants(k);
      if (!lane.active) {
        for (int s = 0; s < run; ++s)
          run_h[s][k] = run_f0[s][k] = run_f1[s][k] = run_f2[s][k] = 0.0;
        far[k] = 1, p_far[k] = m_far[k] = 0.0;  // at rest at +0, its bounds are 0 exactly
        continue;
      }
      // The run's step ends t[0 .. run] and middles, and f at all of them in one call.
      const double dt = lane.job.dt;
      double at[2 * kMaxRun + 1], f[2 * kMaxRun + 1];
      for (int s = 0; s <= run; ++s) at[s] = static_cast<double>(lane.step + s) * dt;
      for (int s = 0; s < run; ++s) at[run + 1 + s] = 0.5 * (at[s] + at[s + 1]);
      lane.job.forcing.values(at, f, static_cast<std::size_t>(2 * run + 1));
      double h_max = 0.0;
      for (int s = 0; s < run; ++s) {
        run_h[s][k] = at[s + 1] - at[s];
        run_f0[s][k] = f[s];
        run_f1[s][k] = f[run + 1 + s];
        run_f2[s][k] = f[s + 1];
        h_max = std::max(h_max, run_h[s][k]);
      }
      const double f_max = detail::largest_magnitude(f, 2 * run + 1);
      lane.drive.remember(at[run], f[run]);
      // Every step but the last far from the bounds (lane_far.h): the kernel may skip theirs.
      // The state before the last step bounds every earlier one.
      const detail::FarMap::Bounds bounds =
          lane.far_map.after(run - 1, lane.p_max, lane.m_max, f_max);
      const double h_bound = lane.far_map.step_bound();
      far[k] = h_max <= h_bound && detail::proven_far(bounds, h_bound, threshold[k]);
      p_far[k] = bounds.p, m_far[k] = bounds.m;
    }
    int done = 0;
    while (true) {
      in.far = done + 1 < run ? far : nullptr;  // the last step takes its bounds
      std::copy(std::begin(run_h[done]), std::end(run_h[done]), h);
      std::copy(std::begin(run_f0[done]), std::end(run_f0[done]), f0);
      std::copy(std::begin(run_f1[done]), std::end(run_f1[done]), f1);
      std::copy(std::begin(run_f2[done]), std::end(run_f2[done]), f2);
      integrate();
      ++done;
      bool stop = done == run;
      for (int k = 0; k < kLanes; ++k) stop |= (bad[k] | near[k]) != 0;
      if (stop) break;
      a.x0.swap(a.xn);
      a.v0.swap(a.vn);
      std::copy(std::begin(p1), std::end(p1), p0);
      std::copy(std::begin(m1), std::end(m1), m0);
    }
    // The steps before the last one done, then the last one begun (begin_plain_step's cursor
    // only moves forward with the clock, so one call finds where the steps between leave it).
    for (Lane& lane : lanes) {
      if (!lane.active) continue;
      lane.step += done - 1;
      const bool plain = begin_plain_step(lane);
      assert(plain);
      (void)plain;
      lane.ta = lane.from;
      lane.tb = lane.cuts[0];
      lane.end_is_breakpoint = false;
    }
    for (int k = 0; k < kLanes; ++k)
      if (lanes[k].active) lanes[k].p_max = p0[k], lanes[k].m_max = m0[k];
  };
  while (std::any_of(std::begin(lanes), std::end(lanes), [](const Lane& l) { return l.active; })) {
    if (stop_requested(cancel)) return false;
    // The PerBead stencil as soon as one lane needs it (uniform lanes hold ones: same bits).
    const bool per_bead = std::any_of(std::begin(lanes), std::end(lanes),
                                      [](const Lane& l) { return l.active && l.coef.per_bead; });
    in.inv_mass = per_bead ? a.inv_mass.data() : nullptr;
    in.stiffness = per_bead ? a.stiffness.data() : nullptr;
    in.far = nullptr;
    int run = kMaxRun;
    for (const Lane& lane : lanes)
      if (lane.active) run = std::min(run, plain_steps_ahead(lane, kMaxRun));
    if (run >= 2) {
      integrate_run(run);
    } else {
      // Each lane's next interval, as Integrator::step would take it.
      for (int k = 0; k < kLanes; ++k) {
        Lane& lane = lanes[k];
        if (!lane.active) {
          set_lane_constants(k);
          h[k] = f0[k] = f1[k] = f2[k] = 0.0;
          continue;
        }
        if (lane.cuts.empty() && !begin_plain_step(lane)) begin_step(lane);
        const double snap = 1e-9 * lane.job.dt;
        if (!lane.plain) apply_kicks(lane, lane.from + snap, a.v0[end_row + k]);
        lane.ta = lane.from;
        lane.tb = lane.cuts[lane.cut];
        lane.end_is_breakpoint = !lane.plain && on_breakpoint(lane.job.forcing, lane.tb, snap);
        const double ta = lane.ta, tb = lane.tb;
        h[k] = tb - ta;
        f0[k] = lane.drive(lane.job.forcing, ta);
        f1[k] = lane.drive(lane.job.forcing, 0.5 * (ta + tb));
        f2[k] = lane.drive(lane.job.forcing, lane.end_is_breakpoint ? std::nextafter(tb, ta) : tb);
        set_lane_constants(k);  // after the kicks, which make m_max unknown (+inf)
      }
      integrate();
    }

    // Every lane's new state becomes the current one; a lane that ended is cleared after.
    bool ended[kLanes] = {};
    for (int k = 0; k < kLanes; ++k) {
      Lane& lane = lanes[k];
      if (!lane.active) continue;
      if (bad[k] != 0) {
        done(lane.job.id, LaneEnd{LaneEnd::Kind::Failed, {}});
        ended[k] = true;
        continue;
      }
      double first = 0.0;
      const int spring = first_crossing(lane, a, k, near[k] != 0, f2[k], first);
      if (spring >= 0) {
        done(lane.job.id, LaneEnd{LaneEnd::Kind::Broke, {spring, first, lane.step + 1}});
        ended[k] = true;
        continue;
      }
      lane.p_max = p1[k];
      lane.m_max = m1[k];
      lane.from = lane.tb;
      if (++lane.cut < lane.cuts.size()) continue;
      lane.cuts.clear();
      if (++lane.step >= lane.job.last_step) {
        done(lane.job.id, LaneEnd{});
        ended[k] = true;
      }
    }
    a.x0.swap(a.xn);
    a.v0.swap(a.vn);
    for (int k = 0; k < kLanes; ++k)
      if (ended[k]) refill(k);
  }
  return true;
}

namespace detail {

LanesKernel lanes_kernel(SimdPath path) {
  return by_simd<LanesKernel>(path, sse2::lanes_interval, avx2::lanes_interval,
                              avx512::lanes_interval);
}

}  // namespace detail

}  // namespace cb
