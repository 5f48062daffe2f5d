#include "overlay/overlay_history.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>

#include "exact/exact_chain.h"
#include "overlay/modes.h"
#include "physics/energy.h"
#include "snapshot/strain_scale.h"

namespace cb {

namespace {

// Keeps elements 0, 2, 4, ... (blocks of `block` values each): the decimation step.
template <class T>
void keep_even(std::vector<T>& v, std::size_t block = 1) {
  const std::size_t count = v.size() / block;
  std::size_t w = 0;
  for (std::size_t i = 0; i < count; i += 2, ++w)
    std::copy_n(v.begin() + static_cast<std::ptrdiff_t>(i * block), block,
                v.begin() + static_cast<std::ptrdiff_t>(w * block));
  v.resize(w * block);
}

double first_break_tau(const ChainState& state) {
  double t = std::numeric_limits<double>::infinity();
  for (const BreakEvent& b : state.breaks) t = std::min(t, b.tau);
  return t;
}

}  // namespace

int plotted_springs(int beads, int out[kPlottedSprings]) {
  const int wanted[kPlottedSprings] = {1, std::max(1, beads / 2), beads};
  int count = 0;
  for (int j : wanted)
    if (count == 0 || out[count - 1] != j) out[count++] = j;
  return count;
}

OverlayHistory::OverlayHistory(const ChainParams& params, const DriveDesc& drive,
                               const OverlaySetup& setup)
    : params_(params), setup_(setup), per_spring_(strain_per_spring(params)) {
  assert(setup.tau_per_frame > 0 && setup.strain_scale > 0);
  OverlayData& d = data_;
  d.title = setup.title;
  d.beads = params.beads;
  d.gamma = params.gamma;
  d.phi_c = params.breakable() ? params.min_threshold() : 0.0;  // the weakest spring's
  d.tau_end = std::max(setup.tau_end, setup.tau_per_frame);
  d.tau_per_frame = setup.tau_per_frame;
  d.spring_count = plotted_springs(params.beads, d.springs);

  // The phi axis: the run's extremes, with 0 and the threshold (and -phi_c when compression
  // breaks too and the run goes well below zero) in view, plus 6% headroom.
  double lo = std::min(setup.phi_min, 0.0), hi = std::max(setup.phi_max, 0.0);
  d.threshold_both_signs = params.breakable() && params.break_on == BreakMode::Abs;
  if (params.breakable()) {
    hi = std::max(hi, d.phi_c);
    if (d.threshold_both_signs && lo < -0.25 * d.phi_c) lo = std::min(lo, -d.phi_c);
  }
  if (!(hi - lo > 0)) hi = lo + 1.0;
  const double pad = 0.06 * (hi - lo);
  d.phi_lo = lo - pad;
  d.phi_hi = hi + pad;
  d.energy_hi = setup.energy_max > 0 ? 1.08 * setup.energy_max : 1.0;

  d.strain_scale = setup.strain_scale;
  d.spacetime_columns = std::min(params.beads, kMaxSpacetimeColumns);
  d.exact = setup.exact && params.beads <= kExactMaxBeads;
  if (d.exact) exact_ = std::make_unique<ExactChain>(params, drive);
  modes_ = ModeBasis(params, std::min(params.beads, kMaxModes));
}

OverlayHistory::~OverlayHistory() = default;

std::shared_ptr<const OverlayData> OverlayHistory::share() const {
  return std::make_shared<const OverlayData>(data_);
}

void OverlayHistory::record(std::int64_t frame, const ChainState& state, double force) {
  assert(frame == next_frame_ && "frames are recorded in order, from 0");
  assert(state.psi.size() == static_cast<std::size_t>(params_.beads));
  next_frame_ = frame + 1;
  OverlayData& d = data_;
  const int n = params_.beads;
  d.frame = frame;
  d.tau = state.tau;
  if (setup_.omega0 > 0) d.seconds = state.tau / setup_.omega0;
  d.force = force;
  const EnergyParts e = energy(state);
  d.energy = per_particle(e.total(), n);
  d.kinetic = per_particle(e.kinetic, n);
  d.potential = per_particle(e.potential, n);
  d.breaks.clear();
  for (const BreakEvent& b : state.breaks)
    if (b.tau <= state.tau) d.breaks.push_back({b.spring, b.tau});
  std::stable_sort(d.breaks.begin(), d.breaks.end(),
                   [](const OverlayBreak& a, const OverlayBreak& b) { return a.tau < b.tau; });

  // Fig. 4(a), 4(b): the simulated points, one per kept frame.
  if (frame % d.history_stride == 0) {
    d.history_tau.push_back(state.tau);
    for (int s = 0; s < d.spring_count; ++s) d.phi[s].push_back(extension(state, d.springs[s]));
    d.energy_total.push_back(d.energy);
    d.energy_kinetic.push_back(d.kinetic);
    d.energy_potential.push_back(d.potential);
    if (static_cast<int>(d.history_tau.size()) > kMaxHistory) {
      keep_even(d.history_tau);
      for (auto& v : d.phi) keep_even(v);
      keep_even(d.energy_total);
      keep_even(d.energy_kinetic);
      keep_even(d.energy_potential);
      d.history_stride *= 2;
    }
  }

  if (exact_ && !exact_done_) record_exact(frame, state.tau, state);

  if (frame % d.spacetime_stride == 0) {
    record_spacetime(state);
    if (d.spacetime_rows() > kMaxSpacetimeRows) {
      keep_even(d.spacetime_tau);
      keep_even(d.spacetime, static_cast<std::size_t>(d.spacetime_columns));
      d.spacetime_stride *= 2;
    }
  }

  modes_.amplitudes(state, d.mode_amplitude);
  d.mode_peak.resize(d.mode_amplitude.size(), 0.0);
  for (std::size_t m = 0; m < d.mode_amplitude.size(); ++m) {
    d.mode_peak[m] = std::max(d.mode_peak[m], d.mode_amplitude[m]);
    d.mode_scale = std::max(d.mode_scale, d.mode_amplitude[m]);
  }
  last_tau_ = state.tau;
}

// The exact lines: at the frame time and kExactPerFrame - 1 evenly spaced times since the
// previous frame (sample index g = frame * kExactPerFrame - i), kept when g is a multiple of
// the stride; up to the first break, where a last sample ends the lines.
void OverlayHistory::record_exact(std::int64_t frame, double tau, const ChainState& state) {
  OverlayData& d = data_;
  const double t_break = first_break_tau(state);
  const int first = frame == 0 ? kExactPerFrame : 1;
  for (int i = first; i <= kExactPerFrame; ++i) {
    const double t = i == kExactPerFrame ? tau : last_tau_ + (tau - last_tau_) * i / kExactPerFrame;
    if (t >= t_break) break;
    const std::int64_t g = frame * kExactPerFrame - (kExactPerFrame - i);
    if (g % exact_stride_ != 0) continue;
    append_exact(t);
    if (static_cast<int>(d.exact_tau.size()) > kMaxHistory * kExactPerFrame) {
      keep_even(d.exact_tau);
      for (auto& v : d.exact_phi) keep_even(v);
      exact_stride_ *= 2;
    }
  }
  if (t_break <= tau) {
    append_exact(t_break);  // past the cap by one at most: the line must end at the break
    d.exact_end = t_break;
    exact_done_ = true;
  }
}

void OverlayHistory::append_exact(double tau) {
  exact_->modal(tau, x_, xdot_);
  data_.exact_tau.push_back(tau);
  for (int s = 0; s < data_.spring_count; ++s) {
    // phi_j = sum_n w_jn x_n (exact_chain.h): one O(N) dot product per spring.
    const double* w = exact_->phi_weights(data_.springs[s]);
    double phi = 0.0;
    for (std::size_t m = 0; m < x_.size(); ++m) phi += w[m] * x_[m];
    data_.exact_phi[s].push_back(phi);
  }
}

// One row: per column the intact spring of its block with the largest |phi|, over the
// colour scale; NaN where every spring of the block is broken.
void OverlayHistory::record_spacetime(const ChainState& state) {
  OverlayData& d = data_;
  const int n = params_.beads, columns = d.spacetime_columns;
  const std::vector<int>& broken = state.broken;
  std::size_t next = 0;
  d.spacetime_tau.push_back(state.tau);
  for (int c = 0; c < columns; ++c) {
    const int j0 = static_cast<int>(static_cast<std::int64_t>(c) * n / columns) + 1;
    const int j1 = static_cast<int>(static_cast<std::int64_t>(c + 1) * n / columns);
    double best = std::numeric_limits<double>::quiet_NaN();
    for (int j = j0; j <= j1; ++j) {
      while (next < broken.size() && broken[next] < j) ++next;
      if (next < broken.size() && broken[next] == j) continue;
      // Springs with thresholds of their own: the largest phi_j / phi_c,j wins, as in the
      // chain panel (snapshot/strain_scale.h).
      const double phi = per_spring_
                             ? extension(state, j) / spring_strain_scale(params_, j, d.strain_scale)
                             : extension(state, j);
      if (std::isnan(best) || std::abs(phi) > std::abs(best)) best = phi;
    }
    d.spacetime.push_back(static_cast<float>(per_spring_ ? best : best / d.strain_scale));
  }
}

}  // namespace cb
