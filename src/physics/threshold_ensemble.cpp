#include "physics/threshold_ensemble.h"

#include <immintrin.h>  // stencil.inc's fmadd

#include <algorithm>
#include <cassert>
#include <cmath>
#include <exception>
#include <limits>
#include <numeric>
#include <type_traits>

#include "physics/coefficients.h"
#include "physics/crossing.h"
#include "physics/integrator.h"
#include "physics/stop_flag.h"
#include "physics/worker_pool.h"

namespace cb {

namespace detail {
#include "physics/stencil.inc"
}  // namespace detail

// A hanging chain is integrated about its equilibrium with bounds shifted per spring
// (coefficients.h); the members' thresholds are not shifted here, so it runs on its own.
bool ensemble_can_run(const ChainParams& member) {
  return !member.pull_string && !member.hanging() && member.breakable() &&
         member.min_threshold() > 0.0;
}

bool ensemble_can_share(const ChainParams& a, const ChainParams& b) {
  return ensemble_can_run(a) && ensemble_can_run(b) && a.beads == b.beads && a.gamma == b.gamma &&
         a.break_on == b.break_on && a.mass == b.mass && a.stiffness == b.stiffness &&
         a.fput_alpha == b.fput_alpha && a.fput_beta == b.fput_beta;
}

namespace {

class Ensemble {
  // One spring's members bucketed by phi_c,j (a counting sort).
  struct Buckets {
    double lo = 0.0, scale = 0.0;
    std::size_t count = 0, first = 0;  // first: no bucket before it holds an open member
    // Bucket k: members[start[k] .. end[k]), end[k] <= start[k + 1]. A member found settled
    // there is taken out (the bucket's last moved into its place): the walks of a slow pull
    // passed each settled member again at every later step of the spring.
    std::vector<int> start, end;
    std::vector<int> members;
    void take_out(std::size_t k, int e) {
      members[static_cast<std::size_t>(e)] = members[static_cast<std::size_t>(--end[k])];
    }
    // Without branches (the counting sort calls it 10^4 times a spring): x is NaN only for
    // v = +inf with scale 0, whose bucket is the last one, as every +inf's.
    std::size_t of(double v) const {
      const double x = (v - lo) * scale, top = static_cast<double>(count - 1);
      const double clamped = x < top ? (x > 0.0 ? x : 0.0) : top;
      return static_cast<std::size_t>(static_cast<int>(clamped));
    }
  };

 public:
  // Members [first, first + count) of `e`, numbered from 0 here.
  Ensemble(const ThresholdEnsemble& e, std::size_t first, std::size_t count)
      : n_(e.chain.beads),
        members_(static_cast<int>(count)),
        stretch_(e.chain.break_on == BreakMode::Stretch),
        phi_(e.thresholds.data() + first * static_cast<std::size_t>(e.chain.beads)),
        ends_(static_cast<std::size_t>(members_)),
        settled_(static_cast<std::size_t>(members_), false),
        seen_(static_cast<std::size_t>(members_), 0),
        buckets_(static_cast<std::size_t>(n_)) {
    assert((first + count) * static_cast<std::size_t>(n_) <= e.thresholds.size());
    // One pass in the members' order: each spring's smallest phi_c,j (the run's first bound),
    // the first member holding it, and its largest finite one (the buckets' range). 30
    // independent minima; one spring at a time they were a chain of dependent ones.
    const auto n = static_cast<std::size_t>(n_);
    lo_.assign(n, std::numeric_limits<double>::infinity());
    hi_.assign(n, 0.0);
    holder_.assign(n, -1);
    // Separate arrays (restrict), so that the row's 30 springs are one vectorised loop.
    double* __restrict lo = lo_.data();
    double* __restrict hi = hi_.data();
    int* __restrict holder = holder_.data();
    for (int m = 0; m < members_; ++m) {
      const double* __restrict row = phi_ + static_cast<std::size_t>(m) * n;
      for (std::size_t j = 0; j < n; ++j) {
        const double v = row[j];
        const bool lower = v < lo[j];
        lo[j] = lower ? v : lo[j];
        holder[j] = lower ? m : holder[j];
        hi[j] = v < std::numeric_limits<double>::infinity() && v > hi[j] ? v : hi[j];
      }
    }
    bound_ = lo_;
    open_ = members_;
    listed_.resize(static_cast<std::size_t>(members_));
    std::iota(listed_.begin(), listed_.end(), 0);
  }

