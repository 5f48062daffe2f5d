#include "physics/threshold_ensemble.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <numeric>
#include <type_traits>

#include "physics/coefficients.h"
#include "physics/crossing.h"
#include "physics/integrator.h"

namespace cb {

namespace detail {
#include "physics/stencil.inc"
}  // namespace detail

bool ensemble_can_run(const ChainParams& member) {
  return !member.pull_string && member.breakable() && member.min_threshold() > 0.0;
}

bool ensemble_can_share(const ChainParams& a, const ChainParams& b) {
  return ensemble_can_run(a) && ensemble_can_run(b) && a.beads == b.beads && a.gamma == b.gamma &&
         a.break_on == b.break_on && a.mass == b.mass && a.stiffness == b.stiffness;
}

namespace {

class Ensemble {
 public:
  explicit Ensemble(const ThresholdEnsemble& e)
      : n_(e.chain.beads),
        members_(static_cast<int>(e.thresholds.size() / static_cast<std::size_t>(e.chain.beads))),
        stretch_(e.chain.break_on == BreakMode::Stretch),
        phi_(e.thresholds),
        ends_(static_cast<std::size_t>(members_)),
        settled_(static_cast<std::size_t>(members_), false),
        seen_(static_cast<std::size_t>(members_), 0),
        order_(static_cast<std::size_t>(n_)),
        next_(static_cast<std::size_t>(n_), 0) {
    assert(e.thresholds.size() == static_cast<std::size_t>(members_) * n_);
    // Per spring, the members by phi_c,j (ties by member, so the order is the same everywhere).
    std::vector<std::pair<double, int>> keyed(static_cast<std::size_t>(members_));
    for (int j = 0; j < n_; ++j) {
      for (int m = 0; m < members_; ++m) keyed[static_cast<std::size_t>(m)] = {phi(m, j + 1), m};
      std::sort(keyed.begin(), keyed.end());
      auto& o = order_[static_cast<std::size_t>(j)];
      o.resize(static_cast<std::size_t>(members_));
      for (int m = 0; m < members_; ++m)
        o[static_cast<std::size_t>(m)] = keyed[static_cast<std::size_t>(m)].second;
    }
    open_ = members_;
  }

  double phi(int member, int spring) const {
    return phi_[static_cast<std::size_t>(member) * n_ + static_cast<std::size_t>(spring - 1)];
  }
  // The loosest bounds of the ensemble: spring j's smallest phi_c,j.
  ChainParams loosest(const ChainParams& shared) const {
    ChainParams p = shared;
    p.thresholds.assign(static_cast<std::size_t>(n_), std::numeric_limits<double>::infinity());
    for (int j = 1; j <= n_; ++j)
      p.thresholds[static_cast<std::size_t>(j - 1)] =
          phi(order_[static_cast<std::size_t>(j - 1)][0], j);
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
      // A member trips spring j (stencil.inc's may_cross_between with (phi_c, -phi_c) or
      // (phi_c, -inf)) only if phi_c <= max(|p0|, |p1|) + s: each side's sum is at most this one
      // (rounding is monotone), so the walk below misses no member the bound would test.
      const double s = slack * (detail::sabs(c.m0) + detail::sabs(c.m1));
      const double reach = std::max(std::abs(c.p0), std::abs(c.p1)) + s;
      const auto j = static_cast<std::size_t>(c.spring - 1);
      const auto& o = order_[j];
      std::size_t& k0 = next_[j];
      while (k0 < o.size() && settled_[static_cast<std::size_t>(o[k0])]) ++k0;
      for (std::size_t k = k0; k < o.size() && phi(o[k], c.spring) <= reach; ++k) {
        const auto m = static_cast<std::size_t>(o[k]);
        if (settled_[m] || seen_[m] == visit_) continue;
        seen_[m] = visit_;
        touched_.push_back(o[k]);
      }
    }
    for (const int m : touched_) settle(m, candidates, slack, ta, tb, step);
  }

  // A member's own candidates (the kernel's bound with its bounds), then Integrator's search.
  void settle(int m, const std::vector<detail::Candidate>& candidates, double slack, double ta,
              double tb, std::int64_t step) {
    mine_.clear();
    for (const detail::Candidate& c : candidates) {
      const double upper = phi(m, c.spring), lower = lower_bound_of(upper, stretch_);
      if (detail::may_cross_between(c.p0, c.p1, c.m0, c.m1, slack, upper, lower))
        mine_.push_back(c);
    }
    double first = 0.0;
    const int spring = detail::earliest_crossing_within(
        mine_,
        [&](int j, double* upper, double* lower) {
          *upper = phi(m, j);
          *lower = lower_bound_of(*upper, stretch_);
        },
        ta, tb, &first);
    if (spring < 0) return;
    LaneEnd& end = ends_[static_cast<std::size_t>(m)];
    end.kind = LaneEnd::Kind::Broke;
    end.first = {spring, first, step};
    settled_[static_cast<std::size_t>(m)] = true;
    --open_;
  }

  int open() const { return open_; }
  void fail_open() {
    for (int m = 0; m < members_; ++m)
      if (!settled_[static_cast<std::size_t>(m)])
        ends_[static_cast<std::size_t>(m)].kind = LaneEnd::Kind::Failed;
  }
  std::vector<LaneEnd> take() { return std::move(ends_); }

 private:
  int n_, members_;
  bool stretch_;
  const std::vector<double>& phi_;
  std::vector<LaneEnd> ends_;  // Reached until settled
  std::vector<bool> settled_;
  std::vector<std::uint64_t> seen_;
  std::uint64_t visit_ = 0;
  std::vector<std::vector<int>> order_;  // per spring, members by phi_c,j
  std::vector<std::size_t> next_;        // per spring, the first member of order_ not settled
  std::vector<int> touched_;
  std::vector<detail::Candidate> mine_;
  int open_ = 0;
};

}  // namespace

std::vector<LaneEnd> ensemble_first_breaks(const ThresholdEnsemble& e,
                                           const std::atomic<bool>* stop) {
  assert(e.chain.beads >= 1 && !e.chain.pull_string);
  Ensemble ensemble(e);
  if (ensemble.open() == 0) return ensemble.take();
  // One worker and no temporal blocks: `run`'s kernels for a chain this size (the same bits on
  // any path, integrator.h), with every crossing handed to watch().
  IntegratorOptions options{e.dt, 1};
  options.block_steps = 0;
  Integrator sim(ensemble.loosest(e.chain), e.forcing, options);
  sim.watch_crossings([&](const std::vector<detail::Candidate>& candidates, double ta, double tb) {
    ensemble.watch(candidates, ta, tb, sim.state().step + 1);
  });
  while (ensemble.open() > 0 && sim.state().step < e.last_step) {
    if (stop && stop->load(std::memory_order_relaxed)) break;
    if (sim.step_up_to(e.last_step - sim.state().step) == 0) {
      ensemble.fail_open();
      break;
    }
  }
  return ensemble.take();
}

}  // namespace cb