  double phi(int member, int spring) const {
    return phi_[static_cast<std::size_t>(member) * n_ + static_cast<std::size_t>(spring - 1)];
  }
  // The loosest bounds of the ensemble: spring j's smallest phi_c,j.
  ChainParams loosest(const ChainParams& shared) const {
    ChainParams p = shared;
    p.thresholds.assign(static_cast<std::size_t>(n_), std::numeric_limits<double>::infinity());
    for (int j = 1; j <= n_; ++j)
      p.thresholds[static_cast<std::size_t>(j - 1)] = bound_[static_cast<std::size_t>(j - 1)];
    p.threshold = *std::min_element(p.thresholds.begin(), p.thresholds.end());
    p.normalize();
    return p;
  }

  // One interval's candidates (Integrator::watch_crossings): the members that may break in it.
  void watch(const std::vector<detail::Candidate>& candidates, double ta, double tb,
             std::int64_t step) {
    const double slack = detail::hermite_slack(tb - ta);
    ++visit_;
    touched_.clear();
    for (const detail::Candidate& c : candidates) {
      // A bound whose member has settled rises here, where it is needed: raising every spring's
      // bound at each settle cost a fast pull (springs the wave never reaches) a fifth more.
      const int holder = holder_[static_cast<std::size_t>(c.spring - 1)];
      if (holder >= 0 && settled_[static_cast<std::size_t>(holder)]) raise_bound(c.spring);
      // A member trips spring j (stencil.inc's may_cross_between with (phi_c, -phi_c) or
      // (phi_c, -inf)) only if phi_c <= max(|p0|, |p1|) + s: each side's sum is at most this one
      // (rounding is monotone), so the walk below misses no member the bound would test.
      const double s = slack * (detail::sabs(c.m0) + detail::sabs(c.m1));
      const double reach = std::max(std::abs(c.p0), std::abs(c.p1)) + s;
      Buckets& b = buckets_of(c.spring);
      const std::size_t last = b.of(reach);
      for (std::size_t k = b.first; k <= last && k < b.count; ++k) {
        for (int e = b.start[k]; e < b.end[k];) {
          const int member = b.members[static_cast<std::size_t>(e)];
          const auto m = static_cast<std::size_t>(member);
          if (settled_[m]) {
            b.take_out(k, e);
            continue;
          }
          ++e;
          if (seen_[m] == visit_ || phi(member, c.spring) > reach) continue;
          seen_[m] = visit_;
          touched_.push_back(member);
        }
      }
    }
    for (const int m : touched_) settle(m, candidates, slack, ta, tb, step);
    if (roots_.size() >= kFinishAt) finish();
  }

  // The springs whose bound rose since the last call, each with its new bound (the smallest
  // phi_c,j of the members still open), handed to `widen(spring, upper)` once.
  template <class Widen>
  void take_widened(Widen&& widen) {
    for (const int j : widened_) widen(j, bound_[static_cast<std::size_t>(j - 1)]);
    widened_.clear();
  }

  // A member's own candidates (the kernel's bound with its bounds), then Integrator's search
  // (crossing.h's earliest_crossing_within) in two parts: whether the member crosses in this
  // interval is known at once, and it settles; its crossing times are bisected later with many
  // other members' (finish), a group of lanes at a time, which a slow pull, one member a step,
  // could not do otherwise. The same roots and the same earliest rule, so the same spring and tau.
  void settle(int m, const std::vector<detail::Candidate>& candidates, double slack, double ta,
              double tb, std::int64_t step) {
    Pending pending{m, ta, tb, step, roots_.size()};
    for (const detail::Candidate& c : candidates) {
      const double upper = phi(m, c.spring), lower = lower_bound_of(upper, stretch_);
      if (!detail::may_cross_between(c.p0, c.p1, c.m0, c.m1, slack, upper, lower)) continue;
      const detail::HermiteRoot root =
          detail::hermite_root(c.p0, c.p1, c.m0, c.m1, tb - ta, upper, lower);
      if (!root.crosses()) continue;
      roots_.push_back(root);
      root_springs_.push_back(c.spring);
    }
    if (roots_.size() == pending.first_root) return;
    pending_.push_back(pending);
    settled_[static_cast<std::size_t>(m)] = true;
    --open_;
  }

  // The settled members' crossing times: their roots bisected together, then each member's
  // earliest (ties to the lower spring).
  void finish() {
    detail::finish_hermite_roots(roots_.data(), roots_.size());
    for (std::size_t k = 0; k < pending_.size(); ++k) {
      const Pending& p = pending_[k];
      const std::size_t end = k + 1 < pending_.size() ? pending_[k + 1].first_root : roots_.size();
      double first = p.tb + 1.0;
      int spring = -1;
      for (std::size_t r = p.first_root; r < end; ++r)
        detail::keep_earliest(root_springs_[r], p.ta, roots_[r].theta, &spring, &first);
      LaneEnd& out = ends_[static_cast<std::size_t>(p.member)];
      out.kind = LaneEnd::Kind::Broke;
      out.first = {spring, first, p.step};
    }
    pending_.clear();
    roots_.clear();
    root_springs_.clear();
  }

  // Spring j's members in buckets by phi_c,j (a counting sort: one linear pass, where sorting
  // 30 x 10^4 keys cost 30 ms against a run's 0.4 ms), built when the run first needs them: a
  // jerk's members all break before its wave has brought more than a few springs near their
  // bounds (2 of 30 at beta = 1), and the buckets of the others were most of its cost. Bucket k
  // holds lo + [k, k+1) / scale; the index is monotone in phi_c,j, so every member with
  // phi_c,j <= reach lies in a bucket up to of(reach).
  Buckets& buckets_of(int j) {
    const auto i = static_cast<std::size_t>(j - 1);
    Buckets& b = buckets_[i];
    if (!b.start.empty()) return b;
    // Only the open members (a list with few settled ones: a branch on each member's settled
    // bit cost more than it saved): a slow pull builds its last springs' buckets when most have
    // settled (10^4 seeds at beta = 0.02: 1.9 x 10^5 of the 3 x 10^5 thresholds are open then).
    const auto open = static_cast<std::size_t>(open_);
    if (listed_.size() > open + open / 8 + 64)
      std::erase_if(listed_, [&](int m) { return settled_[static_cast<std::size_t>(m)]; });
    const auto n = static_cast<std::size_t>(n_);
    const std::size_t count = listed_.size(), buckets = std::max<std::size_t>(count, 1);
    b.lo = lo_[i];
    b.scale = hi_[i] > lo_[i] ? static_cast<double>(buckets) / (hi_[i] - lo_[i]) : 0.0;
    b.count = buckets;
    b.start.assign(buckets + 1, 0);
    slot_.resize(count);
    for (std::size_t k = 0; k < count; ++k) {
      if (k + 16 < count)
        __builtin_prefetch(phi_ + static_cast<std::size_t>(listed_[k + 16]) * n + i);
      const auto m = static_cast<std::size_t>(listed_[k]);
      slot_[k] = static_cast<int>(b.of(phi_[m * n + i]));
      ++b.start[static_cast<std::size_t>(slot_[k]) + 1];
    }
    for (std::size_t k = 0; k < buckets; ++k) b.start[k + 1] += b.start[k];
    b.members.resize(count);
    b.end.assign(b.start.begin(), b.start.end() - 1);  // each bucket filled from its start
    for (std::size_t k = 0; k < count; ++k)
      b.members[static_cast<std::size_t>(b.end[static_cast<std::size_t>(slot_[k])]++)] = listed_[k];
    return b;
  }

  // Spring j's bound in the run: the smallest phi_c,j of its open members (+inf when none is),
  // and the member that holds it. Once that member has settled, the run's bound may rise to the
  // next open member's: a slow pull's steps then stop holding candidates for members already
  // broken (10^4 seeds: from every step after tau ~ 200 to about one step in ten).
  void raise_bound(int j) {
    const auto i = static_cast<std::size_t>(j - 1);
    Buckets& b = buckets_of(j);
    double lowest = std::numeric_limits<double>::infinity();
    int holder = -1;
    for (; b.first < b.count; ++b.first) {
      for (int e = b.start[b.first]; e < b.end[b.first];) {
        const int member = b.members[static_cast<std::size_t>(e)];
        if (settled_[static_cast<std::size_t>(member)]) {
          b.take_out(b.first, e);
          continue;
        }
        ++e;
        if (!(phi(member, j) < lowest)) continue;
        lowest = phi(member, j);
        holder = member;
      }
      if (holder >= 0) break;  // bucket b.first holds it
    }
    holder_[i] = holder;
    if (lowest > bound_[i]) widened_.push_back(j);
    bound_[i] = lowest;
  }

  int open() const { return open_; }
  void fail_open() {
    for (int m = 0; m < members_; ++m)
      if (!settled_[static_cast<std::size_t>(m)])
        ends_[static_cast<std::size_t>(m)].kind = LaneEnd::Kind::Failed;
  }
  std::vector<LaneEnd> take() {
    finish();
    return std::move(ends_);
  }

 private:
  int n_, members_;
  bool stretch_;
  const double* phi_;          // member m's phi_c,j at m N + j - 1
  std::vector<LaneEnd> ends_;  // Reached until settled
  std::vector<bool> settled_;
  std::vector<std::uint64_t> seen_;
  std::uint64_t visit_ = 0;
  std::vector<Buckets> buckets_;  // built by buckets_of, empty until then
  std::vector<int> slot_;         // buckets_of's: each listed member's bucket of the spring at hand
  std::vector<int> listed_;       // the open members and a few settled since (buckets_of)
  std::vector<double> lo_, hi_;   // spring j's smallest and largest finite phi_c,j, at j - 1
  std::vector<double> bound_;     // spring j's bound in the run, at j - 1 (raise_bound) ...
  std::vector<int> holder_;       // ... and the member that holds it (-1: none is open)
  std::vector<int> widened_;      // springs whose bound rose since take_widened
  std::vector<int> touched_;
  // Members settled whose crossing times are not bisected yet (finish), and their roots: member
  // k's are roots_[first_root of k .. first_root of k + 1).
  struct Pending {
    int member;
    double ta, tb;
    std::int64_t step;
    std::size_t first_root;
  };
  static constexpr std::size_t kFinishAt = 256;
  std::vector<Pending> pending_;
  std::vector<detail::HermiteRoot> roots_;
  std::vector<int> root_springs_;
  int open_ = 0;
};

}  // namespace

namespace {

// Members [first, first + count) of `e`: their ends, from one run.
std::vector<LaneEnd> first_breaks_of_part(const ThresholdEnsemble& e, std::size_t first,
                                          std::size_t count, const std::atomic<bool>* stop) {
  Ensemble ensemble(e, first, count);
  if (ensemble.open() == 0) return ensemble.take();
  // One worker and no temporal blocks: `run`'s kernels for a chain this size (the same bits on
  // any path, integrator.h), with every crossing handed to watch().
  // The PerBead policy (the Uniform bits, integrator.h) even when the loosest bounds are all
  // equal, so that each spring's bound can rise on its own.
  IntegratorOptions options{e.dt, 1};
  options.block_steps = 0;
  options.per_bead_policy = true;
  Integrator sim(ensemble.loosest(e.chain), e.forcing, options);
  const bool stretch = e.chain.break_on == BreakMode::Stretch;
  sim.watch_crossings([&](const std::vector<detail::Candidate>& candidates, double ta, double tb) {
    ensemble.watch(candidates, ta, tb, sim.steps_done() + 1);
    ensemble.take_widened([&](int spring, double upper) {
      sim.widen_bounds(spring, upper, lower_bound_of(upper, stretch));
    });
  });
  while (ensemble.open() > 0 && sim.steps_done() < e.last_step) {
    if (stop_requested(stop)) break;
    if (sim.step_up_to(e.last_step - sim.steps_done()) == 0) {
      ensemble.fail_open();
      break;
    }
  }
  return ensemble.take();
}

}  // namespace

std::vector<LaneEnd> ensemble_first_breaks(const ThresholdEnsemble& e,
                                           const std::atomic<bool>* stop, int workers) {
  assert(e.chain.beads >= 1 && !e.chain.pull_string);
  const std::size_t members = e.thresholds.size() / static_cast<std::size_t>(e.chain.beads);
  const std::size_t parts = std::clamp<std::size_t>(
      std::min(static_cast<std::size_t>(std::max(workers, 1)), members / kEnsembleMembersPerWorker),
      1, std::max<std::size_t>(members, 1));
  if (parts == 1) return first_breaks_of_part(e, 0, members, stop);
  std::vector<std::vector<LaneEnd>> ends(parts);
  std::vector<std::exception_ptr> errors(parts);
  const auto part = [&](std::size_t k) {
    const std::size_t first = members * k / parts, last = members * (k + 1) / parts;
    try {
      ends[k] = first_breaks_of_part(e, first, last - first, stop);
    } catch (...) {
      errors[k] = std::current_exception();
    }
  };
  detail::WorkerPool(static_cast<int>(parts)).run([&](int k) {
    part(static_cast<std::size_t>(k));
  });
  for (const auto& error : errors)
    if (error) std::rethrow_exception(error);
  std::vector<LaneEnd> all;
  all.reserve(members);
  for (auto& v : ends) all.insert(all.end(), v.begin(), v.end());
  return all;
}

}  // namespace cb
